// Errors.h -- the two kinds of failure every front end maps to an exit status.
#pragma once
#include <stdexcept>
#include <string>

namespace rv {

/// Bad input: an unknown name, a value out of range, a malformed file. Front ends exit with status 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A computation that did not succeed (blow-up, no convergence, step underflow). Exit status 1.
struct ComputationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

} // namespace rv
