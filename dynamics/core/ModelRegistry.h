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
  /// Where it comes from: "" for rollviz's own, else the module file that registered it.
  std::string origin = {};
};

/// All model kinds, in registration order.
class ModelRegistry {
public:
  /// The registry of every model: the built-in ones (models/BuiltinModels.cpp) and those the loaded modules
  /// added (scenes/ModuleLoader.h).
  static const ModelRegistry& global();
  /// The same registry, for the module loader to add to (before any other use: entries are not moved after).
  static ModelRegistry& mutableGlobal();
  /// Adds an entry; throws InputError naming both origins when the id is taken.
  void add(ModelEntry entry);
  /// The entry with this id, or nullptr.
  const ModelEntry* find(const std::string& id) const;
  /// The entry with this id; throws InputError listing the known ids when there is none.
  const ModelEntry& get(const std::string& id) const;
  const std::vector<ModelEntry>& entries() const { return entries_; }

private:
  std::vector<ModelEntry> entries_;
};

/// What an unknown problem, tool section or command is told: no loaded module provides it, and how modules
/// are found.
std::string notInAnyModule();
/// "KIND 'ID' is already registered by ORIGIN" (rollviz itself when ORIGIN is ""): every registry's refusal.
std::string alreadyRegistered(const std::string& kind, const std::string& id, const std::string& origin);

/// Registers the built-in models (defined in models/BuiltinModels.cpp).
void registerBuiltinModels(ModelRegistry& registry);

} // namespace rv
