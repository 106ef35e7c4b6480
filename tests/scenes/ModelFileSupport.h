// ModelFileSupport.h -- what the model-file tests share: the examples folder, a built-in model paired with
// the file that restates it, and comparisons of their fields and trajectories.
#pragma once
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Integrator.h"
#include "scenes/ModelFile.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cstdlib>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <string>

namespace rv::testing_model_files {

/// A file of the project's examples folder (examples/models by default).
inline std::string examples(const std::string& file, const std::string& folder = "models") {
  const char* root = std::getenv("ROLLVIZ_SOURCE_DIR");
  return std::string(root ? root : ".") + "/examples/" + folder + "/" + file;
}

/// What loading `model`, as if read from the file `source`, reports as bad input; "" when it loads.
inline std::string modelFileError(const nlohmann::json& model, const std::string& source = "m.json") {
  try {
    modelEntryFromJson(model, source);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

struct Pair {
  std::unique_ptr<Model> builtin, file;
};

/// A built-in model and the model file restating it, both with the parameters `set`; `file` is a path under
/// examples/models unless it holds a '/' (then under examples/).
inline Pair pairOf(const std::string& id, const std::string& file,
                   const std::map<std::string, double>& set = {}) {
  const ModelEntry& b = ModelRegistry::global().get(id);
  const ModelEntry& f =
      modelFileEntry(file.find('/') == std::string::npos
                         ? examples(file)
                         : examples(file.substr(file.find('/') + 1), file.substr(0, file.find('/'))));
  ParameterValues pb(b.info->parameters), pf(f.info->parameters);
  for (const auto& [k, v] : set) {
    pb.set(k, v);
    pf.set(k, v);
  }
  return {b.create(pb), f.create(pf)};
}

inline std::unique_ptr<Integrator> verner(double tolerance) {
  const IntegratorEntry& e = IntegratorRegistry::global().get("verner9");
  ParameterValues p(*e.parameters);
  p.set("tolerance", tolerance);
  return e.create(p);
}

/// The largest difference of the states over [0, T], sampled at every unit of time.
inline double trajectoryDifference(const Model& a, const Model& b, const Eigen::VectorXd& x0, double T) {
  auto ia = verner(1e-13), ib = verner(1e-13);
  ia->start(a, 0, x0);
  ib->start(b, 0, x0);
  double worst = 0;
  Eigen::VectorXd ya(x0.size()), yb(x0.size());
  for (double t = 1; t <= T; t += 1) {
    while (ia->time() < t)
      ia->step();
    while (ib->time() < t)
      ib->step();
    ia->interpolate(t, ya);
    ib->interpolate(t, yb);
    worst = std::max(worst, (ya - yb).cwiseAbs().maxCoeff());
  }
  return worst;
}

/// Field, Jacobian (exact: forward mode against Eigen's AutoDiff of the built-in), tangent products,
/// integrals and measure at a state.
inline void expectSameField(const Model& a, const Model& b, const Eigen::VectorXd& x) {
  const int n = a.dimension();
  ASSERT_EQ(n, b.dimension());
  ASSERT_EQ(a.info().coreDimension, b.info().coreDimension);
  Eigen::VectorXd fa(n), fb(n);
  a.rhs(x.data(), fa.data());
  b.rhs(x.data(), fb.data());
  EXPECT_LT((fa - fb).cwiseAbs().maxCoeff(), 1e-13 * (1 + fa.cwiseAbs().maxCoeff())) << fa.transpose() << "\n"
                                                                                     << fb.transpose();
  Eigen::MatrixXd ja(n, n), jb(n, n);
  a.jacobian(x.data(), ja.data());
  b.jacobian(x.data(), jb.data());
  EXPECT_LT((ja - jb).cwiseAbs().maxCoeff(), 1e-12 * (1 + ja.cwiseAbs().maxCoeff()));
  const int m = a.info().coreDimension, k = 2;
  Eigen::MatrixXd V = Eigen::MatrixXd::Random(m, k), dVa(m, k), dVb(m, k);
  a.tangentRhs(x.data(), V.data(), k, fa.data(), dVa.data());
  b.tangentRhs(x.data(), V.data(), k, fb.data(), dVb.data());
  EXPECT_LT((dVa - dVb).cwiseAbs().maxCoeff(), 1e-12 * (1 + dVa.cwiseAbs().maxCoeff()));
  const Eigen::VectorXd ia = a.integrals(x.data()), ib = b.integrals(x.data());
  ASSERT_EQ(ia.size(), ib.size());
  if (ia.size() > 0) {
    EXPECT_LT((ia - ib).cwiseAbs().maxCoeff(), 1e-13 * (1 + ia.cwiseAbs().maxCoeff()));
  }
  EXPECT_NEAR(a.measureDensity(x.data()), b.measureDensity(x.data()), 1e-13);
  for (const auto& o : a.observables()) { // every observable the file also has agrees
    const int i = b.findObservable(o.id);
    if (i < 0) continue;
    const double va = o.value(0.5, x.data()),
                 vb = b.observables()[static_cast<std::size_t>(i)].value(0.5, x.data());
    EXPECT_NEAR(va, vb, 1e-12 * (1 + std::abs(va))) << o.id;
  }
}

inline Eigen::VectorXd named(const Model& m, const std::map<std::string, double>& values) {
  return m.stateFromNamed(values, "initial.state");
}

} // namespace rv::testing_model_files
