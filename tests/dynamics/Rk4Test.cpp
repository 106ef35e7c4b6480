// RK4 alone: exact on cubics in t, dense output of order 4 between steps, backward integration retraces,
// blow-up reported as a ComputationError, and no heap allocation per step.
#include "dynamics/integrators/Rk4.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelWithField.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/TimeSampler.h"
#include "tests/dynamics/TestModels.h"
#include "tests/dynamics/TestSupport.h"

#include <atomic>
#include <cmath>
#include <gtest/gtest.h>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n)) return p;
  throw std::bad_alloc();
}
// not inlined: GCC, seeing free() inlined where GoogleTest calls `new`, would warn of a mismatched pair
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace rv {
namespace {

const ModelInfo& oscillatorInfo() {
  static const ModelInfo info{.id = "oscillator", .stateNames = {"q", "p"}, .coreDimension = 2};
  return info;
}
// harmonic oscillator q'' = -q: q = cos t
struct Oscillator : ModelWithField<Oscillator, 2> {
  Oscillator() : ModelWithField(oscillatorInfo(), ParameterValues(oscillatorInfo().parameters)) {}
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const { dx[0] = x[1], dx[1] = -x[0]; }
};

TEST(Rk4, DenseOutputIsFourthOrderBetweenSteps) {
  Oscillator m;
  double previous = 0;
  for (double h : {0.1, 0.05, 0.025}) {
    Rk4 rk4(h);
    Eigen::VectorXd x0(2), x(2);
    x0 << 1, 0;
    rk4.start(m, 0, x0);
    double err = 0;
    ASSERT_TRUE(sampleUniform(rk4, 0.0123, 400, [&](double t, const Eigen::VectorXd& s) {
      err = std::max(err, std::abs(s[0] - std::cos(t)));
      return true;
    }));
    if (previous > 0) {
      EXPECT_NEAR(std::log2(previous / err), 4.0, 0.35) << "h = " << h;
    }
    previous = err;
  }
}

TEST(Rk4, BackwardIntegrationRetracesTheForwardOne) {
  Oscillator m;
  Rk4 fwd(0.01), back(0.01);
  Eigen::VectorXd x0(2);
  x0 << 1, 0;
  fwd.start(m, 0, x0);
  for (int i = 0; i < 500; ++i)
    fwd.step();
  back.start(m, fwd.time(), fwd.state(), -1);
  for (int i = 0; i < 500; ++i)
    back.step();
  EXPECT_NEAR(back.time(), 0, 1e-12);
  EXPECT_NEAR((back.state() - x0).norm(), 0, 1e-9);
}

TEST(Rk4, BlowUpIsAComputationError) {
  test::Blowup m;
  Rk4 rk4(0.01);
  Eigen::VectorXd x0(1);
  x0 << 1;
  rk4.start(m, 0, x0);
  const auto run = [&] {
    for (int i = 0; i < 1000; ++i)
      rk4.step();
  };
  EXPECT_THROW(run(), ComputationError);
}

TEST(Integrators, StepsAndDenseOutputDoNotAllocate) {
  const auto model = test::makeModel("chaplygin_ball", {{"K1", 0.1}});
  const Eigen::VectorXd x0 = model->stateFromMap({0.5, 0.2}, {}, "test");
  std::vector<std::unique_ptr<Integrator>> all;
  all.push_back(std::make_unique<Rk4>(1e-3));
  all.push_back(std::make_unique<Merson>(1e-2, 1e-10, 1e-8, 0.1));
  all.push_back(std::make_unique<Everhart>(0.1, 15, 12));
  all.push_back(std::make_unique<Everhart>(0.1, 27, 12));
  all.push_back(std::make_unique<Everhart>(0.1, 15, 12, 1e-9)); // adaptive: the step ratio changes every step
  for (auto& integ : all) {
    integ->start(*model, 0, x0);
    integ->step();
    integ->step();
    const long before = g_allocations.load();
    for (int i = 0; i < 200; ++i)
      integ->step();
    EXPECT_EQ(g_allocations.load() - before, 0) << "steps";
    Eigen::VectorXd out(x0.size());
    const long beforeInterp = g_allocations.load();
    integ->interpolate(0.5 * (integ->time() + integ->previousTime()), out);
    EXPECT_EQ(g_allocations.load() - beforeInterp, 0) << "dense output";
  }
}

} // namespace
} // namespace rv
