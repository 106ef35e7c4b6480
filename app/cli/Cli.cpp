#include "app/cli/Cli.h"

#include "app/cli/Commands.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/io/FileNames.h"
#include "dynamics/tools/ToolRegistry.h"
#include "scenes/ToolRunner.h"

#include "render/context/HeadlessContext.h"
#include "scenes/ModelCompiler.h"
#include "scenes/ModuleLoader.h"

#include <cstdlib>
#include <filesystem>
#include <fmt/core.h>
#include <unistd.h>

namespace rv {

Scene SceneArgs::load() const {
  std::vector<SceneOverride> overrides;
  for (const auto& s : sets)
    overrides.push_back(parseOverride(s));
  return loadScene(scene, overrides);
}

void addSceneArgs(CLI::App* cmd, SceneArgs& args) {
  cmd->add_option("scene", args.scene, "scene file (scenes/<problem>.json)")->required();
  cmd->add_option("--set", args.sets, "override a parameter or scene field: ID=VALUE (repeatable)")
      ->type_name("ID=VALUE")
      ->take_all()
      ->allow_extra_args(false);
}

CLI::Validator writesOneOf(const std::vector<std::string>& extensions) {
  std::string list;
  for (const auto& e : extensions)
    list += (list.empty() ? "" : ", ") + e;
  return CLI::Validator(
      [extensions, list](std::string& path) -> std::string {
        for (const auto& e : extensions)
          if (hasExtension(path, e)) return {};
        return path + ": unsupported format '" + std::filesystem::path(path).extension().string() +
               "' (the extension names it; supported: " + list + ")";
      },
      "FILE (" + list + ")");
}

std::pair<int, int> parseSize(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 16 ||
      h < 16 || w > 16384 || h > 16384)
    throw InputError("--size " + text + ": expected WIDTHxHEIGHT, each in [16, 16384]");
  return {w, h};
}

namespace {
// the files of every `--module FILE` / `--module=FILE` before the subcommand (CLI11 parses later)
std::vector<std::string> moduleArguments(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--module" && i + 1 < argc)
      files.push_back(argv[++i]);
    else if (a.rfind("--module=", 0) == 0)
      files.push_back(a.substr(9));
  }
  return files;
}

// With no EGL at all, `rollviz` runs the same command as `rollviz-osmesa` from its own folder (OSMesa cannot
// share a process with GLVND's GL: stack/README.md). Outputs are written to temporary names and renamed, so
// nothing the first attempt began is left; the environment variable tells the second why, and stops a loop.
void handOverToOsMesa(char** argv, const char* why) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || self.filename() == "rollviz-osmesa" || std::getenv(kEglUnavailableVariable)) return;
  const auto sibling = self.parent_path() / "rollviz-osmesa";
  if (!std::filesystem::exists(sibling, ec)) return;
  fmt::print(stderr, "rollviz: {}; running {} instead\n", why, sibling.string());
  std::fflush(nullptr);
  setenv(kEglUnavailableVariable, why, 1);
  execv(sibling.c_str(), argv);
  unsetenv(kEglUnavailableVariable); // exec failed: report the original error
}
} // namespace

int runCli(int argc, char** argv, const GuiLauncher& gui) {
  // hidden: a model's compilation in a process of its own, started by a run that would not wait for it
  // (scenes/ModelCompiler.h); it outlives that run and fills the cache
  if (argc == 3 && std::string(argv[1]) == "compile-model") {
    std::string why;
    const int status = compileCachedModel(argv[2], why);
    if (status != 0) fmt::print(stderr, "rollviz compile-model: {}\n", why);
    return status;
  }
  // modules first: the commands, problems and integrators they add must exist before the command line is
  // built
  try {
    loadModules(moduleArguments(argc, argv),
                [](const std::string& w) { fmt::print(stderr, "rollviz: warning: {}\n", w); });
  } catch (const InputError& e) {
    fmt::print(stderr, "rollviz: --module {}\n", e.what());
    return 2;
  }
  CLI::App app{"rollviz: bodies rolling without slipping, and the tools of nonlinear dynamics"};
  app.require_subcommand(0, 1);
  std::vector<std::string> modules; // read above; declared so that --help lists it and parsing accepts it
  app.add_option("--module", modules,
                 "load a module (a shared library built with the SDK, docs/modules.md) before anything else; "
                 "repeatable. Also loaded: those in ROLLVIZ_MODULE_PATH and ~/.local/lib/rollviz/modules")
      ->type_name("FILE");
  std::vector<Command> commands{
      addListCommand(app),      addDescribeCommand(app), addDescribeToolCommand(app),
      addIntegrateCommand(app), addRenderCommand(app),   addVideoCommand(app),
      addPageCommand(app),      addChartCommand(app),    addInfoCommand(app)};
  // every tool that runs on a scene, derived from its registry entry and runner (a module's too)
  for (const auto& tool : ToolRegistry::global().entries())
    if (!tool.command.empty() && findToolRunner(tool.id))
      commands.push_back(addRegisteredToolCommand(app.add_subcommand(tool.command, tool.commandHelp), tool));
  commands.push_back(addSweepCommand(app));
  GuiOptions guiOptions;
  if (gui) {
    auto* cmd = app.add_subcommand("gui", "open the GUI on a scene (the default with no arguments)");
    cmd->add_option("scene", guiOptions.scene, "scene file");
    cmd->add_option("--screenshot", guiOptions.screenshot, "save a PNG of the window before quitting");
    cmd->add_option("--quit-after", guiOptions.quitAfter, "quit after this many seconds");
    cmd->add_option("--status-file", guiOptions.statusFile,
                    "write the window's state there every 0.2 s; creating FILE.quit quits (as --quit-after "
                    "does: screenshot, summary) -- for scripts that wait on conditions");
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e); // prints the message
    // a command that only a module provides reads as stray arguments: say where commands come from
    if (dynamic_cast<const CLI::ExtrasError*>(&e) && app.get_subcommands().empty())
      fmt::print(stderr, "(not a command of rollviz: {})\n", notInAnyModule());
    return 2;
  }
  installInterruptHandler();
  // a model compiled for the run goes on in a process of its own past the wait budget; Ctrl-C stops it
  std::error_code ec;
  if (const auto self = std::filesystem::read_symlink("/proc/self/exe", ec); !ec)
    setModelCompilerProgram(self.string());
  setModelCompilationInterrupted(interrupted);
  struct StopCompilationsOnCtrlC {
    ~StopCompilationsOnCtrlC() {
      if (interrupted()) stopModelCompilations();
    }
  } stopCompilations;
  try {
    for (const auto& c : commands)
      if (c.app->parsed()) return c.run();
    if (!gui) {
      fmt::print(stderr, "rollviz-osmesa has no GUI: give a command\n{}", app.help());
      return 2;
    }
    return gui(argc, argv, guiOptions);
  } catch (const InputError& e) {
    fmt::print(stderr, "rollviz: {}\n", e.what());
    return 2;
  } catch (const HeadlessUnavailable& e) {
    handOverToOsMesa(argv, e.what()); // returns only when it cannot
    fmt::print(stderr, "rollviz: failed: {}\n", e.what());
    return 1;
  } catch (const ComputationError& e) {
    fmt::print(stderr, "rollviz: failed: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rollviz: failed: {}\n", e.what());
    return 1;
  }
}

} // namespace rv
