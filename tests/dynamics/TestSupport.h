// TestSupport.h -- helpers shared by the numeric tests.
#pragma once
#include "dynamics/core/Model.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Everhart.h"

#include <cstdlib>
#include <memory>
#include <random>

namespace rv::test {

/// Multiplies every numeric tolerance (ROLLVIZ_TOLERANCE_SCALE, default 1).
inline double tol(double t) {
  const char* s = std::getenv("ROLLVIZ_TOLERANCE_SCALE");
  return t * (s ? std::atof(s) : 1.0);
}

/// Everhart's 15th order with 12 iterations at the fixed step h: the maps' integrator in the tool tests.
inline IntegratorFactory everhartFactory(double h = 0.05) {
  return [h] { return std::make_unique<Everhart>(h, 15, 12); };
}

/// A model by id with some parameters changed from their defaults.
inline std::unique_ptr<Model> makeModel(const std::string& id,
                                        std::initializer_list<std::pair<const char*, double>> set = {}) {
  const ModelEntry& e = ModelRegistry::global().get(id);
  ParameterValues p(e.info->parameters);
  for (const auto& [k, v] : set)
    p.set(k, v);
  return e.create(p);
}

/// div(rho f) at x by central differences (step h), over all components; rho = 1 when !withDensity.
inline double divergenceOfDensityFlow(const Model& m, const Eigen::VectorXd& x, double h = 1e-6,
                                      bool withDensity = true) {
  const auto rho = [&](const Eigen::VectorXd& y) { return withDensity ? m.measureDensity(y.data()) : 1.0; };
  const int n = m.dimension();
  Eigen::VectorXd xp = x, xm = x, fp(n), fm(n);
  double div = 0;
  for (int i = 0; i < n; ++i) {
    xp = x, xm = x;
    xp[i] += h, xm[i] -= h;
    m.rhs(xp.data(), fp.data());
    m.rhs(xm.data(), fm.data());
    div += (rho(xp) * fp[i] - rho(xm) * fm[i]) / (2 * h);
  }
  return div;
}

} // namespace rv::test
