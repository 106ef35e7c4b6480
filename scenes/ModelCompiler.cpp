#include "scenes/ModelCompiler.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/models/ModelCode.h"
#include "rollviz/Toolchain.h"
#include "rollviz/Version.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ; // NOLINT(readability-redundant-declaration): posix_spawn passes it on

namespace rv {
namespace fs = std::filesystem;

namespace {

/// FNV-1a, 64 bits: a stable content hash (the same on every run and build, unlike std::hash).
std::string contentHash(const std::string& bytes) {
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char out[17];
  std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
  return out;
}

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path cacheDirectory() {
  if (const char* d = std::getenv("ROLLVIZ_MODEL_CACHE"); d && *d) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "rollviz" / "models";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "rollviz" / "models";
  return fs::temp_directory_path() / "rollviz-models";
}

struct Toolchain {
  std::string compiler;
  std::vector<std::string> includes; // the rollviz headers (installed SDK or the source and build trees)
  std::string eigen, libraryDir;
  std::string problem; // why there is none, when compiler is empty
};

// where librollviz_dynamics.so lives: an installed SDK has its headers beside it, a build tree in the source
const Toolchain& toolchain() {
  static const Toolchain t = [] {
    Toolchain t;
    Dl_info where{};
    if (dladdr(reinterpret_cast<void*>(&modelCode), &where) == 0 || where.dli_fname == nullptr) {
      t.problem = "the rollviz library's folder is unknown";
      return t;
    }
    const fs::path lib = fs::weakly_canonical(where.dli_fname);
    t.libraryDir = lib.parent_path().string();
    const fs::path installed = lib.parent_path().parent_path() / "include" / "rollviz";
    std::error_code ec;
    if (fs::exists(installed / "dynamics" / "core" / "ModelWithField.h", ec))
      t.includes = {installed.string()};
    else if (fs::exists(fs::path(ROLLVIZ_SOURCE_INCLUDE_DIR) / "dynamics" / "core" / "ModelWithField.h", ec))
      t.includes = {ROLLVIZ_SOURCE_INCLUDE_DIR, ROLLVIZ_BINARY_INCLUDE_DIR};
    else {
      t.problem = "the rollviz headers are not installed (cmake --install gives them)";
      return t;
    }
    t.eigen = ROLLVIZ_EIGEN_INCLUDE_DIR;
    if (!fs::exists(fs::path(t.eigen) / "Eigen" / "Core", ec)) {
      t.problem = "Eigen's headers are missing (" + t.eigen + ")";
      return t;
    }
    if (access(ROLLVIZ_CXX_COMPILER, X_OK) != 0) {
      t.problem =
          std::string("the C++ compiler that built rollviz is missing (") + ROLLVIZ_CXX_COMPILER + ")";
      return t;
    }
    t.compiler = ROLLVIZ_CXX_COMPILER;
    return t;
  }();
  return t;
}

std::vector<std::string> compileArguments(const Toolchain& t, const std::string& source,
                                          const std::string& out) {
  std::vector<std::string> a{t.compiler, "-std=c++20", "-O2", "-DNDEBUG", "-fPIC", "-shared", "-w"};
  for (const auto& i : t.includes)
    a.insert(a.end(), {"-I", i});
  a.insert(a.end(), {"-isystem", t.eigen, source, "-o", out, "-L", t.libraryDir, "-lrollviz_dynamics",
                     "-Wl,-rpath," + t.libraryDir});
  return a;
}

/// Runs argv[0] with `argv` (no shell), its output into `log`; the exit status, or -1 when it cannot start.
int run(const std::vector<std::string>& argv, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const auto& s : argv)
    args.push_back(
        const_cast<char*>(s.c_str())); // NOLINT(cppcoreguidelines-pro-type-const-cast): exec's type
  args.push_back(nullptr);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, argv[0].c_str(), &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The library's recorded hash (written after a successful compilation) matches its bytes.
bool intact(const fs::path& lib, const fs::path& sum) {
  std::error_code ec;
  if (!fs::exists(lib, ec) || !fs::exists(sum, ec)) return false;
  return readAll(sum) == contentHash(readAll(lib)) + "\n";
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile file(path, path);
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out << text;
    if (!out) throw ComputationError("cannot write " + path);
  }
  file.commit();
}

std::string firstLines(const std::string& text, int lines) {
  std::istringstream in(text);
  std::string out, line;
  for (int i = 0; i < lines && std::getline(in, line); ++i)
    out += (i ? "\n  " : "  ") + line;
  return out;
}

} // namespace

std::size_t largestCompiledSource() {
  const char* v = std::getenv("ROLLVIZ_COMPILE_MAX_BYTES");
  char* end = nullptr;
  const double bytes = v ? std::strtod(v, &end) : 0;
  if (!v || end == v || !(bytes >= 0)) return 1'000'000;
  return bytes < 1e15 ? static_cast<std::size_t>(bytes) : std::size_t{1'000'000'000'000'000};
}

bool compileModelsByDefault() {
  const char* v = std::getenv("ROLLVIZ_COMPILE_MODELS");
  return !(v && std::string(v) == "0");
}

bool modelCompilationAvailable(std::string* why) {
  const Toolchain& t = toolchain();
  if (why) *why = t.compiler.empty() ? t.problem : t.compiler + ", cache " + cacheDirectory().string();
  return !t.compiler.empty();
}

CompiledModelFactory compiledModel(const std::shared_ptr<const EquationSystem>& system,
                                   const std::function<void(const std::string&)>& note) {
  const Toolchain& t = toolchain();
  const std::string& id = system->info().id;
  if (t.compiler.empty()) {
    static std::once_flag said; // once per process, not per model
    std::call_once(said, [&] { note("model files run interpreted: " + t.problem); });
    return {};
  }
  const std::string code = modelCode(*system);
  // the compiler's time grows faster than the code (a computer-algebra Lagrangian of 100 000 terms waited
  // more than five minutes); past this size the interpreter, which starts at once, is the faster way
  if (const std::size_t largest = largestCompiledSource(); code.size() > largest) {
    note("the model '" + id + "' runs interpreted: its generated code (" +
         std::to_string(code.size() / 1000) + " kB) is larger than ROLLVIZ_COMPILE_MAX_BYTES (" +
         std::to_string(largest) + "), past which compiling costs more than it saves");
    return {};
  }
  std::string identity = code + "\n" + ROLLVIZ_ABI_STAMP;
  for (const auto& a : compileArguments(t, "SOURCE", "OUT"))
    identity += "\n" + a;
  const std::string key = contentHash(identity);
  static std::mutex mutex;
  static std::map<std::string, CompiledModelCreate> loaded;
  const std::lock_guard lock(mutex);
  CompiledModelCreate create = nullptr;
  if (const auto it = loaded.find(key); it != loaded.end()) create = it->second;
  if (!create) {
    const fs::path dir = cacheDirectory();
    std::error_code ec;
    fs::create_directories(dir, ec);
    const fs::path lib = dir / (key + ".so"), sum = dir / (key + ".sum"), source = dir / (key + ".cpp");
    if (!intact(lib, sum)) {
      note("compiling the model '" + id + "' to native code (first use; cached in " + dir.string() + ") ...");
      const auto started = std::chrono::steady_clock::now();
      const std::string unique = "." + std::to_string(getpid()) + ".tmp";
      try {
        writeFileAtomically(source.string(), code);
      } catch (const std::exception& e) {
        note("model files run interpreted: cannot write the generated code: " + std::string(e.what()));
        return {};
      }
      const fs::path out = dir / (key + unique + ".so"), log = dir / (key + ".log");
      if (run(compileArguments(t, source.string(), out.string()), log.string()) != 0) {
        fs::remove(out, ec);
        note("the model '" + id + "' runs interpreted: its generated code did not compile (" + log.string() +
             "):\n" + firstLines(readAll(log), 6));
        return {};
      }
      try {
        writeFileAtomically(sum.string(), contentHash(readAll(out)) + "\n");
      } catch (const std::exception& e) {
        note("model files run interpreted: " + std::string(e.what()));
        return {};
      }
      fs::rename(out, lib, ec);
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      char text[64];
      std::snprintf(text, sizeof text, "%.1f", seconds);
      note("compiled the model '" + id + "' in " + text + " s");
      if (!intact(lib, sum)) {
        note("the model '" + id + "' runs interpreted: its compiled library changed after it was written");
        return {};
      }
    }
    void* handle = dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      note("the model '" + id + "' runs interpreted: " + std::string(dlerror()));
      return {};
    }
    const auto stamp = reinterpret_cast<const char* (*)()>(dlsym(handle, kCompiledModelStamp));
    create = reinterpret_cast<CompiledModelCreate>(dlsym(handle, kCompiledModelCreate));
    if (!stamp || !create || std::string(stamp()) != ROLLVIZ_ABI_STAMP) {
      note("the model '" + id + "' runs interpreted: " + lib.string() + " was built for another rollviz");
      return {}; // the handle stays open: nothing of it was used
    }
    loaded.emplace(key, create); // never unloaded: models made by it may outlive every scene
  }
  return [system, create](const ParameterValues& p) { return std::unique_ptr<Model>(create(&system, &p)); };
}

} // namespace rv
