#include "dynamics/tools/LaneStack.h"

#include "dynamics/core/Errors.h"

namespace rv {

namespace {
detail::LaneStackInfo stackedInfo(const Model& base, int dimension, const std::string& what) {
  detail::LaneStackInfo s{base.info()};
  s.stackInfo.id = base.info().id + "+" + what;
  s.stackInfo.stateNames.clear();
  for (int i = 0; i < dimension; ++i)
    s.stackInfo.stateNames.push_back("y" + std::to_string(i));
  s.stackInfo.coreDimension = dimension;
  s.stackInfo.integralNames.clear();
  s.stackInfo.hasMeasure = false;
  return s;
}
} // namespace

LaneStack::LaneStack(const Model& base, const LaneKernel& kernel, int perLane, const std::string& what)
    : detail::LaneStackInfo(stackedInfo(base, kernel.width() * perLane, what)),
      Model(stackInfo, base.parameters()), kernel_(kernel), lanes_(kernel.width()) {}

void LaneStack::jacobian(const double*, double*) const {
  throw ComputationError("the Jacobian of " + info().id + " is not available");
}

} // namespace rv
