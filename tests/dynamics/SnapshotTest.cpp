// Resumable computations (checkpoints): a run saved at any step and restored into a fresh object goes on
// bit-identically -- for every registered integrator, the Poincare map (saved between steps, not only at
// points) and the Lyapunov algorithm in both modes. Identity is exact (==), the property `--checkpoint`
// promises.
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/tools/PoincareMap.h"
#include "tests/dynamics/TestSupport.h"

#include <gtest/gtest.h>

namespace rv {
namespace {

Eigen::VectorXd henonHeilesStart() {
  Eigen::VectorXd x(4);
  x << 0.0, 0.1, 0.39, 0.05; // (x, y, px, py): a chaotic orbit near E = 1/8
  return x;
}

std::unique_ptr<Integrator> make(const IntegratorEntry& e) {
  return e.create(ParameterValues(*e.parameters));
}

TEST(Snapshot, EveryIntegratorResumesBitIdentically) {
  const auto m = test::makeModel("henon_heiles", {});
  std::vector<std::pair<const IntegratorEntry*, bool>> cases; // every method, and Everhart's adaptive step
  for (const auto& e : IntegratorRegistry::global().entries())
    cases.emplace_back(&e, false);
  cases.emplace_back(&IntegratorRegistry::global().get("everhart"), true);
  for (const auto& [entry, adaptive] : cases) {
    const IntegratorEntry& e = *entry;
    SCOPED_TRACE(e.id + (adaptive ? " adaptive" : ""));
    const auto make = [adaptive = adaptive](const IntegratorEntry& method) {
      ParameterValues p(*method.parameters);
      if (adaptive) p.set("adaptive", 1), p.set("step", 0.37);
      return method.create(p);
    };
    auto a = make(e);
    a->start(*m, 0, henonHeilesStart());
    for (int i = 0; i < 37; ++i)
      a->step();
    Snapshot saved;
    a->save(saved);
    auto b = make(e);
    b->start(*m, 0, henonHeilesStart() * 0.5); // another start: everything must come from the snapshot
    b->restore(saved);
    EXPECT_EQ(saved.position, saved.values.size());
    Eigen::VectorXd da(4), db(4);
    for (int i = 0; i < 200; ++i) {
      a->step(), b->step();
      ASSERT_EQ(a->time(), b->time()) << "step " << i;
      ASSERT_TRUE(a->state() == b->state()) << "step " << i;
    }
    const double mid = 0.5 * (a->time() + a->previousTime());
    a->interpolate(mid, da), b->interpolate(mid, db);
    EXPECT_TRUE(da == db);
    EXPECT_EQ(a->evaluations(), b->evaluations());
  }
}

TEST(Snapshot, RestoringTheWrongKindOfStateIsAnInputError) {
  const auto m3 = test::makeModel("lorenz", {});
  const auto m4 = test::makeModel("henon_heiles", {});
  const auto& rk4 = IntegratorRegistry::global().get("rk4");
  auto a = make(rk4);
  a->start(*m3, 0, Eigen::VectorXd::Ones(3));
  Snapshot saved;
  a->save(saved);
  auto b = make(rk4);
  b->start(*m4, 0, henonHeilesStart());
  EXPECT_THROW(b->restore(saved), InputError);
  Snapshot truncated;
  truncated.values.assign(saved.values.begin(), saved.values.begin() + 5);
  EXPECT_THROW(a->restore(truncated), InputError);
}

TEST(Snapshot, PoincareMapResumesBetweenStepsBitIdentically) {
  const auto m = test::makeModel("henon_heiles", {});
  const auto& everhart = IntegratorRegistry::global().get("everhart");
  SectionSettings s; // the model's default section
  const auto build = [&] {
    auto integ = make(everhart);
    integ->start(*m, 0, henonHeilesStart());
    return PoincareMap(*m, std::move(integ), s);
  };
  // uninterrupted
  PoincareMap whole = build();
  std::vector<MapPoint> expected;
  for (int i = 0; i < 40; ++i)
    expected.push_back(*whole.next());
  // stopped after 1111 steps (between two points) and resumed in a fresh map
  PoincareMap first = build();
  std::vector<MapPoint> got;
  int steps = 0;
  ToolControl stopAfter;
  stopAfter.stopRequested = [&] { return steps >= 1111; };
  first.setStepObserver([&](const Integrator&) { ++steps; });
  while (auto p = first.next(stopAfter))
    got.push_back(*p);
  ASSERT_GT(got.size(), 2u);
  ASSERT_LT(got.size(), 40u);
  Snapshot saved;
  first.save(saved);
  PoincareMap second = build();
  second.restore(saved);
  while (got.size() < expected.size())
    got.push_back(*second.next());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(got[i].time, expected[i].time) << i;
    EXPECT_EQ(got[i].coordinates, expected[i].coordinates) << i;
  }
}

TEST(Snapshot, LyapunovRunResumesBitIdentically) {
  const auto m = test::makeModel("lorenz", {});
  Eigen::VectorXd x0(3);
  x0 << 1, 1, 20;
  for (auto mode : {LyapunovSettings::Mode::Tangent, LyapunovSettings::Mode::Perturbed}) {
    LyapunovSettings s;
    const bool tangent = mode == LyapunovSettings::Mode::Tangent;
    s.mode = mode;
    // tangent mode with rk4 takes the fused path, which sees a stop between chunks of 4096 steps: intervals
    // of 5000 steps (h = 1e-3) have one inside them
    s.interval = tangent ? 5 : 0.5;
    s.maxTime = 60;
    const auto factory = [] { return make(IntegratorRegistry::global().get("rk4")); };
    const LyapunovResult whole = lyapunovExponents(*m, factory, x0, s);
    // stopped in the middle of an interval, saved, restored into a fresh run
    LyapunovRun first(*m, factory, x0, s);
    int polls = 0;
    ToolControl stopSoon;
    stopSoon.stopRequested = [&] { return ++polls > (tangent ? 20 : 5000); };
    EXPECT_FALSE(first.run({}, stopSoon));
    ASSERT_GT(first.result().last.time, 0);
    Snapshot saved;
    first.save(saved);
    LyapunovRun second(*m, factory, Eigen::VectorXd::Ones(3), s);
    second.restore(saved);
    EXPECT_TRUE(second.run());
    EXPECT_EQ(second.result().last.time, whole.last.time);
    EXPECT_EQ(second.result().last.exponents, whole.last.exponents);
  }
}

} // namespace
} // namespace rv
