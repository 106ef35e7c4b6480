// Integrator.h -- one interface for every integration method, registered by name (as REBOUND does),
// each with dense output on its last step so that sections and video frames land on exact times.
#pragma once
#include "dynamics/core/Model.h"
#include "dynamics/core/ParameterTable.h"
#include "dynamics/core/Snapshot.h"

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rv {

/// A stepping method for dx/dt = f(x). Steps allocate nothing (work vectors are sized in start()).
class Integrator {
public:
  virtual ~Integrator() = default;
  /// Begins at (t0, x0); direction +1 integrates forward in time, -1 backward.
  virtual void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1);
  /// Advances one step. Throws ComputationError when the state stops being finite.
  virtual void step() = 0;
  /// State at t in the last step [previousTime(), time()] (either order), from the dense output.
  virtual void interpolate(double t, Eigen::VectorXd& out) const = 0;
  /// interpolate(), checked: throws ComputationError when the state at t is not finite (a dense output's
  /// slopes can overflow where the step's end did not). What every sample written anywhere goes through.
  void sampleAt(double t, Eigen::VectorXd& out) const {
    interpolate(t, out);
    requireFinite(out, t, "the solution");
  }
  /// Saves everything the next steps and the dense output depend on. restore() into an integrator of the same
  /// method and settings, start()ed on the same model, makes its following steps bit-identical (resumable
  /// runs).
  virtual void save(Snapshot& s) const;
  /// Reads what save() wrote; throws InputError when the snapshot does not fit this integrator.
  virtual void restore(Snapshot& s);

  /// Steps until time() reaches or passes t in the direction of integration, then writes the state at t into
  /// `out` (the step's end where it lands on t, else the dense output). False, writing nothing, when
  /// `stopRequested()` is true before a step. An adaptive method whose lanes step alone (stepLanesAlone)
  /// steps each lane with steps of its own until that lane reaches or passes t, each lane as it would alone.
  /// Throws ComputationError rather than hand on a state that is not finite (a method of a module that
  /// checks nothing itself included).
  template <class Stop> bool advanceTo(double t, Eigen::VectorXd& out, Stop&& stopRequested) {
    if (laneSteps_ > 0) return advanceLanesTo(t, out, [&] { return stopRequested(); });
    while (direction_ * (t_ - t) < 0) {
      if (stopRequested()) return false;
      step();
    }
    if (t_ == t) {
      out = x_;
      requireFinite(out, t, "the solution");
    } else {
      sampleAt(t, out);
    }
    return true;
  }
  void advanceTo(double t, Eigen::VectorXd& out) {
    advanceTo(t, out, [] { return false; });
  }

  /// Whether the step never changes (what the Fourier spectrum needs).
  virtual bool fixedStep() const { return false; }
  /// Steps are controlled (error estimates, a corrector's convergence) by the first `components` of the state
  /// only; 0, the default, by all. The integrator of a tangent system set to its orbit's dimension follows
  /// the orbit alone: the orbit does not depend on how many tangent vectors ride along.
  void controlBy(int components) { controlled_ = components; }
  /// Error control relative to blocks: the first `head` components one block, then blocks of `block` each;
  /// a component's error is measured against its block's largest magnitude rather than its own -- a tangent
  /// system's orbit (at least 1: absolute below) and each of its vectors (purely relative: a vector's length
  /// is arbitrary), so that a component of an orbit grown to 1e16 whose own value is near 0 is not held to
  /// the rounding of the others. 0: each component against max(1, its own magnitude), the default. Adaptive
  /// methods with a relative control honour it.
  void scaleErrorsByBlocks(int head, int block) { blockHead_ = head, blockSize_ = block; }
  /// Takes the state as `width` orbits stacked component-major (component c of orbit l at c * width + l: SIMD
  /// lanes, dynamics/core/Lanes.h) and steps each orbit as alone, bit for bit -- a point's result then cannot
  /// depend on the points beside it. Call before start(); controlBy then counts the components of all lanes
  /// (c * width for c per orbit). False, changing nothing, where the method cannot: its steps would read the
  /// whole state (an error control, a step chosen from it). Rk4 steps orbits independently; Everhart at a
  /// fixed step iterates each lane's corrector to that lane's convergence; an adaptive method that says yes
  /// (merson) gives each lane its own step and time (takeLaneSteps): it is then advanced with advanceTo only.
  virtual bool stepLanesAlone(int width) {
    (void)width;
    return false;
  }

  /// Whether its lanes take steps of their own (an adaptive method after stepLanesAlone): time() is then
  /// where the slowest lane stands, and only advanceTo advances it.
  bool lanesStepOnTheirOwn() const { return laneSteps_ > 0; }
  double time() const { return t_; }
  double previousTime() const { return tPrev_; }
  const Eigen::VectorXd& state() const { return x_; }
  const Model& model() const { return *model_; }
  int direction() const { return direction_; }
  /// Number of right-hand-side evaluations since start().
  long evaluations() const { return evaluations_; }
  /// Throws ComputationError "<what> stopped being finite at t = ..." if x holds a NaN or an infinity (or
  /// sums past the largest double: a blow-up too). What every integration, fused paths included, checks.
  static void requireFinite(const Eigen::VectorXd& x, double t, const char* what);

protected:
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& dx) {
    model_->rhs(x.data(), dx.data());
    ++evaluations_;
  }
  /// Throws ComputationError if x_ holds a NaN or an infinity.
  void checkFinite() const;
  /// Why the step could not be made, when the field itself stops being finite at the current state or at a
  /// stage within the step: "; " and the expression that went non-finite (a model written as equations), or
  /// "" (then the cause is the tolerance or a true singularity). Appended to an adaptive method's "the step
  /// fell" message.
  std::string nonFiniteField() const;
  /// Throws InputError for a map (for the methods that only integrate flows).
  static void requireFlow(const Model& model);
  /// Ends a step of signed length h: x_ += increment with compensated (Kahan) summation, `compensation`
  /// carrying what each addition lost into the next step (the rounding of long runs then grows like
  /// sqrt(steps)); the step's start kept in xPrev_/tPrev_, then checkFinite().
  void advanceCompensated(double h, const Eigen::VectorXd& increment, Eigen::VectorXd& compensation);
  /// Cubic Hermite interpolation on the last step from the states and derivatives at both ends.
  void hermite(double t, const Eigen::VectorXd& fPrev, const Eigen::VectorXd& f, Eigen::VectorXd& out) const;
  /// For stepLanesAlone of an adaptive method: each of the `width` lanes takes steps of its own length from
  /// start() on, with its own time (laneTime_, lanePrevious_). advanceTo then runs rounds of stepLanes until
  /// every lane reaches or passes its target, and writes each lane's state there (interpolateLane).
  void takeLaneSteps(int width) { laneSteps_ = width; }
  /// One round of lane steps: each lane whose `behind` is set attempts one step of its own length (accepted
  /// or not, as its error says); the others stand still. Throws as step() does.
  virtual void stepLanes(const std::vector<char>& behind);
  /// Lane `lane`'s state at t, in its last step, into its components of `out` (component c at c * width +
  /// lane).
  virtual void interpolateLane(int lane, double t, Eigen::VectorXd& out) const;
  /// hermite() for one lane, each component computed as hermite() computes it.
  void hermiteLane(int lane, double t, const Eigen::VectorXd& fPrev, const Eigen::VectorXd& f,
                   Eigen::VectorXd& out) const;
  /// A step's error: the largest |err_i| / scale_i over the first `rows` components of a lane (stride
  /// `width`), scale_i = max(1, |x_i|, |x_i + increment_i|) -- or, with scaleErrorsByBlocks, the largest of
  /// those over i's block: absolute below 1, relative above (Hairer, Norsett, Wanner, Solving ODE I, eq.
  /// II.4.10 with atol = rtol). NaN where an error is NaN.
  double relativeError(const double* err, const double* x, const double* increment, int lane, int width,
                       Eigen::Index rows) const;
  /// How many leading components of a state of `dimension` control the steps (controlBy).
  Eigen::Index controlled(Eigen::Index dimension) const {
    return controlled_ > 0 && controlled_ < dimension ? controlled_ : dimension;
  }

  const Model* model_ = nullptr;
  double t_ = 0, tPrev_ = 0;
  int direction_ = +1;
  long evaluations_ = 0;
  int controlled_ = 0;
  int blockHead_ = 0, blockSize_ = 0; ///< scaleErrorsByBlocks
  Eigen::VectorXd x_, xPrev_;
  int laneSteps_ = 0; ///< lanes stepped with steps of their own (takeLaneSteps); 0: one step for the state
  std::vector<double> laneTime_, lanePrevious_; ///< each lane's time and its last step's start

private:
  bool advanceLanesTo(double t, Eigen::VectorXd& out, const std::function<bool()>& stopRequested);
};

/// Makes a fresh integrator of a run's method and settings: what tools that restart integrations take
/// (RunSpec::makeIntegrator, dynamics/jobs/RunSpec.h).
using IntegratorFactory = std::function<std::unique_ptr<Integrator>()>;

/// A registered method: its parameter table and a factory.
struct IntegratorEntry {
  std::string id;        ///< "rk4", "merson", "everhart"
  std::string title;     ///< one line, for lists
  std::string reference; ///< the paper or book behind it
  const ParameterTable* parameters;
  /// Builds the integrator; throws InputError naming the parameter when values are inconsistent.
  std::function<std::unique_ptr<Integrator>(const ParameterValues&)> create;
  /// Where it comes from: "" for rollviz's own, else the module file that registered it.
  std::string origin = {};
};

/// All integration methods by name.
class IntegratorRegistry {
public:
  /// Every method: the built-in ones and those the loaded modules added (scenes/ModuleLoader.h).
  static const IntegratorRegistry& global();
  /// The same registry, for the module loader to add to (before any other use).
  static IntegratorRegistry& mutableGlobal();
  /// Adds an entry; throws InputError naming both origins when the id is taken.
  void add(IntegratorEntry entry);
  /// The entry with this id, or nullptr.
  const IntegratorEntry* find(const std::string& id) const;
  /// The entry with this id; throws InputError listing the known ids when there is none.
  const IntegratorEntry& get(const std::string& id) const;
  const std::vector<IntegratorEntry>& entries() const { return entries_; }

private:
  std::vector<IntegratorEntry> entries_;
};

} // namespace rv
