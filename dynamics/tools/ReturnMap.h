// ReturnMap.h -- the map of a problem as a function of its map coordinates, x -> Map^n(x), with its
// derivative: what fixed points, continuation, separatrices and the |Map(x) - x| surface are built on
// (manual §2.3.4-§2.3.9). For a flow a point is completed into a state (model.stateFromMap), integrated to
// its n-th return to the section, and read back in map coordinates; for an explicit map it is iterated.
//
// Derivatives come either from finite differences with the manual's controls (central differences whose
// step halves until the linear approximation agrees with the map, down to the value of "zero"), or from the
// variational equations along the orbit with the correction for the section (the return time depends on
// the point): DP = Dc (I - f dsigma^T / (dsigma . f)) Phi DC, where Phi is the tangent flow, f the vector
// field at the return, sigma the section function, C the completion and c the coordinates (Guckenheimer &
// Holmes, Nonlinear Oscillations (1983) §1.5; Parker & Chua, Practical Numerical Algorithms for Chaotic
// Systems (1989) ch. 5).
#pragma once
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/PoincareMap.h"

#include <Eigen/Core>
#include <atomic>

namespace rv {

/// How derivatives of the map are computed.
enum class DerivativeMethod { FiniteDifferences, Variational };

/// The manual's controls of numerical differentiation (§2.3.4).
struct DerivativeSettings {
  DerivativeMethod method = DerivativeMethod::Variational; ///< exact up to the integration error
  double linearRegion =
      1e-4;               ///< initial step of the differences (size of the region where the map is linear)
  double accuracy = 1e-6; ///< allowed |Map(x + dx) - Lin(x + dx)| for |dx| = the step
  double zero = 1e-12;    ///< the step may not shrink below this
};

/// The map and its derivative at a point.
struct Linearization {
  Eigen::VectorXd image;    ///< Map^n(x)
  Eigen::MatrixXd jacobian; ///< D Map^n(x), dimension x dimension
  double step = 0;          ///< the finite-difference step used (0: variational)
};

/// Thrown when a tool is asked to stop in the middle of a map evaluation.
struct Stopped {};

class ReturnMap {
public:
  /// `section.order` is n; `section.root` the sheet of many-sheeted maps; `maxReturnTime` bounds the time a
  /// flow may take to return. `makeIntegrator` gives fresh (unstarted) integrators.
  ReturnMap(const Model& model, IntegratorFactory makeIntegrator, SectionSettings section,
            double maxReturnTime = 1e4);

  const Model& model() const { return model_; }
  int dimension() const { return static_cast<int>(names_.size()); }
  int order() const { return s_.order; }
  const std::vector<std::string>& coordinateNames() const { return names_; }
  /// Whether coordinate i is an angle (differences are taken mod 2 pi).
  bool periodic(int i) const { return periodic_[i]; }

  /// Map^n(x). Throws ComputationError when x has no state (outside the region of allowed motion) or does
  /// not return; Stopped when the control asks to stop.
  Eigen::VectorXd operator()(const Eigen::VectorXd& x, const ToolControl& control = {}) const;
  /// Map^n(x) and its derivative by the chosen method.
  Linearization linearize(const Eigen::VectorXd& x, const DerivativeSettings& settings,
                          const ToolControl& control = {}) const;
  /// a - b with angular components reduced to (-pi, pi].
  Eigen::VectorXd difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  /// x with angular components reduced to [0, 2 pi) (or to the model's own range for maps).
  Eigen::VectorXd canonical(const Eigen::VectorXd& x) const;
  /// x with each angular component moved by a multiple of 2 pi to lie nearest to `reference`'s.
  Eigen::VectorXd alignTo(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) const;
  /// Whether x has a state (lies in the region of allowed motion).
  bool allowed(const Eigen::VectorXd& x) const;
  /// The full state a point is completed into (the point itself for explicit maps); ComputationError if none.
  Eigen::VectorXd stateOf(const Eigen::VectorXd& x) const;
  /// The same map run backward (the inverse: backward integration for flows, Newton for explicit maps).
  ReturnMap inverse() const;
  /// Number of map evaluations (Map^n counted once) so far, over all threads.
  long evaluations() const { return evaluations_.load(); }

  ReturnMap(const ReturnMap& other);

private:
  struct Return {
    Eigen::VectorXd coordinates; ///< of the n-th return
    Eigen::VectorXd state;       ///< the whole state of `system` there
  };
  /// The n-th return of `system` (the model or its tangent system) from `start`, the state of map point x.
  Return firstReturn(const Model& system, const Eigen::VectorXd& start, const Eigen::VectorXd& x,
                     const ToolControl& control) const;
  Linearization finiteDifferences(const Eigen::VectorXd& x, const DerivativeSettings& s,
                                  const ToolControl& control) const;
  Linearization variational(const Eigen::VectorXd& x, const ToolControl& control) const;
  Eigen::VectorXd iterateMap(const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) const;
  Eigen::VectorXd invertMapOnce(const Eigen::VectorXd& y) const;
  /// Central-difference gradient of an observable over the core state.
  Eigen::RowVectorXd observableGradient(const Observable& o, const Eigen::VectorXd& x) const;

  const Model& model_;
  IntegratorFactory make_;
  SectionSettings s_;
  double maxReturnTime_;
  std::vector<std::string> names_;
  std::vector<const Observable*> coords_;
  const Observable* section_ = nullptr;
  std::vector<bool> periodic_;
  bool backward_ = false;
  mutable std::atomic<long> evaluations_{0};
};

} // namespace rv
