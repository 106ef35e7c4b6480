// BifurcationTree.h -- the cascade of period doublings of an elliptic fixed point (manual §2.3.7): the point
// is continued until a multiplier passes -1, the bifurcation value is located, the points of doubled period
// are sought at the initial size of the bifurcation region along the eigenvector of the -1 multiplier and
// continued in turn; at each level the step, the accuracy of the bifurcation value and the region shrink by
// the coefficient, by default the Feigenbaum constant of area-preserving maps, 8.721097200 (Greene, MacKay,
// Vivaldi & Feigenbaum, Physica D 3 (1981) 468; Benettin, Cercignani, Galgani & Giorgilli, Lett. Nuovo
// Cimento 28 (1980) 1). A point of a doubled family is accepted only when its minimal period is the doubled
// one (the parent orbit is a fixed point of the doubled order too, and Newton near the pitchfork of Map^2n
// falls onto it); the tree ends when the next bifurcation value could no longer be told apart from the last
// in double precision.
#pragma once
#include "dynamics/tools/Continuation.h"

namespace rv {

struct BifurcationTreeSettings {
  ContinuationSettings continuation; ///< parameter, finite value, step, search settings
  double bifurcationAccuracy = 1e-8; ///< of the first bifurcation value
  double regionSize = 0.05;          ///< initial distance from the point to the first guess of doubled period
  double coefficient = 8.721097200;  ///< by which step, accuracy and region shrink at each doubling
  int maxLevels = 5;                 ///< doublings followed at most
};

/// A period doubling found on the way.
struct PeriodDoubling {
  int level = 0;        ///< 0: of the initial point
  int order = 1;        ///< the order of the point that doubles
  double parameter = 0; ///< the bifurcation value
  Eigen::VectorXd point;
};

/// A continued family of the tree.
struct TreeBranch {
  int level = 0;
  int order = 1;
  std::vector<ContinuationPoint> points;
};

struct BifurcationTreeResult {
  std::vector<TreeBranch> branches;
  std::vector<PeriodDoubling> doublings;
  /// Why the tree ended: "the finite value is reached", "levels reached", ... (empty while it grows).
  std::string end;
  /// (p_k - p_{k-1}) / (p_{k+1} - p_k) for consecutive doublings: tends to the Feigenbaum constant.
  std::vector<double> ratios() const;
};

/// Builds the tree from the elliptic fixed point of order `section.order` near `guess` at parameter value
/// `start`. Streams every continued point (with its level and order) and every doubling. Throws
/// ComputationError when the initial point is not elliptic or its family cannot be followed; past the first
/// doubling a failure ends the tree (the reason in `end`). Stopped when asked to stop (what was found so far
/// is in `partial`).
BifurcationTreeResult
bifurcationTree(const Continuation::ModelAt& modelAt, const IntegratorFactory& makeIntegrator,
                const SectionSettings& section, double start, const Eigen::VectorXd& guess,
                const BifurcationTreeSettings& settings, const ToolControl& control = {},
                const std::function<void(const TreeBranch&, const ContinuationPoint&)>& onPoint = {},
                const std::function<void(const PeriodDoubling&)>& onDoubling = {},
                BifurcationTreeResult* partial = nullptr);

} // namespace rv
