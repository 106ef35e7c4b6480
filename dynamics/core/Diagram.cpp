#include "dynamics/core/Diagram.h"

#include "dynamics/core/Errors.h"

namespace rv {

const Diagram& findDiagram(const std::vector<Diagram>& diagrams, const std::string& id,
                           const std::string& flag, const std::string& problem) {
  if (diagrams.empty()) throw InputError(flag + ": " + problem + " has no bifurcation diagrams");
  if (id.empty()) return diagrams.front();
  std::string known;
  for (const auto& d : diagrams) {
    if (d.id == id) return d;
    known += " " + d.id;
  }
  throw InputError(flag + " " + id + ": unknown diagram of " + problem + " (known:" + known + ")");
}

} // namespace rv
