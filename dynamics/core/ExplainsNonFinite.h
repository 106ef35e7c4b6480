// ExplainsNonFinite.h -- what a model that can name the expression behind a blow-up adds to Model (models
// written as equations do): the integrators ask for it when a step stops being finite.
#pragma once
#include <string>

namespace rv {

/// A capability of some models, found by dynamic_cast from a Model.
class ExplainsNonFinite {
public:
  virtual ~ExplainsNonFinite() = default;
  /// Why the right-hand side is not finite at x (or was not, at the last evaluation that failed on this
  /// thread): "MODEL: WHERE: 'OP' of A B gave VALUE"; "" when it cannot say.
  virtual std::string nonFiniteCause(const double* x) const = 0;
};

} // namespace rv
