// ModelCompiler.h -- the fast path of model files: the C++ generated from a checked model (ModelCode.h)
// compiled by the compiler that built rollviz into a shared library, cached by the hash of its source and of
// the toolchain in ~/.cache/rollviz/models (ROLLVIZ_MODEL_CACHE overrides), checked against the hash recorded
// beside it before it is loaded, and loaded. No shell is involved: the compiler is spawned with its
// arguments. Without a compiler every model file runs interpreted, which is said once.
#pragma once
#include "dynamics/models/EquationModel.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace rv {

/// Makes compiled models of one system.
using CompiledModelFactory = std::function<std::unique_ptr<Model>(const ParameterValues&)>;

/// Whether model files can be compiled here; `why` says how, or why not.
bool modelCompilationAvailable(std::string* why = nullptr);

/// The compiled models of `system`: from the cache, or compiled now (`note` hears "compiling ..." first and
/// how long it took after). Returns null when compilation is unavailable or fails; `note` then hears why, and
/// the caller goes on interpreted.
CompiledModelFactory compiledModel(const std::shared_ptr<const EquationSystem>& system,
                                   const std::function<void(const std::string&)>& note);

/// Whether model files are compiled on first use: ROLLVIZ_COMPILE_MODELS=0 turns it off (interpreted only).
bool compileModelsByDefault();

/// The largest generated source compiled (ROLLVIZ_COMPILE_MAX_BYTES, default 1 MB; a model's is ~20 kB): a
/// larger one runs interpreted, which starts at once, rather than wait minutes on the compiler.
std::size_t largestCompiledSource();

} // namespace rv
