// ToolControl.h -- how a running tool learns that it should stop, and reports how far it got.
#pragma once
#include <functional>

namespace rv {

struct ToolControl {
  std::function<bool()> stopRequested = [] { return false; }; ///< polled often (at least once per step)
  std::function<void(double)> progress = [](double) {};       ///< fraction done in [0, 1]
};

} // namespace rv
