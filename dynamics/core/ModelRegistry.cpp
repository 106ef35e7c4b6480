#include "dynamics/core/ModelRegistry.h"

#include "dynamics/core/Errors.h"

namespace rv {

const ModelRegistry& ModelRegistry::builtin() {
  static const ModelRegistry registry = [] {
    ModelRegistry r;
    registerBuiltinModels(r);
    return r;
  }();
  return registry;
}

void ModelRegistry::add(ModelEntry entry) {
  entries_.push_back(std::move(entry));
}

const ModelEntry& ModelRegistry::get(const std::string& id) const {
  std::string known;
  for (const auto& e : entries_) {
    if (e.info->id == id) return e;
    known += " " + e.info->id;
  }
  throw InputError("unknown problem '" + id + "' (known:" + known + ")");
}

} // namespace rv
