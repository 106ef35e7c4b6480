// ModelRegistry.h -- models registered by id; front ends list, describe and build them by name.
#pragma once
#include "dynamics/core/Model.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rv {

/// One registered model kind: its constant description and how to build an instance.
struct ModelEntry {
  const ModelInfo* info;
  /// Builds the model; throws InputError naming the parameter when the values are inconsistent.
  std::function<std::unique_ptr<Model>(const ParameterValues&)> create;
};

/// All model kinds, in registration order.
class ModelRegistry {
public:
  /// The registry with every built-in model (see models/BuiltinModels.cpp).
  static const ModelRegistry& builtin();
  void add(ModelEntry entry);
  /// The entry with this id; throws InputError listing the known ids when there is none.
  const ModelEntry& get(const std::string& id) const;
  const std::vector<ModelEntry>& entries() const { return entries_; }

private:
  std::vector<ModelEntry> entries_;
};

/// Registers the built-in models (defined in models/BuiltinModels.cpp).
void registerBuiltinModels(ModelRegistry& registry);

} // namespace rv
