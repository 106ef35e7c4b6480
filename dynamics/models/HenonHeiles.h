// HenonHeiles.h -- the Henon-Heiles Hamiltonian, a reference flow for the map tools:
// H = (px^2 + py^2)/2 + (x^2 + y^2)/2 + x^2 y - y^3/3; section x = 0 crossed with px > 0, map coordinates (y,
// py). Reference: M. Henon, C. Heiles, The applicability of the third integral of motion, Astron. J. 69
// (1964) 73.
#pragma once
#include "dynamics/core/ModelWithField.h"

namespace rv {

class HenonHeiles final : public ModelWithField<HenonHeiles, 4> {
public:
  explicit HenonHeiles(const ParameterValues& params);
  static const ModelInfo& staticInfo();
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  template <class S> void field(const Vec<S>& s, Vec<S>& ds) const {
    const S& x = s[0];
    const S& y = s[1];
    ds[0] = s[2];
    ds[1] = s[3];
    ds[2] = -x - 2.0 * x * y;
    ds[3] = -y - x * x + y * y;
  }
  Eigen::VectorXd integrals(const double* s) const override;
  /// Hamiltonian: the Liouville measure, density 1.
  double measureDensity(const double*) const override { return 1.0; }
  /// (y, py) on x = 0, px > 0 from the energy.
  Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                               const std::string& context) const override;
  static double hamiltonian(const double* s);
};

// compiled once, in HenonHeiles.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<HenonHeiles, 4>;

} // namespace rv
