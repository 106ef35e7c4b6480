#include "scenes/ModuleLoader.h"

#include "dynamics/core/Errors.h"
#include "scenes/BuiltinTools.h"
#include "scenes/Module.h"
#include "scenes/SceneLoader.h"

#include <algorithm>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <set>

namespace rv {

namespace fs = std::filesystem;

namespace {

std::vector<LoadedModule>& moduleList() {
  static std::vector<LoadedModule> m;
  return m;
}

std::string realPath(const std::string& path) {
  std::error_code ec;
  const auto p = fs::canonical(path, ec);
  return ec ? path : p.string();
}

// everything the module registers, added first to copies of the registries (so their own refusals apply,
// among the module's parts too) before any of it is added for real
void check(const ModuleRegistrar& r, const std::string& path) {
  try {
    ModelRegistry models = ModelRegistry::global();
    for (ModelEntry m : r.models) {
      if (!m.info || !m.create) throw InputError("registers a model without its description or factory");
      m.origin = path;
      models.add(std::move(m));
    }
    IntegratorRegistry integrators = IntegratorRegistry::global();
    for (IntegratorEntry i : r.integrators) {
      if (!i.parameters || !i.create)
        throw InputError("registers the integrator '" + i.id + "' without its parameters or factory");
      i.origin = path;
      integrators.add(std::move(i));
    }
    ToolRegistry tools = ToolRegistry::global();
    std::set<std::string> sections;
    for (const auto& t : r.tools) {
      ToolEntry e = t.entry;
      e.origin = path;
      tools.add(std::move(e));
      if (!t.runner.run) throw InputError("the tool '" + t.entry.id + "' has no run function");
      if (!t.settings) continue;
      const std::string& key = t.entry.section;
      if (sceneKeys().count(key)) // the scene's own keys cannot be a tool's section either
        throw InputError("the tool '" + t.entry.id + "' takes the scene key '" + key +
                         "' as its settings section");
      if (const ToolSection* s = findToolSection(key))
        throw InputError(alreadyRegistered("settings section", key, s->origin));
      if (!sections.insert(key).second) throw InputError(alreadyRegistered("settings section", key, path));
    }
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

} // namespace

const char* moduleStamp() {
  return ROLLVIZ_ABI_STAMP;
}

std::vector<std::string> moduleSearchPath() {
  std::vector<std::string> dirs;
  if (const char* p = std::getenv("ROLLVIZ_MODULE_PATH")) {
    std::string s = p;
    std::size_t start = 0;
    while (start <= s.size()) {
      const std::size_t end = std::min(s.find(':', start), s.size());
      if (end > start) dirs.push_back(s.substr(start, end - start));
      start = end + 1;
    }
  }
  if (const char* home = std::getenv("HOME"); home && *home)
    dirs.push_back(std::string(home) + "/.local/lib/rollviz/modules");
  return dirs;
}

void loadModule(const std::string& given) {
  const std::string path = realPath(given);
  for (const auto& m : moduleList())
    if (m.path == path) return;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(given + ": no such module file");
  // RTLD_LOCAL: the module's own symbols stay its own; it resolves rollviz's against the loaded libraries
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw InputError(given + ": cannot be loaded as a module: " + (why ? why : "unknown reason"));
  }
  // a refused module is not closed: what it ran may have left objects of its code behind
  using StampFn = const char* (*)();
  using RegisterFn = void (*)(ModuleRegistrar&);
  const auto stamp = reinterpret_cast<StampFn>(dlsym(handle, ROLLVIZ_MODULE_STAMP_SYMBOL));
  const auto enter = reinterpret_cast<RegisterFn>(dlsym(handle, ROLLVIZ_MODULE_REGISTER_SYMBOL));
  if (!stamp || !enter)
    throw InputError(given + ": not a rollviz module (no ROLLVIZ_MODULE entry point; see docs/modules.md)");
  const std::string theirs = stamp() ? stamp() : "";
  if (theirs != moduleStamp())
    throw InputError(given + ": built for another rollviz or compiler ABI (module: \"" + theirs +
                     "\"; this rollviz: \"" + moduleStamp() + "\"): rebuild it against this rollviz's SDK");
  ModuleRegistrar r;
  try {
    enter(r);
  } catch (const std::exception& e) {
    throw InputError(given + ": its entry point failed: " + e.what());
  }
  check(r, path);
  LoadedModule m{path, {}, {}, {}};
  for (auto& e : r.models) {
    m.models.push_back(e.info->id);
    e.origin = path;
    ModelRegistry::mutableGlobal().add(std::move(e));
  }
  for (auto& e : r.integrators) {
    m.integrators.push_back(e.id);
    e.origin = path;
    IntegratorRegistry::mutableGlobal().add(std::move(e));
  }
  for (auto& t : r.tools) {
    m.tools.push_back(t.entry.id);
    t.entry.origin = path;
    if (t.settings) addToolSection({t.entry.section, t.entry.title, t.settings, "", path});
    const std::string id = t.entry.id;
    ToolRegistry::mutableGlobal().add(std::move(t.entry));
    addToolRunner(id, std::move(t.runner));
  }
  moduleList().push_back(std::move(m));
}

void loadModules(const std::vector<std::string>& files, const ModuleWarning& warn) {
  registerBuiltinTools(); // rollviz's own runnable tools first: a module's are checked against them
  static bool searched = false;
  if (!searched) {
    searched = true;
    for (const auto& dir : moduleSearchPath()) {
      std::error_code ec;
      if (!fs::is_directory(dir, ec)) continue;
      std::vector<std::string> found;
      for (const auto& f : fs::directory_iterator(dir, ec))
        if (f.path().extension() == ".so") found.push_back(f.path().string());
      std::sort(found.begin(), found.end());
      for (const auto& f : found) {
        try {
          loadModule(f);
        } catch (const InputError& e) {
          if (warn) warn(std::string("skipped a module: ") + e.what());
        }
      }
    }
  }
  for (const auto& f : files)
    loadModule(f);
}

const std::vector<LoadedModule>& loadedModules() {
  return moduleList();
}

} // namespace rv
