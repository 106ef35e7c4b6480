// ModelCode.h -- C++ generated from a checked model (EquationSystem): the right-hand side written out as
// straight-line code in a ModelWithField, so that a model file runs at the speed of a built-in model --
// Eigen's forward-mode Jacobians and tangent vectors with sizes fixed at compile time, the fused RK4 of
// Lyapunov spectra, the Taylor recording -- while its observables, integrals, completions and pose stay
// interpreted. Only the parsed program reaches the code: registers get generated names (r0, r1, ...), numbers
// are printed in hexadecimal (exact), parameters are read from an array; no text of the file is copied into
// it.
#pragma once
#include "dynamics/models/EquationModel.h"

#include <string>

namespace rv {

/// The exported symbols of a compiled model library.
inline constexpr const char* kCompiledModelCreate = "rollviz_compiled_model_create";
inline constexpr const char* kCompiledModelStamp = "rollviz_compiled_model_stamp";

/// What a compiled model library's create function is: a new model of `system` at `params` (owned by the
/// caller), its field compiled, the rest delegated to the interpreted model.
using CompiledModelCreate = Model* (*)(const std::shared_ptr<const EquationSystem>* system,
                                       const ParameterValues* params);

/// The source of a compiled model library for `system`.
std::string modelCode(const EquationSystem& system);

} // namespace rv
