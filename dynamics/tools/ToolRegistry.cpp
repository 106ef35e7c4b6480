#include "dynamics/tools/ToolRegistry.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"

namespace rv {

namespace {
std::vector<ToolSection>& sections() {
  static std::vector<ToolSection> s;
  return s;
}
} // namespace

const std::vector<ToolSection>& toolSections() {
  return sections();
}

void addToolSection(ToolSection section) {
  if (const ToolSection* s = findToolSection(section.key))
    throw InputError(alreadyRegistered("settings section", section.key, s->origin));
  sections().push_back(std::move(section));
}

const ToolSection* findToolSection(const std::string& key) {
  for (const auto& s : toolSections())
    if (s.key == key) return &s;
  return nullptr;
}

const ToolRegistry& ToolRegistry::global() {
  return mutableGlobal();
}

void ToolRegistry::add(ToolEntry entry) {
  if (const ToolEntry* e = find(entry.id)) throw InputError(alreadyRegistered("tool", entry.id, e->origin));
  if (!entry.command.empty())
    for (const auto& e : entries_)
      if (e.command == entry.command) throw InputError(alreadyRegistered("command", entry.command, e.origin));
  if (!entry.parent.empty() && !find(entry.parent))
    throw InputError("tool '" + entry.id + "': its parent '" + entry.parent + "' is not registered");
  entries_.push_back(std::move(entry));
}

ToolRegistry& ToolRegistry::mutableGlobal() {
  static ToolRegistry r;
  return r;
}

const ToolEntry* ToolRegistry::find(const std::string& id) const {
  for (const auto& e : entries_)
    if (e.id == id) return &e;
  return nullptr;
}

const ToolEntry& ToolRegistry::get(const std::string& id) const {
  if (const ToolEntry* e = find(id)) return *e;
  std::string known;
  for (const auto& e : entries_)
    known += " " + e.id;
  throw InputError("unknown tool '" + id + "' (known:" + known + ")");
}

} // namespace rv
