#include "scenes/ModelCompiler.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/models/ModelCode.h"
#include "rollviz/Toolchain.h"
#include "rollviz/Version.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <spawn.h>
#include <sstream>
#include <sys/file.h>
#include <sys/wait.h>
#include <thread>
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
    // another compiler (a wrapper, or a test's slow stand-in); part of the cache key like every argument
    const char* other = std::getenv("ROLLVIZ_MODEL_COMPILER");
    const std::string compiler = other && *other ? other : ROLLVIZ_CXX_COMPILER;
    if (access(compiler.c_str(), X_OK) != 0) {
      t.problem = (other && *other ? "the compiler ROLLVIZ_MODEL_COMPILER names is missing ("
                                   : "the C++ compiler that built rollviz is missing (") +
                  compiler + ")";
      return t;
    }
    t.compiler = compiler;
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

/// Starts argv[0] with `argv` (no shell), its output into `log` (/dev/null when empty), in a process group of
/// its own when `ownGroup` (a terminal's Ctrl-C then does not reach it); its pid, or -1 when it cannot start.
pid_t spawn(const std::vector<std::string>& argv, const std::string& log, bool ownGroup) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.empty() ? "/dev/null" : log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  if (ownGroup) {
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
  }
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const auto& s : argv)
    args.push_back(
        const_cast<char*>(s.c_str())); // NOLINT(cppcoreguidelines-pro-type-const-cast): exec's type
  args.push_back(nullptr);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return started == 0 ? pid : -1;
}

/// The exit status of a child that ended (-1 when a signal ended it); blocks.
int waitFor(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Runs argv[0] with `argv` (no shell), its output into `log`; the exit status, or -1 when it cannot start.
int run(const std::vector<std::string>& argv, const std::string& log) {
  const pid_t pid = spawn(argv, log, false);
  return pid < 0 ? -1 : waitFor(pid);
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

namespace {

// What outlives a call: libraries loaded and compilations left running. Never destroyed, since threads that
// finish a compilation may still use them while the process exits.
std::mutex& stateMutex() {
  static auto* m = new std::mutex;
  return *m;
}
std::map<std::string, CompiledModelCreate>& loadedLibraries() {
  static auto* m = new std::map<std::string, CompiledModelCreate>;
  return *m;
}
struct Running {
  pid_t pid;
  bool detached; // a `compile-model` process of its own, meant to outlive this one
};
std::vector<Running>& running() {
  static auto* r = new std::vector<Running>;
  return *r;
}
std::string& compilerProgram() {
  static auto* p = new std::string;
  return *p;
}
std::function<bool()>& interruptedHook() {
  static auto* f = new std::function<bool()>;
  return *f;
}

void forget(pid_t pid) {
  const std::lock_guard lock(stateMutex());
  auto& r = running();
  r.erase(std::remove_if(r.begin(), r.end(), [pid](const Running& x) { return x.pid == pid; }), r.end());
}

void stop(const Running& r) {
  kill(r.detached ? -r.pid : r.pid, SIGTERM); // a detached one: its whole group (the compiler with it)
}

/// The cache's files of one key.
struct CacheFiles {
  fs::path dir, source, lib, sum, log;
};
CacheFiles cacheFiles(const fs::path& dir, const std::string& key) {
  return {dir, dir / (key + ".cpp"), dir / (key + ".so"), dir / (key + ".sum"), dir / (key + ".log")};
}

/// The rollviz headers the code includes (#include "..."), and theirs, found in the toolchain's include
/// directories. They belong to a library's identity: a class the code reaches into (EquationSystem,
/// ModelWithField) may change its layout between builds of one version, and a library compiled against the
/// old one would then read the wrong members.
std::string includedHeaders(const Toolchain& t, const std::string& code) {
  std::set<fs::path> seen;
  std::string all;
  std::function<void(const std::string&)> scan = [&](const std::string& text) {
    for (std::size_t at = text.find("#include \""); at != std::string::npos;
         at = text.find("#include \"", at + 1)) {
      const std::size_t from = at + 10, to = text.find('"', from);
      if (to == std::string::npos) break;
      const std::string name = text.substr(from, to - from);
      for (const auto& dir : t.includes) {
        std::error_code ec;
        const fs::path header = fs::path(dir) / name;
        if (!fs::is_regular_file(header, ec)) continue;
        if (seen.insert(header).second) {
          const std::string content = readAll(header);
          all += name + "\n" + content + "\n";
          scan(content);
        }
        break;
      }
    }
  };
  scan(code);
  return all;
}

std::string cacheKey(const Toolchain& t, const std::string& code) {
  // the headers' part, once: every model's code includes the same ones
  static const std::string headers = contentHash(includedHeaders(t, code));
  std::string identity = code + "\n" + ROLLVIZ_ABI_STAMP + "\n" + headers;
  for (const auto& a : compileArguments(t, "SOURCE", "OUT"))
    identity += "\n" + a;
  return contentHash(identity);
}

/// After the compiler wrote `out` successfully: its hash recorded, then renamed into the cache. "" or why
/// not.
std::string install(const CacheFiles& f, const fs::path& out) {
  try {
    writeFileAtomically(f.sum.string(), contentHash(readAll(out)) + "\n");
  } catch (const std::exception& e) {
    return e.what();
  }
  std::error_code ec;
  fs::rename(out, f.lib, ec);
  if (ec) return "cannot rename " + out.string() + ": " + ec.message();
  return intact(f.lib, f.sum) ? "" : "its compiled library changed after it was written";
}

/// The library loaded (once per process); null and `why` when it cannot be.
CompiledModelCreate loadLibrary(const std::string& key, const fs::path& lib, std::string& why) {
  const std::lock_guard lock(stateMutex());
  if (const auto it = loadedLibraries().find(key); it != loadedLibraries().end()) return it->second;
  void* handle = dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    why = dlerror();
    return nullptr;
  }
  const auto stamp = reinterpret_cast<const char* (*)()>(dlsym(handle, kCompiledModelStamp));
  const auto create = reinterpret_cast<CompiledModelCreate>(dlsym(handle, kCompiledModelCreate));
  if (!stamp || !create || std::string(stamp()) != ROLLVIZ_ABI_STAMP) {
    why = lib.string() + " was built for another rollviz";
    return nullptr; // the handle stays open: nothing of it was used
  }
  loadedLibraries().emplace(key, create); // never unloaded: models made by it may outlive every scene
  return create;
}

CompiledModelFactory factoryOf(const std::shared_ptr<const EquationSystem>& system,
                               CompiledModelCreate create) {
  return [system, create](const ParameterValues& p) { return std::unique_ptr<Model>(create(&system, &p)); };
}

std::string seconds(double s) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f", s);
  return text;
}

/// The threads that wait for an in-process compiler left running past the wait budget.
struct Waiters {
  std::mutex mutex;
  std::condition_variable ended;
  int count = 0;
};
Waiters& waiters() {
  static auto* w = new Waiters;
  return *w;
}

/// An in-process compiler still running at exit is stopped (a detached one goes on: it fills the cache), and
/// the threads waiting for them end before the process does: one still cleaning the cache while the process
/// exited crashed LeakSanitizer's exit check.
void stopCompilersAtExit() {
  {
    const std::lock_guard lock(stateMutex());
    for (const Running& r : running())
      if (!r.detached) stop(r);
  }
  Waiters& w = waiters();
  std::unique_lock lock(w.mutex);
  w.ended.wait_for(lock, std::chrono::seconds(10), [&w] { return w.count == 0; });
}

} // namespace

double compileWaitSeconds() {
  const char* v = std::getenv("ROLLVIZ_COMPILE_WAIT");
  char* end = nullptr;
  const double s = v ? std::strtod(v, &end) : 0;
  return v && end != v && *end == '\0' && s >= 0 ? s : 5.0; // "inf" waits for as long as it takes
}

void setModelCompilerProgram(std::string program) {
  const std::lock_guard lock(stateMutex());
  compilerProgram() = std::move(program);
}

void setModelCompilationInterrupted(std::function<bool()> interrupted) {
  const std::lock_guard lock(stateMutex());
  interruptedHook() = std::move(interrupted);
}

void stopModelCompilations() {
  const std::lock_guard lock(stateMutex());
  for (const Running& r : running())
    stop(r);
}

int compileCachedModel(const std::string& sourcePath, std::string& why) {
  const Toolchain& t = toolchain();
  if (t.compiler.empty()) {
    why = t.problem;
    return 1;
  }
  const fs::path source(sourcePath);
  const std::string key = source.stem().string();
  const std::string code = readAll(source);
  // the name is the hash of the code and of this rollviz's compiler line: the library is what the run wants
  if (code.empty() || cacheKey(t, code) != key) {
    why = sourcePath + ": not a model source written by this rollviz into its cache";
    return 2;
  }
  const CacheFiles f = cacheFiles(source.parent_path(), key);
  // one at a time per library (an mpirun's ranks start one each): the others find it done
  const int lock = open((f.dir / (key + ".lock")).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock >= 0) flock(lock, LOCK_EX); // released when the process ends
  if (intact(f.lib, f.sum)) return 0;  // another process was faster
  const fs::path out = f.dir / (key + "." + std::to_string(getpid()) + ".tmp.so");
  std::error_code ec;
  if (run(compileArguments(t, f.source.string(), out.string()), f.log.string()) != 0) {
    fs::remove(out, ec);
    why = "its generated code did not compile (" + f.log.string() + ")";
    return 1;
  }
  why = install(f, out);
  fs::remove(out, ec);
  return why.empty() ? 0 : 1;
}

CompiledModelFactory compiledModel(const std::shared_ptr<const EquationSystem>& system,
                                   const std::function<void(const std::string&)>& note, double waitSeconds) {
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
  const std::string key = cacheKey(t, code);
  std::string why;
  {
    const std::lock_guard lock(stateMutex());
    if (const auto it = loadedLibraries().find(key); it != loadedLibraries().end())
      return factoryOf(system, it->second);
  }
  std::error_code ec;
  fs::create_directories(cacheDirectory(), ec);
  const CacheFiles f = cacheFiles(cacheDirectory(), key);
  if (!intact(f.lib, f.sum)) {
    note("compiling the model '" + id + "' to native code (first use; cached in " + f.dir.string() + ") ...");
    const auto started = std::chrono::steady_clock::now();
    try {
      writeFileAtomically(f.source.string(), code);
    } catch (const std::exception& e) {
      note("model files run interpreted: cannot write the generated code: " + std::string(e.what()));
      return {};
    }
    // a program of its own (`rollviz compile-model`) when there is one: it goes on after this process ends
    // and fills the cache; else the compiler, finished here
    std::string program;
    std::function<bool()> interrupted;
    {
      const std::lock_guard lock(stateMutex());
      program = compilerProgram();
      interrupted = interruptedHook();
    }
    const bool detached = !program.empty();
    static std::atomic<int> made{0}; // two entries of one code in one process compile side by side
    const fs::path out =
        f.dir / (key + "." + std::to_string(getpid()) + "." + std::to_string(made++) + ".tmp.so");
    const pid_t pid =
        detached ? spawn({program, "compile-model", f.source.string()}, "", true)
                 : spawn(compileArguments(t, f.source.string(), out.string()), f.log.string(), false);
    if (pid < 0) {
      note("the model '" + id + "' runs interpreted: " + (detached ? program : t.compiler) +
           " did not start");
      return {};
    }
    {
      const std::lock_guard lock(stateMutex());
      running().push_back({pid, detached});
    }
    // what the compiler leaves behind, once it ended: "" when the library is in the cache, else why not
    const auto finish = [f, out, detached](int status) -> std::string {
      std::error_code ec;
      if (status != 0) {
        if (!detached) fs::remove(out, ec);
        return "its generated code did not compile (" + f.log.string() + "):\n" +
               firstLines(readAll(f.log), 6);
      }
      return detached ? (intact(f.lib, f.sum) ? "" : "its compiled library is not in the cache")
                      : install(f, out);
    };
    // wait for it up to the budget (and not past a Ctrl-C), then go on interpreted while it goes on
    const auto deadline = started + std::chrono::duration<double>(std::min(waitSeconds, 1e9));
    int status = 0;
    bool ended = false;
    while (true) {
      int raw = 0;
      const pid_t done = waitpid(pid, &raw, WNOHANG);
      if (done == pid || (done < 0 && errno != EINTR)) {
        ended = true;
        status = done == pid && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
        break;
      }
      if (interrupted && interrupted()) {
        stop({pid, detached});
        waitFor(pid);
        forget(pid);
        if (!detached) fs::remove(out, ec);
        note("the model '" + id + "' runs interpreted: its compilation was stopped");
        return {};
      }
      if (std::chrono::steady_clock::now() >= deadline) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!ended) {
      note("the model '" + id + "' runs interpreted for now: its compilation takes longer than " +
           "ROLLVIZ_COMPILE_WAIT (" + seconds(waitSeconds) + " s); it goes on " +
           (detached ? "in the background (process " + std::to_string(pid) +
                           ") and fills the cache for the "
                           "next run"
                     : "while this process runs") +
           "; Ctrl-C stops it");
      if (!detached) {
        static std::once_flag registered;
        std::call_once(registered, [] { std::atexit(stopCompilersAtExit); });
      }
      // it ends on its own: the library is installed (here, when not detached) for the next process
      if (!detached) {
        const std::lock_guard lock(waiters().mutex);
        ++waiters().count;
      }
      std::thread([pid, finish, detached] {
        finish(waitFor(pid));
        forget(pid);
        if (detached) return;
        Waiters& w = waiters();
        const std::lock_guard lock(w.mutex);
        --w.count;
        w.ended.notify_all();
      }).detach();
      return {};
    }
    forget(pid);
    if (const std::string failed = finish(status); !failed.empty()) {
      note("the model '" + id + "' runs interpreted: " + failed);
      return {};
    }
    note("compiled the model '" + id + "' in " +
         seconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()) + " s");
  }
  const CompiledModelCreate create = loadLibrary(key, f.lib, why);
  if (!create) {
    note("the model '" + id + "' runs interpreted: " + why);
    return {};
  }
  return factoryOf(system, create);
}

} // namespace rv
