// Tool benchmarks: the Poincare map's cost against plain integration of the same trajectory, crossings per
// second, Lyapunov spectra of Lorenz (tangent and perturbed modes) beside Boost.Odeint's chaotic_system
// approach (the variational equations integrated with runge_kutta4 and a QR every interval), the Chaplygin
// ball's spectrum, MEGNO orbits per second, and job throughput on 1 and 2 threads.
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/PoincareTask.h"
#include "dynamics/tools/FixedPoint.h"
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/tools/MapGrid.h"
#include "dynamics/tools/Megno.h"
#include "dynamics/tools/PoincareMap.h"
#include "dynamics/tools/TangentSystem.h"

#include "tests/dynamics/TestSupport.h"
#include <Eigen/QR>
#include <array>

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <thread>
#include <type_traits>

namespace {

using namespace rv;

// a fixed point to |Map(x) - x| <= 1e-10 from a guess ~0.3 away: finite differences against variational
// derivatives; counters give the map evaluations (a variational evaluation integrates 2-3 tangent vectors
// too)
void FixedPointSearch(benchmark::State& state, const char* which, DerivativeMethod method) {
  const bool ball = std::string(which) == "chaplygin_ball";
  const auto m = ball ? test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}})
                      : test::makeModel("ellipsoid_on_plane", {{"I1", 1.0},
                                                               {"I2", 1.4},
                                                               {"I3", 1.9},
                                                               {"g", 0.0},
                                                               {"b1", 1.0},
                                                               {"b2", 1.0},
                                                               {"b3", 1.0},
                                                               {"a3", 0.0},
                                                               {"psi", 0.0},
                                                               {"energy", 0.5}});
  const ReturnMap map(
      *m, [] { return std::make_unique<Everhart>(0.02, 15, 12); }, SectionSettings{});
  FixedPointSettings s;
  s.accuracy = 1e-10;
  s.derivatives.method = method;
  s.section2D = !ball; // the balanced ball's 3D map has a line of fixed points (H/G is conserved)
  const Eigen::VectorXd guess =
      ball ? Eigen::VectorXd(Eigen::Vector2d(4.2, 0.2)) : Eigen::VectorXd(Eigen::Vector3d(4.5, 0.0, 0.215));
  long evaluations = 0, searches = 0;
  for (auto _ : state) {
    const auto r = findFixedPoint(map, guess, s);
    evaluations += r.evaluations, ++searches;
  }
  state.counters["map_evaluations"] = static_cast<double>(evaluations) / static_cast<double>(searches);
}
BENCHMARK_CAPTURE(FixedPointSearch, chaplygin_ball_differences, "chaplygin_ball",
                  DerivativeMethod::FiniteDifferences)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(FixedPointSearch, chaplygin_ball_variational, "chaplygin_ball",
                  DerivativeMethod::Variational)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(FixedPointSearch, ellipsoid_on_plane_differences, "ellipsoid_on_plane",
                  DerivativeMethod::FiniteDifferences)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(FixedPointSearch, ellipsoid_on_plane_variational, "ellipsoid_on_plane",
                  DerivativeMethod::Variational)
    ->Unit(benchmark::kMillisecond);

// the |Map(x) - x| surface of Henon-Heiles (61 x 61 Poincare returns) on 1 and 2 threads
void SurfaceGrid(benchmark::State& state) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const ReturnMap map(
      *m, [] { return std::make_unique<Everhart>(0.05, 15, 12); }, SectionSettings{});
  GridSettings g;
  g.axes[0] = {-0.3, 0.3, 0.01};
  g.axes[1] = {-0.3, 0.3, 0.01};
  g.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    MapGrid grid(map, MapGrid::Kind::Surface, g);
    grid.run();
    benchmark::DoNotOptimize(grid.result().values.data());
  }
  state.counters["points_per_second"] =
      benchmark::Counter(61.0 * 61.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(SurfaceGrid)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// chaplygin_ball over t = 200 (Everhart 15, h = 0.1): plain, and with every crossing of g = 0 located
void PoincareCost(benchmark::State& state, bool withSection) {
  const auto m = test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
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

// adaptive: the interval adapts to the vectors' spread (the default, 1e3: Lorenz's intervals go to 0.25,
// bench README); otherwise every interval is 0.5, as the peer's
LyapunovSettings lorenzSettings(LyapunovSettings::Mode mode, bool adaptive = false) {
  LyapunovSettings s;
  s.mode = mode;
  s.interval = mode == LyapunovSettings::Mode::Tangent ? 0.5 : 0.1;
  if (!adaptive) s.spread = 0;
  s.maxTime = 2000;
  return s;
}

void LorenzSpectrum(benchmark::State& state, LyapunovSettings::Mode mode, bool adaptive = false) {
  const auto m = test::makeModel("lorenz");
  Eigen::VectorXd x0(3);
  x0 << 1, 1, 20;
  double l1 = 0;
  for (auto _ : state) {
    const auto r = lyapunovExponents(
        *m, [] { return std::make_unique<Rk4>(0.005); }, x0, lorenzSettings(mode, adaptive));
    l1 = r.last.exponents[0];
  }
  state.counters["lambda1"] = l1;
}

// the peers' orthonormalisation (as odeint's chaotic_system example): V = QR with R's diagonal made positive,
// log |R_jj| added to logs[j]
template <class Tangents> void orthonormalizePeer(Tangents&& V, double* logs) {
  using Square = typename std::decay_t<Tangents>::PlainObject;
  Eigen::HouseholderQR<Square> qr(V);
  Square Q = qr.householderQ();
  for (Eigen::Index j = 0; j < Q.cols(); ++j) {
    const double r = qr.matrixQR()(j, j);
    logs[j] += std::log(std::abs(r));
    if (r < 0) Q.col(j) = -Q.col(j);
  }
  V = Q;
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
      orthonormalizePeer(Eigen::Map<Eigen::Matrix3d>(&x[3]), logs);
    }
    l1 = logs[0] / t;
  }
  state.counters["lambda1"] = l1;
}

// the Chaplygin ball's full spectrum: six tangent vectors beside the 16-component state (52 components), rk4
// h = 0.01 to t = 200, a QR every unit of time. rollviz takes the fused path (the model's tangent equations
// compiled into the steps); the peer steps the same variational system (TangentSystem, the generic path with
// a virtual right-hand side) with Boost.Odeint's runge_kutta4 and the same QR
const Eigen::VectorXd& chaplyginStart(const Model& m) {
  static const Eigen::VectorXd x0 = m.stateFromMap({0.5, 0.2}, {}, "bench");
  return x0;
}

void ChaplyginSpectrum(benchmark::State& state) {
  const auto m = test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
  LyapunovSettings s;
  s.interval = 1;
  s.maxTime = 200;
  double l1 = 0;
  for (auto _ : state)
    l1 = lyapunovExponents(
             *m, [] { return std::make_unique<Rk4>(0.01); }, chaplyginStart(*m), s)
             .last.exponents[0];
  state.counters["lambda1"] = l1;
  state.counters["spectra_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void ChaplyginSpectrum_odeint(benchmark::State& state) {
  const auto m = test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
  const TangentSystem tangent(*m, 6);
  const int n = m->dimension();
  using State = std::vector<double>;
  const auto sys = [&](const State& x, State& dx, double) { tangent.rhs(x.data(), dx.data()); };
  double l1 = 0;
  for (auto _ : state) {
    State x(static_cast<std::size_t>(tangent.dimension()), 0.0);
    Eigen::Map<Eigen::VectorXd>(x.data(), n) = chaplyginStart(*m);
    Eigen::Map<Eigen::MatrixXd> V(x.data() + n, 6, 6);
    V.setIdentity();
    boost::numeric::odeint::runge_kutta4<State> rk4;
    double t = 0, logs[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 0; k < 200; ++k) {
      for (int i = 0; i < 100; ++i, t += 0.01)
        rk4.do_step(sys, x, t, 0.01);
      orthonormalizePeer(V, logs);
    }
    l1 = logs[0] / t;
  }
  state.counters["lambda1"] = l1;
  state.counters["spectra_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// MEGNO of one orbit as the Henon-Heiles sweep computes it (scenes/sweeps/henon_heiles_megno.json: E = 1/8,
// everhart 15, h = 0.05, t = 400), on a torus and in the chaotic sea
void MegnoHenonHeiles(benchmark::State& state, double x, double y) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const Eigen::VectorXd x0 = m->stateFromMap({x, y}, {}, "bench");
  MegnoSettings s;
  s.maxTime = 400;
  double value = 0;
  for (auto _ : state)
    value = megno(
                *m, [] { return std::make_unique<Everhart>(0.05, 15, 12); }, x0, s)
                .last.megno;
  state.counters["megno"] = value;
  state.counters["orbits_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// points per second from `jobs` Poincare jobs on Henon-Heiles running side by side for 1 s
void JobThroughput(benchmark::State& state) {
  const int jobs = static_cast<int>(state.range(0));
  long points = 0;
  for (auto _ : state) {
    JobTree tree;
    std::vector<PoincareTask*> tasks;
    for (int j = 0; j < jobs; ++j) {
      RunSpec s(ModelRegistry::global().get("henon_heiles"), IntegratorRegistry::global().get("everhart"));
      s.integratorParameters.set("step", 0.05);
      s.initialState = s.makeModel()->stateFromMap({0.1 + 0.01 * j, 0.1}, {}, "bench");
      auto task = std::make_unique<PoincareTask>(s, SectionSettings{.maxPoints = 0});
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
BENCHMARK_CAPTURE(LorenzSpectrum, tangent_adaptive, LyapunovSettings::Mode::Tangent, true)
    ->Name("LorenzSpectrum/rollviz_tangent_default_spread")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(LorenzSpectrum, perturbed, LyapunovSettings::Mode::Perturbed)
    ->Name("LorenzSpectrum/rollviz_perturbed")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(LorenzSpectrum_odeint)->Name("LorenzSpectrum/odeint")->Unit(benchmark::kMillisecond);
BENCHMARK(ChaplyginSpectrum)->Name("ChaplyginSpectrum/rollviz_tangent")->Unit(benchmark::kMillisecond);
BENCHMARK(ChaplyginSpectrum_odeint)->Name("ChaplyginSpectrum/odeint_generic")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(MegnoHenonHeiles, torus, 0.1, 0.1)
    ->Name("Megno/henon_heiles/torus")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(MegnoHenonHeiles, chaos, 0.3, 0.3)
    ->Name("Megno/henon_heiles/chaos")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(JobThroughput)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
