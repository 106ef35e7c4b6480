// Derivative.h -- exact derivatives written into the graph itself (symbolic forward mode): the directional
// derivative of some nodes along tangents given to others, as new nodes. The language's derivative(),
// gradient() and jacobian() lower to it, so a model file (and a rolling body's generated equations,
// scenes/RollingModel.h) can state the rate of a contact point or the torque of a potential without writing
// the derivative out by hand, and the result is again plain graph nodes: interpreted, compiled and
// differentiated once more like any other.
// Reference: A. Griewank, A. Walther, Evaluating Derivatives (2008), ch. 3 (the tangent rules of each
// elementary operation).
#pragma once
#include "dynamics/expr/Graph.h"

#include <utility>
#include <vector>

namespace rv::expr {

/// The most nodes a graph may hold while derivatives are written into it: each derivative multiplies the
/// operations a few times, so derivatives of derivatives grow geometrically (an error, not a hang).
constexpr int kMaxDerivativeGraph = 250'000;

/// The nodes d(output)/dt when each seed's node `first` moves at the rate given by node `second` and every
/// other node that does not depend on a seed stands still (a partial derivative through the seeds' nodes).
/// A seed that is a constant node is an error of the caller. Min, max, abs and sign differentiate as the
/// branch taken. Throws InputError when the graph would pass kMaxDerivativeGraph nodes.
std::vector<int> directionalDerivative(Graph& graph, const std::vector<int>& outputs,
                                       const std::vector<std::pair<int, int>>& seeds);

} // namespace rv::expr
