#include "dynamics/core/LaneField.h"

#include "dynamics/core/Model.h"

#include <algorithm>

namespace rv {

std::unique_ptr<LaneKernel> laneKernelFor(const std::vector<const Model*>& models) {
  if (models.empty() || models.size() > static_cast<std::size_t>(kMaxLanes)) return nullptr;
  LaneModels lanes(models.size() <= 4 ? 4 : 8);
  for (std::size_t l = 0; l < lanes.size(); ++l)
    lanes[l] = models[std::min(l, models.size() - 1)];
  const auto* field = dynamic_cast<const LaneField*>(lanes[0]);
  return field ? field->laneKernel(lanes) : nullptr;
}

} // namespace rv
