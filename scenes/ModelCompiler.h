// ModelCompiler.h -- the fast path of model files: the C++ generated from a checked model (ModelCode.h)
// compiled by the compiler that built rollviz into a shared library, cached by the hash of its source and of
// the toolchain in ~/.cache/rollviz/models (ROLLVIZ_MODEL_CACHE overrides), checked against the hash recorded
// beside it before it is loaded, and loaded. No shell is involved: the compiler is spawned with its
// arguments. Without a compiler every model file runs interpreted, which is said once. A run waits for a
// first compilation only up to a budget (compileWaitSeconds) and goes on interpreted meanwhile.
#pragma once
#include "dynamics/models/EquationModel.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <string>

namespace rv {

/// Makes compiled models of one system.
using CompiledModelFactory = std::function<std::unique_ptr<Model>(const ParameterValues&)>;

/// Whether model files can be compiled here; `why` says how, or why not.
bool modelCompilationAvailable(std::string* why = nullptr);

/// The compiled models of `system`: from the cache, or compiled now (`note` hears "compiling ..." first and
/// how long it took after). Returns null when compilation is unavailable or fails; `note` then hears why, and
/// the caller goes on interpreted. A compilation that takes longer than `waitSeconds` is left running (`note`
/// says so; null is returned): by `rollviz compile-model` in a process of its own when a compiler program is
/// set (setModelCompilerProgram), which fills the cache even after this process ends; else by the compiler
/// alone, finished here while the process lives and stopped when it exits.
CompiledModelFactory compiledModel(const std::shared_ptr<const EquationSystem>& system,
                                   const std::function<void(const std::string&)>& note,
                                   double waitSeconds = std::numeric_limits<double>::infinity());

/// How long a run waits for a model's first compilation before it goes on interpreted: ROLLVIZ_COMPILE_WAIT
/// seconds (default 5; "inf" waits for as long as it takes).
double compileWaitSeconds();

/// The program that compiles a model detached from the process that wants it, as `PROGRAM compile-model
/// SOURCE` (the command line sets its own executable); empty (the default): the compiler is run in-process.
void setModelCompilerProgram(std::string program);

/// Polled while a compilation is waited for: true stops the compiler (Ctrl-C) and goes on interpreted.
void setModelCompilationInterrupted(std::function<bool()> interrupted);

/// Stops every compilation this process started that still runs (on Ctrl-C; detached ones too).
void stopModelCompilations();

/// What `rollviz compile-model SOURCE` does: compiles a source that compiledModel wrote into the cache,
/// records the library's hash and renames it into place. 0 done (or already there); 1 the compilation failed,
/// 2 not such a source, with `why`.
int compileCachedModel(const std::string& source, std::string& why);

/// Whether model files are compiled on first use: ROLLVIZ_COMPILE_MODELS=0 turns it off (interpreted only).
bool compileModelsByDefault();

/// The largest generated source compiled (ROLLVIZ_COMPILE_MAX_BYTES, default 1 MB; a model's is ~20 kB): a
/// larger one runs interpreted, which starts at once, rather than wait minutes on the compiler.
std::size_t largestCompiledSource();

} // namespace rv
