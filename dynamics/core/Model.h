// Model.h -- one rolling problem or reference system: a constant description (ModelInfo, parameters)
// and the equations; the mutable state is a plain vector owned by whoever integrates it (MuJoCo's
// mjModel/mjData split).
#pragma once
#include "dynamics/core/Diagram.h"
#include "dynamics/core/ParameterTable.h"

#include <Eigen/Core>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rv {
namespace taylor {
class Tape;
}

/// A named quantity computed from (t, state): energy, Andoyer-Deprit variables, Euler angles, ...
struct Observable {
  std::string id;
  std::string description;
  std::function<double(double t, const double* x)> value;
  bool angle = false; ///< an angle, defined mod 2 pi (sections on it are crossed where sin(value - v0) = 0)
};

/// Where the body is, for drawing: rotation (body -> world), its centre and the contact point.
struct BodyPose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();
  Eigen::Vector3d supportNormal = Eigen::Vector3d::UnitZ(); ///< of the fixed surface at the contact, outward
};

/// The fixed surface a body rolls on, when it is not the plane z = 0: points p(u, v) for u, v in [0, 1]
/// (u periodic when `closedU`), for drawing.
struct SupportSurface {
  std::function<Eigen::Vector3d(double u, double v)> point;
  bool closedU = true;
};

/// Which body and surface the render layer should build for a model.
enum class BodyShape { None, Ball, Ellipsoid, Paraboloid };

/// A flow (dx/dt = f(x), integrated) or an explicit point map (x -> P(x), iterated).
enum class ModelKind { Flow, Map };

/// The shape of a body in its own frame, relative to the pose's centre (for drawing).
struct BodyGeometry {
  BodyShape shape = BodyShape::None;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< ball or ellipsoid centre; paraboloid vertex
  Eigen::Vector3d semiAxes = Eigen::Vector3d::Ones(); ///< ellipsoid semi-axes (ball: the radius thrice)
  double p = 1, q = 1;                                ///< paraboloid: radii of curvature at the vertex
  double height = 1;                                  ///< paraboloid: how far above its vertex it is drawn
};

/// The constant description of a model kind.
struct ModelInfo {
  std::string id;                          ///< e.g. "chaplygin_ball" (design.md contract)
  std::string title;                       ///< one line, for lists
  std::string reference;                   ///< where the equations come from
  ParameterTable parameters;               ///< declared once, used by GUI, CLI and scenes
  std::vector<std::string> stateNames;     ///< names of the state components, in order
  int coreDimension = 0;                   ///< the leading components that evolve on their own
  std::vector<std::string> integralNames;  ///< first integrals, in the order integrals() returns them
  bool hasMeasure = false;                 ///< measureDensity() is an invariant measure density
  std::vector<std::string> mapCoordinates; ///< coordinates of a map point given as "initial": {"map": ...}
  std::string section;                     ///< observable whose level set is the default Poincare section
  ModelKind kind = ModelKind::Flow;
};

/// Where a map point lies: the section value and which root (sheet) to complete it on.
struct MapPointSpec {
  double sectionValue = 0.0;
  int root = 1; ///< 1-based index of the root, counted from the smallest
};

/// A model instance: the equations at fixed parameter values. Immutable after construction.
class Model {
public:
  Model(const ModelInfo& info, const ParameterValues& params);
  virtual ~Model() = default;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const ModelInfo& info() const { return *info_; }
  const ParameterValues& parameters() const { return params_; }
  int dimension() const { return static_cast<int>(info_->stateNames.size()); }

  bool isMap() const { return info_->kind == ModelKind::Map; }
  /// Flows: dx/dt = f(x) (all models here are autonomous). Maps: out = P(x).
  virtual void rhs(const double* x, double* dx) const = 0;
  /// Exact Jacobian (df/dx of a flow, dP/dx of a map), row-major dimension() x dimension().
  virtual void jacobian(const double* x, double* jac) const = 0;
  /// The core block of the Jacobian (coreDimension squared, row-major): what tangent vectors need.
  virtual void coreJacobian(const double* x, double* jac) const;
  /// The right-hand side and its derivative along k tangent vectors in core coordinates (V: k columns of
  /// coreDimension, column after column): dx = f(x), dV = J_core(x) V. What the variational equations need;
  /// models with a templated field compute both in one pass of directional derivatives.
  virtual void tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const;
  /// The fused path of fixed-step tangent runs (Lyapunov spectra with rk4): advances x and the k tangent
  /// vectors V (laid out as in tangentRhs) by `steps` classical RK4 steps of h in one compiled loop, with no
  /// virtual call per stage -- the same steps as the rk4 integrator on the variational equations
  /// (TangentSystem). Returns false, changing nothing, where a model has no such path; steps = 0 only asks.
  virtual bool tangentRk4(double* x, double* V, int k, double h, long steps) const;
  /// A system of orbits stacked on lanes (dynamics/tools/LaneStack.h) gives lane `lane`'s orbit as a system
  /// of its own, whose field is the stacked one's in that lane bit for bit: what a method whose setup reads
  /// the whole state (Adams's starter) runs orbit by orbit. Null where there is none (dynamics/core/OneLane.h
  /// then views the stacked field one lane at a time, at the cost of the whole stack per evaluation).
  virtual const Model* laneSystem(int /*lane*/) const { return nullptr; }
  /// Records one evaluation of the right-hand side at x on a tape that yields its Taylor coefficients
  /// (TaylorTape.h). Models with a templated field do it with no code of their own; the rest throw
  /// InputError saying that the Taylor method cannot expand them.
  virtual void recordField(taylor::Tape& tape, const double* x) const;
  /// Values of the first integrals, in the order of info().integralNames.
  virtual Eigen::VectorXd integrals(const double* x) const;
  /// Density of the invariant measure (1 when hasInvariantMeasure() is false).
  virtual double measureDensity(const double* x) const;
  /// Whether measureDensity() is invariant at these parameter values (info().hasMeasure unless a model knows
  /// better).
  virtual bool hasInvariantMeasure() const { return info_->hasMeasure; }
  /// Pose of the body, for models that have one.
  virtual std::optional<BodyPose> pose(const double* x) const;
  /// The body's shape in its frame, for models that have one.
  virtual std::optional<BodyGeometry> geometry() const;
  /// The surface the body rolls on; nothing means the plane z = 0.
  virtual std::optional<SupportSurface> support() const;

  /// A full state from named components; names the model can derive may be omitted.
  /// Throws InputError naming `context` and the offending name.
  virtual Eigen::VectorXd stateFromNamed(const std::map<std::string, double>& named,
                                         const std::string& context) const;
  /// Which sheet (root of the completion, 1-based) a state lies on, for many-sheeted maps; 1 when
  /// single-sheeted.
  virtual int sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const;
  /// A full state from a map point, completed through the energy and the other integrals.
  /// Throws InputError when the point has no state (outside the region of allowed motion).
  virtual Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                                       const std::string& context) const;

  /// Bifurcation diagrams on the plane of first integrals at these parameter values (none by default).
  virtual std::vector<Diagram> diagrams() const { return {}; }

  const std::vector<Observable>& observables() const { return observables_; }
  /// Index of an observable by id, or -1.
  int findObservable(const std::string& id) const;

protected:
  /// Adds the state components, t, and the integrals as observables; call from the constructor.
  void addStandardObservables();
  void addObservable(std::string id, std::string description, std::function<double(double, const double*)> f);
  void addObservables(std::vector<Observable> list);
  /// Fills `x` from `named`; components absent from `named` keep their value. Rejects unknown names.
  void assignNamed(const std::map<std::string, double>& named, const std::string& context,
                   Eigen::VectorXd& x) const;

  const ModelInfo* info_;
  ParameterValues params_;
  std::vector<Observable> observables_;
};

} // namespace rv
