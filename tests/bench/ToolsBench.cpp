// Tool benchmarks: the Poincare map's cost against plain integration of the same trajectory, crossings per
// second, Lyapunov spectra of Lorenz (tangent and perturbed modes) beside Boost.Odeint's chaotic_system
// approach (the variational equations integrated with runge_kutta4 and a QR every interval), and job
// throughput on 1 and 2 threads.
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/PoincareTask.h"
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/tools/PoincareMap.h"

#include <Eigen/QR>
#include <array>
#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <thread>

namespace {

using namespace rv;

std::unique_ptr<Model> make(const std::string& id,
                            std::initializer_list<std::pair<const char*, double>> set = {}) {
  const auto& e = ModelRegistry::builtin().get(id);
  ParameterValues p(e.info->parameters);
  for (const auto& [k, v] : set)
    p.set(k, v);
  return e.create(p);
}

// chaplygin_ball over t = 200 (Everhart 15, h = 0.1): plain, and with every crossing of g = 0 located
void PoincareCost(benchmark::State& state, bool withSection) {
  const auto m = make("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.5, 0.2}, {}, "bench");
  long crossings = 0;
  for (auto _ : state) {
    auto e = std::make_unique<Everhart>(0.1, 15, 12);
    e->start(*m, 0, x0);
    if (withSection) {
      SectionSettings s;
      s.maxTime = 200;
      PoincareMap map(*m, std::move(e), s);
      while (map.next())
        ++crossings;
    } else {
      while (e->time() < 200)
        e->step();
    }
  }
  if (withSection)
    state.counters["crossings_per_second"] =
        benchmark::Counter(static_cast<double>(crossings), benchmark::Counter::kIsRate);
}

LyapunovSettings lorenzSettings(LyapunovSettings::Mode mode) {
  LyapunovSettings s;
  s.mode = mode;
  s.interval = mode == LyapunovSettings::Mode::Tangent ? 0.5 : 0.1;
  s.maxTime = 2000;
  return s;
}

void LorenzSpectrum(benchmark::State& state, LyapunovSettings::Mode mode) {
  const auto m = make("lorenz");
  Eigen::VectorXd x0(3);
  x0 << 1, 1, 20;
  double l1 = 0;
  for (auto _ : state) {
    const auto r = lyapunovExponents(
        *m, [] { return std::make_unique<Rk4>(0.005); }, x0, lorenzSettings(mode));
    l1 = r.last.exponents[0];
  }
  state.counters["lambda1"] = l1;
}

// Boost.Odeint's chaotic_system example: x and three tangent vectors as one 12-component state, runge_kutta4
using State12 = std::array<double, 12>;
void LorenzSpectrum_odeint(benchmark::State& state) {
  const double sigma = 10, rho = 28, beta = 8.0 / 3.0;
  auto sys = [&](const State12& x, State12& dx, double) {
    dx[0] = sigma * (x[1] - x[0]);
    dx[1] = rho * x[0] - x[1] - x[0] * x[2];
    dx[2] = -beta * x[2] + x[0] * x[1];
    for (int j = 0; j < 3; ++j) {
      const double* v = &x[3 + 3 * j];
      double* dv = &dx[3 + 3 * j];
      dv[0] = sigma * (v[1] - v[0]);
      dv[1] = (rho - x[2]) * v[0] - v[1] - x[0] * v[2];
      dv[2] = x[1] * v[0] + x[0] * v[1] - beta * v[2];
    }
  };
  double l1 = 0;
  for (auto _ : state) {
    State12 x{1, 1, 20, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    boost::numeric::odeint::runge_kutta4<State12> rk4;
    double t = 0, logs[3] = {0, 0, 0};
    for (int k = 0; k < 4000; ++k) { // 4000 intervals of 0.5 = t 2000
      for (int i = 0; i < 100; ++i, t += 0.005)
        rk4.do_step(sys, x, t, 0.005);
      Eigen::Map<Eigen::Matrix3d> V(&x[3]);
      Eigen::HouseholderQR<Eigen::Matrix3d> qr(V);
      const Eigen::Matrix3d R = qr.matrixQR().triangularView<Eigen::Upper>();
      Eigen::Matrix3d Q = qr.householderQ();
      for (int j = 0; j < 3; ++j) {
        logs[j] += std::log(std::abs(R(j, j)));
        if (R(j, j) < 0) Q.col(j) = -Q.col(j);
      }
      V = Q;
    }
    l1 = logs[0] / t;
  }
  state.counters["lambda1"] = l1;
}

// points per second from `jobs` Poincare jobs on Henon-Heiles running side by side for 1 s
void JobThroughput(benchmark::State& state) {
  const int jobs = static_cast<int>(state.range(0));
  long points = 0;
  for (auto _ : state) {
    JobTree tree;
    std::vector<PoincareTask*> tasks;
    for (int j = 0; j < jobs; ++j) {
      RunSpec s(ModelRegistry::builtin().get("henon_heiles"), IntegratorRegistry::builtin().get("everhart"));
      s.integratorParameters.set("step", 0.05);
      s.initialState = s.makeModel()->stateFromMap({0.1 + 0.01 * j, 0.1}, {}, "bench");
      auto task = std::make_unique<PoincareTask>(s, SectionSettings{});
      tasks.push_back(task.get());
      tree.add(std::move(task)).start();
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
    tree.stopAll();
    for (auto* t : tasks)
      points += t->points().total();
  }
  state.counters["points_per_second"] =
      benchmark::Counter(static_cast<double>(points), benchmark::Counter::kIsRate);
}

} // namespace

BENCHMARK_CAPTURE(PoincareCost, plain, false)
    ->Name("PoincareCost/plain_integration")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(PoincareCost, section, true)
    ->Name("PoincareCost/with_section")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(LorenzSpectrum, tangent, LyapunovSettings::Mode::Tangent)
    ->Name("LorenzSpectrum/rollviz_tangent")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(LorenzSpectrum, perturbed, LyapunovSettings::Mode::Perturbed)
    ->Name("LorenzSpectrum/rollviz_perturbed")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(LorenzSpectrum_odeint)->Name("LorenzSpectrum/odeint")->Unit(benchmark::kMillisecond);
BENCHMARK(JobThroughput)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
