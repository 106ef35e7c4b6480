// MEGNO on lanes (dynamics/tools/MegnoLanes.h): a method that steps lanes alone (rk4, everhart at a fixed
// step, each lane's corrector converging on its own) steps orbits together as alone; the lane kernel equals
// the scalar tangent right-hand side bit for bit; Henon-Heiles orbits at once with rk4 and with everhart are
// the scalar runs bit for bit; orbits that blow up (Henon-Heiles above the escape energy 1/6) fail in the
// batch as they fail alone, and the others keep their scalar answers.
#include "dynamics/tools/MegnoLanes.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "tests/dynamics/LaneTestSupport.h"
#include "tests/dynamics/TestModels.h"
#include "tests/dynamics/TestSupport.h"

#include <array>
#include <gtest/gtest.h>
#include <random>

namespace rv {
namespace {

// K coupled oscillators side by side in one state, component-major as on lanes (component c of orbit l at
// c * K + l)
ModelInfo stackInfo(int k) {
  ModelInfo info{.id = "oscillator stack", .coreDimension = 3 * k};
  for (int i = 0; i < 3 * k; ++i)
    info.stateNames.push_back("x" + std::to_string(i));
  return info;
}
struct OscillatorStack final : Model {
  OscillatorStack(const ModelInfo& info, int k) : Model(info, ParameterValues(info.parameters)), k_(k) {}
  void rhs(const double* x, double* dx) const override {
    for (int l = 0; l < k_; ++l) {
      std::array<double, 3> in{}, out{};
      for (int c = 0; c < 3; ++c)
        in[static_cast<std::size_t>(c)] = x[c * k_ + l];
      one.rhs(in.data(), out.data());
      for (int c = 0; c < 3; ++c)
        dx[c * k_ + l] = out[static_cast<std::size_t>(c)];
    }
  }
  void jacobian(const double*, double*) const override {
    ADD_FAILURE() << "the methods stepped need no Jacobian";
  }
  test::CoupledOscillator one;
  int k_;
};

// Integrator::stepLanesAlone is what lets a sweep put orbits on lanes and still write each orbit's own
// numbers: a method that says yes gives each of K orbits integrated together the steps and the state of the
// orbit integrated alone, bit for bit (orbits far apart and of different shapes: a method whose steps read
// the whole state would step them differently -- everhart's corrector converges lane by lane, merson's error
// and step are each lane's own). K = 2 and 6: a small system and one large enough for rk4's AVX2 path (18
// components: four registers and two left over) against the alone runs' fixed-size path. Compared where
// advanceTo lands, off the steps (the dense output) and after many steps; and step by step where the lanes
// share one step (the time too).
TEST(Lanes, AMethodThatStepsLanesAloneStepsEachOrbitAsAlone) {
  int saying = 0;
  for (const auto& entry : IntegratorRegistry::global().entries()) {
    const ParameterValues values(*entry.parameters);
    if (!entry.create(values)->stepLanesAlone(2)) continue;
    ++saying;
    for (int k : {2, 6}) {
      SCOPED_TRACE(entry.id + ", " + std::to_string(k) + " orbits");
      const ModelInfo info = stackInfo(k);
      const OscillatorStack stack(info, k);
      Eigen::VectorXd all(3 * k);
      std::vector<std::unique_ptr<Integrator>> alone;
      for (int i = 0; i < k; ++i) {
        Eigen::VectorXd x(3);
        x << 1 + 13.0 * i, -3.0 * i, 0.5 * i * i;
        for (int c = 0; c < 3; ++c)
          all[c * k + i] = x[c];
        alone.push_back(entry.create(values));
        alone.back()->start(stack.one, 0, x);
      }
      auto together = entry.create(values);
      ASSERT_TRUE(together->stepLanesAlone(k));
      together->start(stack, 0, all);
      Eigen::VectorXd out, outAlone;
      for (int j = 1; j <= 40; ++j) {
        const double target = 0.137 * j;
        ASSERT_TRUE(together->advanceTo(target, out, [] { return false; }));
        for (int i = 0; i < k; ++i) {
          alone[static_cast<std::size_t>(i)]->advanceTo(target, outAlone);
          for (int c = 0; c < 3; ++c)
            ASSERT_EQ(out[c * k + i], outAlone[c])
                << "t = " << target << ", orbit " << i << " component " << c;
        }
      }
      if (together->lanesStepOnTheirOwn()) continue; // each lane at a time of its own: advanceTo alone
      for (int step = 0; step < 200; ++step) {
        together->step();
        for (auto& a : alone) {
          a->step();
          ASSERT_EQ(together->time(), a->time());
        }
      }
      for (int i = 0; i < k; ++i)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(together->state()[c * k + i], alone[static_cast<std::size_t>(i)]->state()[c])
              << "orbit " << i << " component " << c;
    }
  }
  EXPECT_GE(saying, 4); // rk4, everhart, adams, merson
  EXPECT_FALSE(Everhart(0.05, 15, 12, 1e-9).stepLanesAlone(4)) << "an adaptive step is one for all lanes";
}

// `count` orbits of one model
std::vector<const Model*> sameModel(const Model& model, std::size_t count) {
  return std::vector<const Model*>(count, &model);
}

// a Henon-Heiles state at energy e from (y, py) on x = 0 with px > 0
Eigen::VectorXd hhState(double e, double y, double py) {
  Eigen::VectorXd x(4);
  const double px2 = 2 * e - py * py - y * y + 2 * y * y * y / 3;
  x << 0, y, std::sqrt(std::max(0.0, px2)), py;
  return x;
}

TEST(Lanes, KernelEqualsTheScalarTangentRightHandSideBitForBit) {
  std::mt19937 random(7);
  for (const char* id :
       {"henon_heiles", "lorenz", "chaplygin_ball", "ball_on_ellipsoid", "ball_on_paraboloid"}) {
    const auto model = test::makeModel(id, {});
    for (std::size_t orbits : {1, 5}) { // four lanes (AVX2), eight (AVX-512)
      const auto kernel = laneKernelFor(std::vector<const Model*>(orbits, model.get()));
      ASSERT_TRUE(kernel) << id;
      EXPECT_EQ(kernel->width(), orbits == 1 ? 4 : 8);
      test::expectKernelRhsIsEachModelAlone(
          *kernel, std::vector<const Model*>(static_cast<std::size_t>(kernel->width()), model.get()), random,
          id);
    }
  }
  // a flow with no lane kernel (a field not declared kLaneField) is left to the scalar run by the batched
  // tools
  const test::CoupledOscillator oscillator;
  const auto map = test::makeModel("standard_map", {}), hh = test::makeModel("henon_heiles", {}),
             lorenz = test::makeModel("lorenz", {});
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.02); };
  const IntegratorFactory everhart = [] { return std::make_unique<Everhart>(0.05, 15, 12); };
  const IntegratorFactory adaptive = [] { return std::make_unique<Everhart>(0.05, 15, 12, 1e-9); };
  EXPECT_FALSE(megnoRunsOnLanes({&oscillator}, rk4));
  EXPECT_FALSE(megnoRunsOnLanes({map.get()}, rk4));
  EXPECT_TRUE(megnoRunsOnLanes({hh.get()}, rk4));
  EXPECT_TRUE(megnoRunsOnLanes({hh.get()}, everhart));
  EXPECT_FALSE(megnoRunsOnLanes({hh.get()}, adaptive)) << "one adaptive step for all lanes";
  // lanes of one class only
  EXPECT_FALSE(megnoRunsOnLanes({hh.get(), lorenz.get()}, rk4));
}

TEST(Lanes, MegnoWithRk4IsTheScalarRunBitForBit) {
  const auto model = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.02); };
  MegnoSettings s;
  s.maxTime = 60, s.interval = 10, s.outputPeriod = 60;
  // tori and chaos, and a batch of three (the last lane repeats the third)
  const std::vector<Eigen::VectorXd> x0s{hhState(0.125, 0.1, 0.1), hhState(0.125, 0.3, 0.3),
                                         hhState(0.125, -0.2, 0.05)};
  const auto lanes = megnoOnLanes(sameModel(*model, x0s.size()), rk4, x0s, s);
  ASSERT_EQ(lanes.size(), 3u);
  for (std::size_t k = 0; k < x0s.size(); ++k) {
    ASSERT_FALSE(lanes[k].failure);
    const MegnoEstimate alone = megno(*model, rk4, x0s[k], s).last;
    EXPECT_EQ(lanes[k].last.megno, alone.megno) << k;
    EXPECT_EQ(lanes[k].last.y, alone.y) << k;
    EXPECT_EQ(lanes[k].last.fli, alone.fli) << k;
    EXPECT_EQ(lanes[k].last.time, alone.time) << k;
  }
}

// each lane's corrector iterates to its own convergence: the batch is the scalar runs bit for bit, on tori
// and in the chaotic sea, at four lanes and at eight. The MEGNO system of Henon-Heiles has 11 components:
// Everhart's node sums must add the last one in the same order as the others (three of these orbits, from
// the example sweep henon_heiles_megno.json, came out 1e-14 apart when a matrix product summed them)
void expectMegnoOnLanesIsTheScalarRun(const IntegratorFactory& method) {
  const auto model = test::makeModel("henon_heiles", {{"energy", 0.125}});
  MegnoSettings s;
  s.maxTime = 400, s.interval = 10, s.outputPeriod = 400;
  const double py = -0.35714285714285715;
  const std::vector<Eigen::VectorXd> x0s{hhState(0.125, -0.15, py), hhState(0.125, 0.0, py),
                                         hhState(0.125, 0.15, py),  hhState(0.125, 0.05, -0.1),
                                         hhState(0.125, 0.3, 0.3),  hhState(0.125, -0.2, 0.05),
                                         hhState(0.125, 0.1, 0.1),  hhState(0.125, 0.2, -0.3)};
  int tori = 0, chaos = 0;
  for (std::size_t count : {4, 8}) {
    const std::vector<Eigen::VectorXd> some(x0s.begin(), x0s.begin() + static_cast<long>(count));
    const auto lanes = megnoOnLanes(sameModel(*model, count), method, some, s);
    ASSERT_EQ(lanes.size(), count);
    for (std::size_t k = 0; k < count; ++k) {
      ASSERT_FALSE(lanes[k].failure) << k;
      const MegnoEstimate alone = megno(*model, method, x0s[k], s).last;
      EXPECT_EQ(lanes[k].last.megno, alone.megno) << count << " lanes, orbit " << k;
      EXPECT_EQ(lanes[k].last.fli, alone.fli) << count << " lanes, orbit " << k;
      if (count == 8) ++(alone.megno < 2.5 ? tori : chaos);
    }
  }
  EXPECT_GE(tori, 2);
  EXPECT_GE(chaos, 1) << "pick a chaotic orbit: the lanes' corrector iterations should differ";
}

TEST(Lanes, MegnoWithEverhartIsTheScalarRunBitForBit) {
  expectMegnoOnLanesIsTheScalarRun([] { return std::make_unique<Everhart>(0.05, 15, 12); });
}

// Adams steps component by component and starts orbit by orbit (its adaptive starter on each lane's view of
// the stacked field, dynamics/core/OneLane.h)
TEST(Lanes, MegnoWithAdamsIsTheScalarRunBitForBit) {
  expectMegnoOnLanesIsTheScalarRun([] { return std::make_unique<Adams>(0.02, 12); });
}

// each lane's step under its own error control: the orbits' step sequences differ, each the scalar run's
TEST(Lanes, MegnoWithMersonIsTheScalarRunBitForBit) {
  expectMegnoOnLanesIsTheScalarRun([] { return std::make_unique<Merson>(0.01, 1e-10, 1e-10, 0.1); });
}

TEST(Lanes, AnOrbitThatBlowsUpFailsAsItWouldAloneAndTheOthersKeepTheirAnswers) {
  // above the escape energy 1/6 an orbit leaving through a saddle runs off to infinity in finite time (the
  // model's energy only completes map points: the states are given whole)
  const double e = 0.3;
  const auto model = test::makeModel("henon_heiles", {});
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.01); };
  MegnoSettings s;
  s.maxTime = 40, s.interval = 5, s.outputPeriod = 40;
  const std::vector<Eigen::VectorXd> x0s{hhState(0.1, 0.1, 0.1), hhState(e, 0.6, 0.3),
                                         hhState(0.1, -0.2, 0.05), hhState(e, 0.0, 0.1)};
  const auto lanes = megnoOnLanes(sameModel(*model, x0s.size()), rk4, x0s, s);
  int failed = 0;
  for (std::size_t k = 0; k < x0s.size(); ++k) {
    bool aloneFails = false;
    MegnoEstimate alone;
    try {
      alone = megno(*model, rk4, x0s[k], s).last;
    } catch (const ComputationError&) {
      aloneFails = true;
    }
    EXPECT_EQ(static_cast<bool>(lanes[k].failure), aloneFails) << k;
    failed += aloneFails ? 1 : 0;
    if (!aloneFails) {
      EXPECT_EQ(lanes[k].last.megno, alone.megno) << k;
    }
  }
  EXPECT_GE(failed, 1) << "no orbit of the batch blew up: pick others";
  EXPECT_LT(failed, 4) << "every orbit blew up: pick others";
}

} // namespace
} // namespace rv
