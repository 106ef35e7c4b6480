// Dynamics benchmarks: right-hand sides per second for every model, steps per second for every integrator,
// and Boost.Odeint side by side on the same right-hand side (<Case>/rollviz vs <Case>/odeint). Run: cmake
// --preset bench && cmake --build --preset bench && build/bench/tests/bench/bench_dynamics
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Taylor.h"
#include "dynamics/integrators/Verner9.h"

#include "tests/dynamics/TestSupport.h"

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <functional>
#include <vector>

namespace {

using namespace rv;
namespace odeint = boost::numeric::odeint;

// the default scene's start of chaplygin_ball: map point (0.5, 0.2) at E = 0.5, c = 0.3, K = (0.2, 0.1, 0.3)
std::unique_ptr<Model> chaplygin() {
  const auto& e = ModelRegistry::global().get("chaplygin_ball");
  ParameterValues p(e.info->parameters);
  p.set("K1", 0.2), p.set("K2", 0.1), p.set("K3", 0.3);
  return e.create(p);
}

Eigen::VectorXd startOf(const Model& m) {
  const auto& names = m.info().stateNames;
  if (m.info().id == "ball_on_paraboloid")
    return m.stateFromNamed({{"omega1", 0.1}, {"omega2", 0.2}, {"omega3", 0.3}, {"x1", 0.2}, {"x2", 0.1}},
                            "bench");
  if (names.size() > 5 && names[3] == "gamma1")
    return m.stateFromNamed(
        {{"M1", 0.2}, {"M2", -0.3}, {"M3", 0.4}, {"gamma1", 0.1}, {"gamma2", 0.2}, {"gamma3", 1}}, "bench");
  return Eigen::VectorXd::Constant(m.dimension(), 0.3);
}

void RightHandSide(benchmark::State& state, const std::string& id) {
  const auto m = test::makeModel(id);
  const Eigen::VectorXd x = startOf(*m);
  Eigen::VectorXd dx(x.size());
  for (auto _ : state) {
    m->rhs(x.data(), dx.data());
    benchmark::DoNotOptimize(dx.data());
  }
  state.SetItemsProcessed(state.iterations());
}

// odeint's view of a rollviz model
struct OdeintSystem {
  const Model* model;
  void operator()(const std::vector<double>& x, std::vector<double>& dx, double) const {
    model->rhs(x.data(), dx.data());
  }
};

// RK4 fixed step, h = 1e-3, t = 10 on chaplygin_ball
void Rk4Chaplygin_rollviz(benchmark::State& state) {
  const auto m = chaplygin();
  const Eigen::VectorXd x0 = m->stateFromMap({0.5, 0.2}, {}, "bench");
  for (auto _ : state) {
    Rk4 rk4(1e-3);
    rk4.start(*m, 0, x0);
    for (int i = 0; i < 10000; ++i)
      rk4.step();
    benchmark::DoNotOptimize(rk4.state().data());
  }
  state.SetItemsProcessed(state.iterations() * 10000);
}

void Rk4Chaplygin_odeint(benchmark::State& state) {
  const auto m = chaplygin();
  const Eigen::VectorXd x0 = m->stateFromMap({0.5, 0.2}, {}, "bench");
  odeint::runge_kutta4<std::vector<double>> stepper;
  for (auto _ : state) {
    std::vector<double> x(x0.data(), x0.data() + x0.size());
    double t = 0;
    for (int i = 0; i < 10000; ++i, t += 1e-3)
      stepper.do_step(OdeintSystem{m.get()}, x, t, 1e-3);
    benchmark::DoNotOptimize(x.data());
  }
  state.SetItemsProcessed(state.iterations() * 10000);
}

// high accuracy: chaplygin_ball over t = 1000 to a final relative energy error near 1e-12
struct AccurateCase {
  std::unique_ptr<Model> model = chaplygin();
  Eigen::VectorXd x0 = model->stateFromMap({0.5, 0.2}, {}, "bench");
  double E0 = model->integrals(x0.data())[0];
};

// Everhart 15 at a fixed step to t = 1000: state.range(0) steps per 10 time units, state.range(1) corrector
// sweeps at most
void AccurateChaplygin_rollviz(benchmark::State& state) {
  const AccurateCase c;
  const Model* m = c.model.get();
  const Eigen::VectorXd& x0 = c.x0;
  const double E0 = c.E0;
  double err = 0;
  long evals = 0;
  for (auto _ : state) {
    const double h = 10.0 / static_cast<double>(state.range(0)); // range(0) steps per 10: lands on t = 1000
    Everhart e(h, 15, static_cast<int>(state.range(1)));
    e.start(*m, 0, x0);
    for (long i = 0; i < 100 * state.range(0); ++i)
      e.step();
    err = std::abs(m->integrals(e.state().data())[0] - E0) / E0;
    evals = e.evaluations();
  }
  state.counters["energy_error"] = err;
  state.counters["rhs_evaluations"] = static_cast<double>(evals);
}

// an adaptive method from the accurate case's start to t = 1000 (dense output there): the energy error,
// evaluations and steps of the last run as counters
void adaptiveToThousand(benchmark::State& state, const std::function<std::unique_ptr<Integrator>()>& make) {
  const AccurateCase c;
  const Model* m = c.model.get();
  double err = 0;
  long evals = 0, steps = 0;
  for (auto _ : state) {
    const auto e = make();
    e->start(*m, 0, c.x0);
    Eigen::VectorXd x(c.x0.size());
    steps = 0;
    while (e->time() < 1000)
      e->step(), ++steps;
    e->interpolate(1000, x);
    err = std::abs(m->integrals(x.data())[0] - c.E0) / c.E0;
    evals = e->evaluations();
  }
  state.counters["energy_error"] = err;
  state.counters["rhs_evaluations"] = static_cast<double>(evals);
  state.counters["steps"] = static_cast<double>(steps);
}

// Everhart 15 with IAS15's adaptive step at a tolerance (state.range(0) = -log10 tolerance), to t = 1000
void Chaplygin_adaptive(benchmark::State& state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  adaptiveToThousand(state, [&] { return std::make_unique<Everhart>(0.5, 15, 12, tolerance); });
}

// the Taylor method at a tolerance (state.range(0) = -log10 tolerance; the order follows from it), to t =
// 1000; "rhs_evaluations" counts one per order and step (a sweep of the tape)
void Chaplygin_taylor(benchmark::State& state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  adaptiveToThousand(state, [&] { return std::make_unique<Taylor>(tolerance, 0); });
}

// Verner's 9(8) pair at a tolerance (state.range(0) = -log10 tolerance), to t = 1000
void Chaplygin_verner9(benchmark::State& state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  adaptiveToThousand(state, [&] { return std::make_unique<Verner9>(tolerance, 0.1); });
}

// Adams PECE of order state.range(0) at the constant step state.range(1) / 1000, to t = 1000
void Chaplygin_adams(benchmark::State& state) {
  const double h = static_cast<double>(state.range(1)) / 1000;
  adaptiveToThousand(state, [&] { return std::make_unique<Adams>(h, static_cast<int>(state.range(0))); });
}

// an odeint peer to t = 1000 from the AccurateCase start: integrate(system, x) runs it on x (the system
// counts its evaluations); the same counters as adaptiveToThousand
template <class Integrate> void odeintToThousand(benchmark::State& state, Integrate&& integrate) {
  const AccurateCase c;
  const Model* m = c.model.get();
  double err = 0;
  long evals = 0;
  for (auto _ : state) {
    std::vector<double> x(c.x0.data(), c.x0.data() + c.x0.size());
    long count = 0;
    auto sys = [&](const std::vector<double>& y, std::vector<double>& dy, double) {
      ++count;
      m->rhs(y.data(), dy.data());
    };
    integrate(sys, x);
    err = std::abs(m->integrals(x.data())[0] - c.E0) / c.E0;
    evals = count;
  }
  state.counters["energy_error"] = err;
  state.counters["rhs_evaluations"] = static_cast<double>(evals);
}

// odeint's runge_kutta_fehlberg78, controlled, at a tolerance
void rkf78ToThousand(benchmark::State& state, double tolerance) {
  odeintToThousand(state, [&](auto& sys, std::vector<double>& x) {
    odeint::integrate_adaptive(
        odeint::make_controlled(tolerance, tolerance, odeint::runge_kutta_fehlberg78<std::vector<double>>()),
        sys, x, 0.0, 1000.0, 0.1);
  });
}

// RKF78 at tolerance 10^-state.range(0)
void Chaplygin_odeint(benchmark::State& state) {
  rkf78ToThousand(state, std::pow(10.0, -static_cast<double>(state.range(0))));
}

// odeint's adams_bashforth_moulton<8> (its highest order, PECE) at the constant step 1 / state.range(0),
// started with RKF78 steps: the multistep peer of `adams`
void Chaplygin_odeintAbm8(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  odeintToThousand(state, [&](auto& sys, std::vector<double>& x) {
    odeint::adams_bashforth_moulton<8, std::vector<double>> abm;
    double t = 0; // initialize() advances it over the starting steps
    abm.initialize(odeint::runge_kutta_fehlberg78<std::vector<double>>(), sys, x, t, h);
    odeint::integrate_n_steps(abm, sys, x, t, h, std::lround((1000 - t) / h));
  });
}

// RKF78 at the tolerance the AccurateChaplygin case was set at
void AccurateChaplygin_odeint(benchmark::State& state) {
  rkf78ToThousand(state, 1e-13);
}

// steps per second of each integrator on chaplygin_ball
void Steps(benchmark::State& state, const std::string& method) {
  const auto m = chaplygin();
  const Eigen::VectorXd x0 = m->stateFromMap({0.5, 0.2}, {}, "bench");
  std::unique_ptr<Integrator> integ;
  if (method == "rk4") integ = std::make_unique<Rk4>(1e-2);
  if (method == "merson") integ = std::make_unique<Merson>(1e-2, 1e-10, 1e-8, 0.1);
  if (method == "everhart15") integ = std::make_unique<Everhart>(0.2, 15, 12);
  if (method == "everhart27") integ = std::make_unique<Everhart>(0.5, 27, 12);
  if (method == "taylor") integ = std::make_unique<Taylor>(1e-15, 0);
  if (method == "verner9") integ = std::make_unique<Verner9>(1e-13, 0.1);
  if (method == "adams") integ = std::make_unique<Adams>(0.05, 13);
  integ->start(*m, 0, x0);
  for (auto _ : state)
    integ->step();
  state.SetItemsProcessed(state.iterations());
}

} // namespace

BENCHMARK_CAPTURE(RightHandSide, paraboloid_on_plane, std::string("paraboloid_on_plane"));
BENCHMARK_CAPTURE(RightHandSide, ellipsoid_on_plane, std::string("ellipsoid_on_plane"));
BENCHMARK_CAPTURE(RightHandSide, ball_on_ellipsoid, std::string("ball_on_ellipsoid"));
BENCHMARK_CAPTURE(RightHandSide, ball_on_paraboloid, std::string("ball_on_paraboloid"));
BENCHMARK_CAPTURE(RightHandSide, chaplygin_ball, std::string("chaplygin_ball"));
BENCHMARK_CAPTURE(RightHandSide, lorenz, std::string("lorenz"));
BENCHMARK_CAPTURE(RightHandSide, henon_heiles, std::string("henon_heiles"));
BENCHMARK(Rk4Chaplygin_rollviz)->Name("Rk4Chaplygin/rollviz")->Unit(benchmark::kMillisecond);
BENCHMARK(Rk4Chaplygin_odeint)->Name("Rk4Chaplygin/odeint")->Unit(benchmark::kMillisecond);
BENCHMARK(AccurateChaplygin_rollviz)
    ->Name("AccurateChaplygin/rollviz")
    ->Unit(benchmark::kMillisecond)
    ->ArgsProduct({{10, 20}, {6, 8, 12}});
BENCHMARK(Chaplygin_taylor)->Name("AccurateChaplygin/rollviz_taylor")->Unit(benchmark::kMillisecond)->Arg(12);
BENCHMARK(Chaplygin_verner9)
    ->Name("AccurateChaplygin/rollviz_verner9")
    ->Unit(benchmark::kMillisecond)
    ->Arg(13);
BENCHMARK(Chaplygin_adams)
    ->Name("AccurateChaplygin/rollviz_adams")
    ->Unit(benchmark::kMillisecond)
    ->Args({12, 60})
    ->Args({11, 50});
BENCHMARK(AccurateChaplygin_odeint)->Name("AccurateChaplygin/odeint")->Unit(benchmark::kMillisecond);
// the same motion near 1e-15: RKF78 at its smallest useful tolerances beside Everhart fixed and adaptive
BENCHMARK(AccurateChaplygin_rollviz)
    ->Name("PreciseChaplygin/rollviz")
    ->Unit(benchmark::kMillisecond)
    ->Args({20, 12})
    ->Args({20, 8})
    ->Args({16, 8})
    ->Args({30, 6});
BENCHMARK(Chaplygin_adaptive)
    ->Name("PreciseChaplygin/rollviz_adaptive")
    ->Unit(benchmark::kMillisecond)
    ->Arg(9)
    ->Arg(8)
    ->Arg(7);
BENCHMARK(Chaplygin_taylor)
    ->Name("PreciseChaplygin/rollviz_taylor")
    ->Unit(benchmark::kMillisecond)
    ->Arg(15)
    ->Arg(16);
BENCHMARK(Chaplygin_verner9)
    ->Name("PreciseChaplygin/rollviz_verner9")
    ->Unit(benchmark::kMillisecond)
    ->Arg(15)
    ->Arg(16);
BENCHMARK(Chaplygin_adams)
    ->Name("PreciseChaplygin/rollviz_adams")
    ->Unit(benchmark::kMillisecond)
    ->Args({13, 50})
    ->Args({13, 45});
BENCHMARK(Chaplygin_odeintAbm8)
    ->Name("PreciseChaplygin/odeint_abm8")
    ->Unit(benchmark::kMillisecond)
    ->Arg(40)
    ->Arg(80);
BENCHMARK(Chaplygin_odeint)->Name("PreciseChaplygin/odeint")->Unit(benchmark::kMillisecond)->Arg(15)->Arg(16);
BENCHMARK_CAPTURE(Steps, rk4, std::string("rk4"));
BENCHMARK_CAPTURE(Steps, merson, std::string("merson"));
BENCHMARK_CAPTURE(Steps, everhart15, std::string("everhart15"));
BENCHMARK_CAPTURE(Steps, everhart27, std::string("everhart27"));
BENCHMARK_CAPTURE(Steps, taylor, std::string("taylor"));
BENCHMARK_CAPTURE(Steps, verner9, std::string("verner9"));
BENCHMARK_CAPTURE(Steps, adams, std::string("adams"));
