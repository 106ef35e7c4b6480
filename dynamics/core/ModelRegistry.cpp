#include "dynamics/core/ModelRegistry.h"

#include "dynamics/core/Errors.h"

namespace rv {

ModelRegistry& ModelRegistry::mutableGlobal() {
  static ModelRegistry registry = [] {
    ModelRegistry r;
    registerBuiltinModels(r);
    return r;
  }();
  return registry;
}

const ModelRegistry& ModelRegistry::global() {
  return mutableGlobal();
}

void ModelRegistry::add(ModelEntry entry) {
  if (const ModelEntry* e = find(entry.info->id))
    throw InputError(alreadyRegistered("problem", entry.info->id, e->origin));
  entries_.push_back(std::move(entry));
}

const ModelEntry* ModelRegistry::find(const std::string& id) const {
  for (const auto& e : entries_)
    if (e.info->id == id) return &e;
  return nullptr;
}

std::string notInAnyModule() {
  return "provided by no loaded module -- is ROLLVIZ_MODULE_PATH set? (--module FILE loads one; `rollviz "
         "info` "
         "lists the loaded ones)";
}

std::string alreadyRegistered(const std::string& kind, const std::string& id, const std::string& origin) {
  return kind + " '" + id + "' is already registered by " + (origin.empty() ? "rollviz itself" : origin);
}

const ModelEntry& ModelRegistry::get(const std::string& id) const {
  std::string known;
  for (const auto& e : entries_) {
    if (e.info->id == id) return e;
    known += " " + e.info->id;
  }
  throw InputError("unknown problem '" + id + "' (known:" + known + "): " + notInAnyModule());
}

} // namespace rv
