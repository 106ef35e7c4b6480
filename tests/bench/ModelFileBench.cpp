// Models written as equations (examples/models) and rolling bodies described by their geometry
// (examples/rolling, equations derived by rollviz) beside the built-in model they restate, in one run:
// right-hand sides, Jacobians, an adaptive integration and a Lyapunov spectrum. Model files run as their
// native code when ROLLVIZ_COMPILE_MODELS allows (the default), interpreted with ROLLVIZ_COMPILE_MODELS=0.
// Report the ratios (<Case>/file and <Case>/rolling over <Case>/builtin), and the time to read, check and
// build a model file.
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/Lyapunov.h"
#include "scenes/ModelFile.h"

#include <benchmark/benchmark.h>
#include <cstdlib>
#include <fstream>

namespace {

using namespace rv;

std::string examples(const std::string& file, const char* folder = "models") {
  const char* root = std::getenv("ROLLVIZ_SOURCE_DIR");
  return std::string(root ? root : ROLLVIZ_SOURCE_DIR) + "/examples/" + folder + "/" + file;
}

/// Where a benchmarked model comes from.
enum class Source { Builtin, File, Rolling };

const ModelEntry& entryOf(const std::string& id, Source from) {
  switch (from) {
  case Source::File:
    return modelFileEntry(examples(id + ".json"));
  case Source::Rolling:
    return modelFileEntry(examples(id + ".json", "rolling"));
  case Source::Builtin:
    break;
  }
  return ModelRegistry::global().get(id);
}

std::unique_ptr<Model> make(const std::string& id, Source file) {
  const ModelEntry& e = entryOf(id, file);
  return e.create(ParameterValues(e.info->parameters));
}

Eigen::VectorXd startOf(const Model& m) {
  if (m.info().stateNames[0] == "x") return Eigen::Vector3d(1, 1, 1);
  return m.stateFromNamed(
      {{"M1", 0.2}, {"M2", -0.3}, {"M3", 0.4}, {"gamma1", 0.1}, {"gamma2", 0.2}, {"gamma3", 1}}, "bench");
}

std::unique_ptr<Integrator> verner(double tolerance) {
  const IntegratorEntry& e = IntegratorRegistry::global().get("verner9");
  ParameterValues p(*e.parameters);
  p.set("tolerance", tolerance);
  return e.create(p);
}

void RightHandSide(benchmark::State& state, const std::string& id, Source file) {
  const auto m = make(id, file);
  const Eigen::VectorXd x = startOf(*m);
  Eigen::VectorXd dx(x.size());
  for (auto _ : state) {
    m->rhs(x.data(), dx.data());
    benchmark::DoNotOptimize(dx.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void Jacobian(benchmark::State& state, const std::string& id, Source file) {
  const auto m = make(id, file);
  const Eigen::VectorXd x = startOf(*m);
  Eigen::MatrixXd J(x.size(), x.size());
  for (auto _ : state) {
    m->jacobian(x.data(), J.data());
    benchmark::DoNotOptimize(J.data());
  }
}

void Integrate(benchmark::State& state, const std::string& id, Source file) {
  const auto m = make(id, file);
  const Eigen::VectorXd x = startOf(*m);
  for (auto _ : state) {
    auto integ = verner(1e-12);
    integ->start(*m, 0, x);
    while (integ->time() < 20)
      integ->step();
    benchmark::DoNotOptimize(integ->state().data());
  }
}

void Lyapunov(benchmark::State& state, const std::string& id, Source file) {
  const auto m = make(id, file);
  const Eigen::VectorXd x = startOf(*m);
  LyapunovSettings s;
  s.maxTime = 20;
  for (auto _ : state) {
    const auto r = lyapunovExponents(
        *m, [] { return verner(1e-10); }, x, s);
    benchmark::DoNotOptimize(r.last.exponents.data());
  }
}

void ReadModelFile(benchmark::State& state) {
  const std::string path = examples("chaplygin_ball.json");
  for (auto _ : state) {
    // a fresh id each time, so nothing comes from the cache of loaded files
    nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
    j["id"] = "bench_" + std::to_string(state.iterations());
    benchmark::DoNotOptimize(&modelEntryFromJson(j, "bench"));
  }
}

} // namespace

#define RV_PAIR(FN, ID)                                                                                      \
  BENCHMARK_CAPTURE(FN, ID##_builtin, std::string(#ID), Source::Builtin)->Name(#FN "/" #ID "/builtin");      \
  BENCHMARK_CAPTURE(FN, ID##_file, std::string(#ID), Source::File)->Name(#FN "/" #ID "/file")
#define RV_ROLLING(FN, ID)                                                                                   \
  BENCHMARK_CAPTURE(FN, ID##_rolling, std::string(#ID), Source::Rolling)->Name(#FN "/" #ID "/rolling")
RV_PAIR(RightHandSide, lorenz);
RV_PAIR(RightHandSide, chaplygin_ball);
RV_PAIR(Jacobian, lorenz);
RV_PAIR(Jacobian, chaplygin_ball);
RV_PAIR(Integrate, lorenz)->Unit(benchmark::kMillisecond);
RV_PAIR(Integrate, chaplygin_ball)->Unit(benchmark::kMillisecond);
RV_PAIR(Lyapunov, lorenz)->Unit(benchmark::kMillisecond);
RV_PAIR(Lyapunov, chaplygin_ball)->Unit(benchmark::kMillisecond);
RV_PAIR(RightHandSide, ellipsoid_on_plane);
RV_ROLLING(RightHandSide, ellipsoid_on_plane);
RV_ROLLING(RightHandSide, chaplygin_ball);
RV_PAIR(Jacobian, ellipsoid_on_plane);
RV_ROLLING(Jacobian, ellipsoid_on_plane);
RV_ROLLING(Jacobian, chaplygin_ball);
RV_PAIR(Integrate, ellipsoid_on_plane)->Unit(benchmark::kMillisecond);
RV_ROLLING(Integrate, ellipsoid_on_plane)->Unit(benchmark::kMillisecond);
RV_ROLLING(Integrate, chaplygin_ball)->Unit(benchmark::kMillisecond);
RV_PAIR(Lyapunov, ellipsoid_on_plane)->Unit(benchmark::kMillisecond);
RV_ROLLING(Lyapunov, ellipsoid_on_plane)->Unit(benchmark::kMillisecond);
RV_ROLLING(Lyapunov, chaplygin_ball)->Unit(benchmark::kMillisecond);
BENCHMARK(ReadModelFile)->Unit(benchmark::kMillisecond);
