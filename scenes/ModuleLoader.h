// ModuleLoader.h -- loads the rollviz modules (scenes/Module.h, docs/modules.md) at start, in the CLI, the
// GUI, the Python module and on every MPI rank: the shared libraries in the folders of ROLLVIZ_MODULE_PATH
// (colon-separated) and in ~/.local/lib/rollviz/modules, then the files given with `--module FILE`. A module
// is refused, with a message that says why, when its stamp (rollviz version, compiler ABI) differs from
// rollviz's, when it has no entry point, or when it registers an id that is already taken (the message names
// both files); nothing of a refused module is registered. A file found in a folder that cannot be loaded is
// skipped with a warning naming it; one given by name is bad input (InputError).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace rv {

/// A loaded module and what it added.
struct LoadedModule {
  std::string path;
  std::vector<std::string> models, integrators, tools;
};

/// Where warnings go (the CLI and Python print them on stderr).
using ModuleWarning = std::function<void(const std::string&)>;

/// Loads the modules of the search path (once per process) and then `files`; a file already loaded (the
/// same real path) is not loaded again. Throws InputError for a file of `files` that is refused.
void loadModules(const std::vector<std::string>& files, const ModuleWarning& warn);

/// Loads one module file; throws InputError "FILE: why" when it is refused.
void loadModule(const std::string& path);

/// The modules loaded so far, in load order.
const std::vector<LoadedModule>& loadedModules();

/// The folders searched: those of ROLLVIZ_MODULE_PATH, then ~/.local/lib/rollviz/modules.
std::vector<std::string> moduleSearchPath();

/// The stamp modules are compared with (ROLLVIZ_ABI_STAMP of this build).
const char* moduleStamp();

} // namespace rv
