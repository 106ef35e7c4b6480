// EquationModel.h -- a model written as equations (a model file, scenes/ModelFile.h): the texts parsed and
// checked once (EquationSystem), then, for each set of parameter values, lowered to scalar programs with the
// parameters folded in (EquationModel): the right-hand side, its exact derivatives by forward mode, the
// Taylor recording, the integrals, the measure, the observables, the completion of states and map points,
// and the body's pose. A flow that reads the time `t` gets a last state component `time` with d time/dt = 1
// (the autonomous extension), so every tool applies unchanged.
#pragma once
#include "dynamics/core/BodyShapes.h"
#include "dynamics/core/ExplainsNonFinite.h"
#include "dynamics/core/Model.h"
#include "dynamics/expr/Expression.h"
#include "dynamics/expr/Graph.h"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rv {

/// The text of one expression and where it stands in its file (a JSON path such as "equations.x").
struct ExprText {
  std::string text;
  std::string where;
};

/// The shape a definition must have (rows x cols; cols 1: a vector; 1 x 1: a scalar) and what it is, for the
/// message: a value of the wrong size is then named at the definition, not where it is first used.
struct RequiredShape {
  int rows = 1, cols = 1;
  std::string what;
};

/// Everything a model file declares, with the texts not yet parsed.
struct EquationModelSpec {
  /// id, title, reference, parameters, stateNames, kind, mapCoordinates, section; the rest is derived.
  ModelInfo info;
  /// Vectors made of state components (name, component names): usable in expressions and as equation keys.
  std::vector<std::pair<std::string, std::vector<std::string>>> vectors;
  /// Intermediate definitions (name, expression), in any order: each may use the ones it needs.
  std::vector<std::pair<std::string, ExprText>> definitions;
  /// Shapes some definitions must have, by name (a rolling model's: the user's sizes, scenes/RollingModel.h).
  std::map<std::string, RequiredShape> definitionShapes;
  /// d(variable)/dt of a flow or the next value of a map, by state variable or state vector name.
  std::vector<std::pair<std::string, ExprText>> equations;
  struct ObservableText {
    std::string id, description;
    ExprText value;
    bool angle = false;    ///< an angle (sections on it are crossed where sin(value - v0) = 0)
    bool integral = false; ///< a first integral (conserved; listed in info.integralNames)
  };
  std::vector<ObservableText> observables;
  std::optional<ExprText> measure; ///< density of an invariant measure
  /// Default values of state variables a scene does not give, from the ones it gives (in this order).
  std::vector<std::pair<std::string, ExprText>> completion;
  /// A stroboscopic section: the period T of a time section (the observable "strobe" = 2 pi t / T).
  std::optional<ExprText> strobePeriod;

  /// How a map point (coordinates named info.mapCoordinates) becomes a state.
  struct MapCompletion {
    std::vector<std::string> symbols; ///< the coordinates' names in the expressions below
    /// Every state variable as an expression of the symbols, `section` (the section's value) and, when
    /// `unknown` is set, the unknown: solved so that the observable `integral` equals `value`.
    std::vector<std::pair<std::string, ExprText>> state;
    std::string unknown;
    ExprText from, to, step; ///< the range scanned for roots in the unknown, and the scan step
    std::string integral;
    ExprText value;
    double accuracy = 1e-15;
  };
  std::optional<MapCompletion> map;

  /// A drawn shape whose sizes are expressions of the parameters.
  struct Shape {
    BodyShape shape = BodyShape::None;
    std::optional<ExprText> semiAxes; ///< ellipsoid: a 3-vector; ball: the radius
    std::optional<ExprText> centre;   ///< body: its centre in its frame; support: in the world
    std::optional<ExprText> p, q, height;
  };
  /// The body drawn in the 3D view and what it rolls on.
  struct View {
    Shape body;
    std::string mesh;                       ///< or a mesh file (STL, OBJ) for the body: its absolute path
    std::optional<ExprText> meshScale;      ///< the mesh's coordinates are multiplied by it
    std::optional<ExprText> surface;        ///< or the body's implicit surface F(x, y, z) = 0 about `centre`
    std::optional<ExprText> surfaceSize;    ///< a length that bounds that surface
    Shape support;                          ///< the fixed surface (None: the plane z = 0)
    std::optional<ExprText> supportSurface; ///< or the support's implicit surface F(x, y, z) = 0, world axes
    std::optional<ExprText> supportSurfaceSize; ///< a length that bounds the part of it drawn
    ExprText rotation;                          ///< body -> world, a 3x3 matrix of the state
    ExprText position;                          ///< the pose's centre in the world
    ExprText contact;                           ///< the contact point in the world
    std::optional<ExprText> normal;             ///< the support's normal at the contact (else from its shape)
  };
  std::optional<View> view;
  std::string source; ///< the file, for messages
};

/// A checked model: the spec with every expression parsed, names and shapes verified (at the default
/// parameter values). Shared by every instance.
class EquationSystem : public std::enable_shared_from_this<EquationSystem> {
public:
  /// Parses and checks every expression (lowering them at the default parameter values); throws InputError
  /// "WHERE: column C: what is wrong".
  static std::shared_ptr<const EquationSystem> build(EquationModelSpec spec);
  const EquationModelSpec& spec() const { return spec_; }
  /// The model's constant description (with integralNames, hasMeasure, coreDimension and the time
  /// component filled in).
  const ModelInfo& info() const { return info_; }
  bool nonAutonomous() const { return nonAutonomous_; }
  /// Parsed expressions by their `where`.
  const expr::Expression& parsed(const std::string& where) const;
  /// The interpreted model at these parameter values.
  std::unique_ptr<Model> create(const ParameterValues& params) const;
  /// The right-hand side with the parameters as inputs: slots 0..n-1 the state, n the time, n + 1 + k
  /// parameter k (what the generated C++ computes, ModelCode.h).
  expr::Program parametricField() const;

private:
  explicit EquationSystem(EquationModelSpec spec);
  EquationModelSpec spec_;
  ModelInfo info_;
  bool nonAutonomous_ = false;
  std::vector<std::pair<std::string, expr::Expression>> parsed_;
};

/// The programs of one system at fixed parameter values. Its input slots are the state then the time.
class EquationModel final : public Model, public ExplainsNonFinite, public DrawnFromMesh {
public:
  EquationModel(std::shared_ptr<const EquationSystem> system, const ParameterValues& params);

  void rhs(const double* x, double* dx) const override;
  void jacobian(const double* x, double* jac) const override;
  void coreJacobian(const double* x, double* jac) const override;
  void tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const override;
  void recordField(taylor::Tape& tape, const double* x) const override;
  Eigen::VectorXd integrals(const double* x) const override;
  double measureDensity(const double* x) const override;
  std::optional<BodyPose> pose(const double* x) const override;
  std::optional<BodyGeometry> geometry() const override { return geometry_; }
  std::optional<SupportSurface> support() const override;
  std::optional<BodyMeshFile> bodyMesh() const override { return mesh_; }
  std::optional<ImplicitSurface> bodySurface() const override;
  std::optional<ImplicitSurface> supportSurface() const override;
  Eigen::VectorXd stateFromNamed(const std::map<std::string, double>& named,
                                 const std::string& context) const override;
  Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                               const std::string& context) const override;
  int sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const override;
  std::string nonFiniteCause(const double* x) const override;

  /// The field's program (for tests and the code generator).
  const expr::Program& field() const { return field_; }

private:
  /// Roots of the map completion's unknown at a point; `state` (when given) the state on root `root`.
  std::vector<double> completionRoots(const std::vector<double>& point, double section,
                                      Eigen::VectorXd* state, int root) const;
  std::shared_ptr<const EquationSystem> system_;
  expr::Graph graph_;
  expr::Program field_, integrals_, measure_, pose_, map_;
  std::vector<std::pair<int, expr::Program>> completion_; // state index, its default
  std::optional<BodyGeometry> geometry_;
  std::optional<BodyGeometry> support_; // the fixed surface, when not the plane
  std::optional<double> supportCap_;    // a sphere or ellipsoid drawn up to this height above its bottom
  std::optional<BodyMeshFile> mesh_;
  std::optional<expr::Program> surface_; ///< the implicit body's F of inputs 0..2, about the shape's centre
  double surfaceSize_ = 1;
  std::optional<expr::Program> supportSurface_; ///< the implicit support's F of inputs 0..2, world axes
  double supportSurfaceSize_ = 1;
  bool poseHasNormal_ = false; // the pose program's last three outputs are the normal
  int unknownObservable_ = -1; // the observable holding the map completion's unknown, if any
};

} // namespace rv
