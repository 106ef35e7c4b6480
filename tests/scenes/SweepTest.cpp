// Sweep files: bad ones name the field; each quantity against a known answer -- Lorenz's largest exponent
// against the stable equilibrium's eigenvalues and against a Lyapunov run of the same scene, the conserved
// energy as an observable's end value and mean, the rattleback's reversal against its mirror symmetry, the
// Henon map's orbit against its fixed point in closed form, the standard map's periods and types.
#include "scenes/Sweep.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/Lanes.h"
#include "dynamics/tools/Lyapunov.h"
#include "scenes/SceneLoader.h"
#include "scenes/SweepTask.h"
#include "scenes/ToolRunner.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <numeric>
#include <thread>

namespace rv {
namespace {

using nlohmann::json;

json sweep(const std::string& problem, json axes, const std::string& quantity, json set = json::object(),
           json options = json::object()) {
  json j{{"scene", defaultScenePath(problem)}, {"axes", std::move(axes)}, {"quantity", quantity}};
  if (!set.empty()) j["set"] = std::move(set);
  if (!options.empty()) j["options"] = std::move(options);
  return j;
}

json axis(const std::string& id, double min, double max, int count) {
  return {{"id", id}, {"min", min}, {"max", max}, {"count", count}};
}

std::string sweepError(const json& doc) {
  try {
    (void)sweepFromJson(doc, "sw.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

SweepRecord evaluate(const SweepSpec& s, long i) {
  const SweepRecord r = evaluateSweepPoint(s, i, {});
  EXPECT_TRUE(r.ok) << r.reason;
  return r;
}

TEST(Sweep, BadFilesNameTheField) {
  const json good = sweep("lorenz", json::array({axis("rho", 5, 30, 3)}), "lyapunov.max");
  EXPECT_EQ(sweepError(good), "(no error)");
  const auto expectError = [&](json doc, const std::string& where) {
    const std::string e = sweepError(doc);
    EXPECT_NE(e.find("sw.json:" + where + ":"), std::string::npos) << where << " -> " << e;
  };
  json j = good;
  j["axes"][0]["id"] = "no_such";
  expectError(j, "axes.0.id");
  j = good;
  j["quantity"] = "no_such";
  expectError(j, "quantity");
  j = good;
  j["quantity"] = "observable.no_such";
  expectError(j, "quantity");
  j = good;
  j["axes"][0]["count"] = 0;
  expectError(j, "axes.0.count");
  j = good;
  j["axes"][0]["count"] = 2.5;
  expectError(j, "axes.0.count");
  j = good;
  j["axes"][0]["min"] = 40;
  expectError(j, "axes.0.min");
  j = good;
  j["scene"] = "no/such/scene.json";
  expectError(j, "scene");
  j = good;
  j.erase("scene");
  expectError(j, "$");
  j = good;
  j["axes"].push_back(axis("rho", 1, 2, 2));
  expectError(j, "axes.1.id");
  j = good;
  j["axes"] = json::array();
  expectError(j, "axes");
  j = good;
  j["axes"][0]["id"] = "map.7";
  expectError(j, "axes.0.id");
  j = good;
  j["axes"][0]["id"] = "integrator.no_such";
  expectError(j, "axes.0.id");
  j = good;
  j["set"] = {{"no_such", 1}};
  expectError(j, "set");
  j = good;
  j["options"] = {{"orbit_points", -1}};
  expectError(j, "options.orbit_points");
  j = good;
  j["colour"] = "red";
  expectError(j, "colour");
}

TEST(Sweep, GridOrderAndAxisValues) {
  const SweepSpec s = sweepFromJson(
      sweep("lorenz", json::array({axis("rho", 5, 30, 6), axis("sigma", 5, 15, 3)}), "lyapunov.max"),
      "sw.json");
  EXPECT_EQ(s.points(), 18);
  EXPECT_EQ(s.axisValues(0), (std::vector<double>{5, 5}));
  EXPECT_EQ(s.axisValues(5), (std::vector<double>{30, 5})); // the first axis fastest, ending exactly at max
  EXPECT_EQ(s.axisValues(7), (std::vector<double>{10, 10}));
  EXPECT_EQ(sweepCsvHeader(s), (std::vector<std::string>{"rho", "sigma", "lyapunov.max", "status"}));
  EXPECT_EQ(sweepCsvHeader(s, true),
            (std::vector<std::string>{"rho", "sigma", "lyapunov.max", "seconds", "status"}));
  const Scene p = sweepPointScene(s, 7);
  EXPECT_EQ(p.document["parameters"]["rho"], 10.0);
  EXPECT_EQ(p.document["parameters"]["sigma"], 10.0);
}

TEST(Sweep, LorenzLargestExponentKnownAnswers) {
  const SweepSpec s = sweepFromJson(
      sweep("lorenz", json::array({axis("rho", 5, 28, 2)}), "lyapunov.max", {{"lyapunov.time", 300}}),
      "sw.json");
  // rho = 5: every trajectory falls onto a stable equilibrium C+ or C-; the exponent is the largest real part
  // of the Jacobian's eigenvalues there
  const double sigma = 10, beta = 8.0 / 3, rho = 5, c = std::sqrt(beta * (rho - 1));
  Eigen::Matrix3d J;
  J << -sigma, sigma, 0, rho - (rho - 1), -1, -c, c, c, -beta;
  const double expected = Eigen::EigenSolver<Eigen::Matrix3d>(J).eigenvalues().real().maxCoeff();
  const SweepRecord at5 = evaluate(s, 0);
  EXPECT_LT(at5.values[0], 0);
  EXPECT_NEAR(at5.values[0], expected, 0.02);
  // rho = 28: the same number as a Lyapunov run of the scene with --set (what `rollviz lyapunov` does)
  const Scene scene = loadScene(defaultScenePath("lorenz"), {{"lyapunov.time", "300"}, {"rho", "28"}});
  const RunSpec spec = scene.runSpec();
  LyapunovRun run(
      *scene.model, [&] { return spec.makeIntegrator(*scene.model); }, scene.initialState,
      scene.settings(lyapunovSettingsTable(), "lyapunov"));
  ASSERT_TRUE(run.run());
  const SweepRecord at28 = evaluate(s, 1);
  // (the sweep follows L1's vector alone, whose intervals need not shorten for L3's contraction: to rounding)
  EXPECT_NEAR(at28.values[0], run.result().last.exponents[0], 1e-9);
  EXPECT_NEAR(at28.values[0], 0.9056, 0.05); // Sprott, Chaos and Time-Series Analysis (2003): 0.9056
}

TEST(Sweep, MapAxesSetTheInitialPointOnTheSection) {
  const SweepSpec s = sweepFromJson(
      sweep("henon_heiles", json::array({axis("map.0", -0.1, 0.1, 3), axis("map.1", 0.0, 0.2, 2)}),
            "observable.E", {}, {{"time", 20}}),
      "sw.json");
  const Scene p = sweepPointScene(s, 5); // (0.1, 0.2)
  const Scene direct = loadScene(defaultScenePath("henon_heiles"), {{"initial.map", "[0.1, 0.2]"}});
  EXPECT_EQ(p.initialState, direct.initialState);
  EXPECT_NE(s.axisLabel(1).find("py"), std::string::npos) << s.axisLabel(1);
}

TEST(Sweep, ObservableEndValueAndMeanOfAConservedEnergy) {
  for (const char* statistic : {"end", "mean"}) {
    const SweepSpec s = sweepFromJson(sweep("henon_heiles", json::array({axis("map.0", -0.1, 0.1, 2)}),
                                            "observable.E", {}, {{"time", 30}, {"statistic", statistic}}),
                                      "sw.json");
    for (long i = 0; i < s.points(); ++i)
      EXPECT_NEAR(evaluate(s, i).values[0], 0.125, 1e-9) << statistic;
  }
  // a time average that is not the end value: x(t) of a regular orbit averages to about zero over many
  // periods
  const SweepSpec s = sweepFromJson(sweep("henon_heiles", json::array({axis("map.0", 0.1, 0.1, 1)}),
                                          "observable.x", {}, {{"time", 400}, {"statistic", "mean"}}),
                                    "sw.json");
  EXPECT_LT(std::abs(evaluate(s, 0).values[0]), 0.05);
}

TEST(Sweep, RattlebackReversalObeysTheMirrorSymmetry) {
  // mirroring the body (psi -> -psi) and the spin (M3 -> -M3) maps motions onto motions: a reversal at the
  // same time, the final spin opposite; with no misalignment (psi = 0) no reversal at all
  const SweepSpec s =
      sweepFromJson(sweep("ellipsoid_on_plane",
                          json::array({axis("initial.state.M3", -0.3, 0.3, 2), axis("psi", -0.2, 0.2, 3)}),
                          "reversal", {}, {{"time", 150}}),
                    "sw.json");
  ASSERT_EQ(s.columns, (std::vector<std::string>{"reversed", "reversal_at", "spin_end"}));
  const SweepRecord a = evaluate(s, 0), b = evaluate(s, 5); // (-0.3, -0.2) and (0.3, 0.2)
  EXPECT_EQ(a.values[0], b.values[0]);
  if (a.values[0] == 1) {
    EXPECT_NEAR(a.values[1], b.values[1], 1e-6);
  }
  EXPECT_NEAR(a.values[2], -b.values[2], 1e-8);
  EXPECT_EQ(evaluate(s, 2).values[0], 0); // psi = 0
  EXPECT_EQ(evaluate(s, 3).values[0], 0);
  EXPECT_EQ(a.values[0], 1); // the scene's own case (M3 = -0.3 with the body misaligned) turns back
}

TEST(Sweep, HenonOrbitSettlesOnTheClosedFormFixedPoint) {
  const SweepSpec s = sweepFromJson(sweep("henon_map", json::array({axis("a", 0.2, 0.3, 2)}), "orbit", {},
                                          {{"orbit_points", 20}, {"transient", 500}}),
                                    "sw.json");
  ASSERT_EQ(s.columns.size(), 20U);
  EXPECT_EQ(s.columns[0], "x.1");
  const double b = 0.3;
  for (long i = 0; i < 2; ++i) {
    const double a = s.axisValues(i)[0];
    const double fixed = (-(1 - b) + std::sqrt((1 - b) * (1 - b) + 4 * a)) / (2 * a); // x = 1 - a x^2 + b x
    for (double v : evaluate(s, i).values)
      EXPECT_NEAR(v, fixed, 1e-9) << a;
  }
}

TEST(Sweep, StandardMapPeriodsAndTypes) {
  // K = 0.9: (pi, 0) is an elliptic fixed point (trace 2 - K), (0, 0) a hyperbolic one (trace 2 + K), and
  // {(0, pi), (pi, pi)} an elliptic orbit of period 2
  const SweepSpec s = sweepFromJson(
      sweep("standard_map", json::array({axis("map.0", 0.03, 3.11, 2), axis("map.1", 0.02, 3.12, 2)}),
            "fixedpoint.order", {}, {{"max_order", 3}, {"radius", 0.1}}),
      "sw.json");
  const auto at = [&](long i) { return evaluate(s, i).values; };
  EXPECT_EQ(at(0), (std::vector<double>{1, 1})); // near (0, 0): order 1, hyperbolic
  EXPECT_EQ(at(1), (std::vector<double>{1, 0})); // near (pi, 0): order 1, elliptic
  EXPECT_EQ(at(2), (std::vector<double>{2, 0})); // near (0, pi): order 2, elliptic
  const SweepSpec t = sweepFromJson(
      sweep("standard_map", json::array({axis("map.0", 3.11, 3.11, 1), axis("map.1", 0.02, 0.02, 1)}),
            "fixedpoint.type"),
      "sw.json");
  EXPECT_EQ(evaluate(t, 0).values[0], 0); // the fixed point (pi, 0) found from (3.11, 0.02): elliptic
}

TEST(Sweep, AFailedPointSaysWhyAndTheRestGoOn) {
  const SweepSpec s = sweepFromJson(
      sweep("henon_heiles", json::array({axis("map.0", 0.0, 0.9, 2)}), "megno", {{"megno.time", 20}}),
      "sw.json");
  EXPECT_TRUE(evaluateSweepPoint(s, 0, {}).ok);
  const SweepRecord outside = evaluateSweepPoint(s, 1, {});
  EXPECT_FALSE(outside.ok);
  EXPECT_NE(outside.reason.find("no state"), std::string::npos) << outside.reason;
  EXPECT_TRUE(std::isnan(outside.values[0]));
  EXPECT_NE(sweepCsvRow(s, 1, outside).find(",\"failed: "), std::string::npos);
}

TEST(Sweep, PointLevelsOfARefinedGrid) {
  const SweepSpec s = sweepFromJson(sweep("henon_map", json::array({axis("map.0", -1, 1, 3)}), "observable.x",
                                          json::object(), {{"refine", 2}, {"time", 5}}),
                                    "sw.json");
  ASSERT_EQ(s.points(), 9); // (3 - 1) 2^2 + 1: the finest grid
  EXPECT_EQ(s.axisValues(4), (std::vector<double>{0.0}));
  const std::vector<int> levels{0, 2, 1, 2, 0, 2, 1, 2, 0};
  for (long i = 0; i < 9; ++i)
    EXPECT_EQ(sweepPointLevel(s, i), levels[static_cast<std::size_t>(i)]) << i;
  json bad =
      sweep("henon_map", json::array({axis("map.0", -1, 1, 3)}), "orbit", json::object(), {{"refine", 1}});
  EXPECT_NE(sweepError(bad).find("sw.json:options.refine:"), std::string::npos) << sweepError(bad);
}

// Runs a sweep level after level on a store in `path`; `stopAfter` points (0: never) stops it there.
bool runRefined(const SweepSpec& s, SweepStore& store, long stopAfter = 0) {
  std::atomic<long> evaluated{0};
  ToolControl control;
  control.stopRequested = [&] { return stopAfter > 0 && evaluated.load() >= stopAfter; };
  control.progress = [](double) {};
  return runSweepLevels(s, store, 2, [&](ChunkScheduler& scheduler) {
    return runSweepThreads(
        store, scheduler,
        [&](long i, const ToolControl& c) {
          if (++evaluated >= stopAfter && stopAfter > 0) {
            // hold the point until the run has seen the stop: it looks between points (every 20 ms), and a
            // fast sweep on a busy machine would otherwise finish first
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
            while (!c.stopRequested() && std::chrono::steady_clock::now() < deadline)
              std::this_thread::yield();
          }
          return evaluateSweepPoint(s, i, c);
        },
        2, control);
  });
}

// The window's picture of a refined sweep while it runs (SweepTask::updateChartData: records read once into
// memory, the grid painted again from them when more are done) is the store's painted grid, stopped halfway
// and finished.
TEST(Sweep, ARefinedSweepsChartDataIsTheStoresPaintedGrid) {
  const SweepSpec spec = sweepFromJson(
      sweep("henon_map", json::array({axis("map.0", -2.5, 2.5, 17), axis("map.1", -2.5, 2.5, 17)}),
            "observable.x", json::object(), {{"refine", 2}, {"time", 40}}),
      "sw.json");
  SweepTask task(spec, 1);
  SweepChartData data;
  std::vector<char> read;
  const auto same = [&] {
    task.updateChartData(data, read);
    const std::vector<double> painted = sweepGridValues(task.spec(), task.store());
    if (data.values.size() != painted.size()) return false;
    for (std::size_t i = 0; i < painted.size(); ++i)
      if (!(data.values[i] == painted[i] || (std::isnan(data.values[i]) && std::isnan(painted[i]))))
        return false;
    return true;
  };
  EXPECT_TRUE(same()); // nothing computed: NaN everywhere
  ToolControl halfway;
  halfway.stopRequested = [&] { return task.store().doneCount() > 300; };
  ASSERT_FALSE(task.run(halfway));
  const long stopped = task.store().doneCount();
  EXPECT_GT(stopped, 0);
  EXPECT_TRUE(same());
  ASSERT_TRUE(task.run(ToolControl{}));
  EXPECT_GT(task.store().doneCount(), stopped);
  EXPECT_TRUE(same());
  EXPECT_TRUE(std::any_of(data.values.begin(), data.values.end(), [](double v) { return !std::isnan(v); }));
}

// The Henon map's basin of attraction over the initial point: orbits that escape fail (their state stops
// being finite), the others end on the attractor -- a sharp boundary between regimes.
TEST(Sweep, RefinementComputesTheBoundaryAtTheFineResolutionAndEachPointAsADirectRun) {
  const auto file = [](int count, int levels) {
    return sweepFromJson(
        sweep("henon_map", json::array({axis("map.0", -2.5, 2.5, count), axis("map.1", -2.5, 2.5, count)}),
              "observable.x", json::object(), {{"refine", levels}, {"time", 40}}),
        "sw.json");
  };
  const SweepSpec refined = file(9, 2), fine = file(33, 0);
  ASSERT_EQ(refined.points(), fine.points());
  const std::string dir = ::testing::TempDir();
  SweepStore store(dir + "/refined.store", refined.resolved.dump(), refined.points(),
                   static_cast<int>(refined.columns.size()), "test");
  ASSERT_TRUE(runRefined(refined, store));
  long computed = 0, failed = 0;
  for (long i = 0; i < refined.points(); ++i) {
    if (!store.done(i)) continue;
    ++computed;
    const SweepRecord r = store.read(i), direct = evaluateSweepPoint(fine, i, {});
    failed += r.ok ? 0 : 1;
    ASSERT_EQ(r.ok, direct.ok) << i;
    if (r.ok) {
      EXPECT_EQ(r.values, direct.values) << "point " << i << ": a refined cell is a direct run there";
    }
  }
  // both regimes are there, and refinement computed far fewer points than the fine grid
  EXPECT_GT(failed, 0);
  EXPECT_LT(failed, computed);
  EXPECT_GT(computed, 81);
  EXPECT_LT(computed, fine.points() * 3 / 4) << computed << " of " << fine.points();

  // the painted grid has the fine grid's regimes almost everywhere (escape or not), where a plain sweep at
  // the coarse resolution misses the boundary's detail
  const std::vector<double> painted = sweepGridValues(refined, store);
  long agree = 0;
  for (long i = 0; i < fine.points(); ++i)
    agree += std::isnan(painted[static_cast<std::size_t>(i)]) == !evaluateSweepPoint(fine, i, {}).ok ? 1 : 0;
  EXPECT_GT(agree, fine.points() * 97 / 100) << agree << " of " << fine.points();

  // stopped part way and run again on its store: the same points, the same values
  SweepStore resumed(dir + "/resumed.store", refined.resolved.dump(), refined.points(),
                     static_cast<int>(refined.columns.size()), "test");
  EXPECT_FALSE(runRefined(refined, resumed, 120));
  EXPECT_LT(resumed.doneCount(), computed);
  ASSERT_TRUE(runRefined(refined, resumed));
  for (long i = 0; i < refined.points(); ++i) {
    ASSERT_EQ(resumed.done(i), store.done(i)) << i;
    if (store.done(i) && store.read(i).ok) {
      EXPECT_EQ(resumed.read(i).values, store.read(i).values) << i;
    }
  }
  store.remove();
  resumed.remove();
}

// options.refine_by value: only the cells whose corners lie on different sides of refine_at are halved. One
// iteration of the Henon map from (x0, 0) gives x1 = 1 - 1.4 x0^2, which falls through 0.5 once on [0, 1], at
// x0 = sqrt(0.5 / 1.4): refinement follows that one crossing down to the finest level, where "change" refines
// wherever neighbours differ by more than the threshold (the steep half of the line).
TEST(Sweep, RefiningByAValueFollowsOnlyWhereTheQuantityCrossesIt) {
  const auto file = [](const json& options) {
    json o{{"refine", 3}, {"time", 1}};
    o.update(options);
    return sweepFromJson(sweep("henon_map", json::array({axis("map.0", 0, 1, 5)}), "observable.x",
                               {{"initial.map", json::array({0.1, 0.0})}}, o),
                         "sw.json");
  };
  const double crossing = std::sqrt(0.5 / 1.4);
  const std::string dir = ::testing::TempDir();
  const SweepSpec byValue = file({{"refine_by", "value"}, {"refine_at", 0.5}});
  SweepStore store(dir + "/by_value.store", byValue.resolved.dump(), byValue.points(),
                   static_cast<int>(byValue.columns.size()), "test");
  ASSERT_TRUE(runRefined(byValue, store));
  std::vector<double> computed;
  for (long i = 0; i < byValue.points(); ++i)
    if (store.done(i)) {
      computed.push_back(byValue.axisValues(i)[0]);
      EXPECT_NEAR(store.read(i).values.at(0), 1 - 1.4 * computed.back() * computed.back(), 1e-15);
    }
  // the coarse grid (0, 0.25, ..., 1), then one new point per level, each in the cell around the crossing
  EXPECT_EQ(computed.size(), 5U + 3U);
  double below = 0, above = 1;
  for (double x : computed)
    (x < crossing ? below : above) = x < crossing ? std::max(below, x) : std::min(above, x);
  EXPECT_NEAR(above - below, 0.25 / 8, 1e-12) << "the crossing is bracketed at the finest spacing";
  store.remove();
  // by change, the line is refined wherever it is steep, far from the crossing too
  const SweepSpec byChange = file(json::object());
  SweepStore all(dir + "/by_change.store", byChange.resolved.dump(), byChange.points(),
                 static_cast<int>(byChange.columns.size()), "test");
  ASSERT_TRUE(runRefined(byChange, all));
  EXPECT_GT(all.doneCount(), 2 * static_cast<long>(computed.size()));
  EXPECT_TRUE(all.done(byChange.points() - 2)) << "x0 = 1 - 1/32, where x1 falls fastest";
  all.remove();
  // a categorical quantity has no value to refine across
  EXPECT_NE(sweepError(sweep("henon_map", json::array({axis("map.0", 0, 1, 5)}), "fixedpoint.type",
                             json::object(), {{"refine", 1}, {"refine_by", "value"}}))
                .find("options.refine_by"),
            std::string::npos);
}

// a whole sweep on two threads, into a store in the test's folder
std::unique_ptr<SweepStore> sweepOnTwoThreads(const SweepSpec& s, const std::string& name) {
  auto store = std::make_unique<SweepStore>(::testing::TempDir() + "/" + name, s.resolved.dump(), s.points(),
                                            static_cast<int>(s.columns.size()), "test");
  ChunkScheduler scheduler(*store, 2);
  EXPECT_TRUE(runSweepThreads(*store, scheduler,
                              [&](const std::vector<long>& chunk, const ToolControl& c,
                                  const RecordSink& sink) { evaluateSweepPoints(s, chunk, c, sink); },
                              2, {}));
  return store;
}

// MEGNO over Henon-Heiles initial points: four points at once on SIMD lanes (options.lanes 0) against one at
// a time (lanes 1) -- with rk4 the same records bit for bit, points outside the energy surface failing alike
TEST(Sweep, PointsOnLanesAreThePointsOneAtATime) {
  const auto file = [](int lanes) {
    return sweepFromJson(
        sweep("henon_heiles", json::array({axis("map.0", -0.45, 0.6, 7), axis("map.1", -0.5, 0.5, 5)}),
              "megno", {{"megno.time", 60}, {"integrator.method", "rk4"}, {"integrator.step", 0.02}},
              {{"lanes", lanes}}),
        "sw.json");
  };
  const SweepSpec batched = file(0), single = file(1);
  // the megno tool's batch evaluation is a registry property of the tool (not a name the sweep knows)
  ASSERT_NE(findLanesEvaluator("megno"), nullptr);
  EXPECT_NE(findLanesEvaluator("lyapunov"), nullptr);
  EXPECT_EQ(findLanesEvaluator("spectrum"), nullptr);
  EXPECT_THROW(addLanesEvaluator("megno", {}), InputError);
  ASSERT_EQ(sweepBatch(batched), laneWidth());
  ASSERT_EQ(sweepBatch(single), 1);
  auto a = sweepOnTwoThreads(batched, "lanes.store"), b = sweepOnTwoThreads(single, "single.store");
  int failed = 0;
  for (long i = 0; i < batched.points(); ++i) {
    const SweepRecord x = a->read(i), y = b->read(i);
    ASSERT_EQ(x.ok, y.ok) << i << ": " << x.reason << " / " << y.reason;
    failed += x.ok ? 0 : 1;
    if (x.ok) {
      EXPECT_EQ(x.values, y.values) << i;
    } else {
      EXPECT_EQ(x.reason, y.reason) << i;
    }
  }
  EXPECT_GT(failed, 0); // the corners lie outside the energy surface
  EXPECT_LT(failed, batched.points());
  a->remove();
  b->remove();
}

// A point with no state at its values (outside the energy surface) takes no lane: the batches of a chunk are
// full but for its last, each point handed to the sink once, and the records are the ones a point gets alone
TEST(Sweep, APointOutsideTheEnergySurfaceLeavesNoLaneIdle) {
  const SweepSpec plain = sweepFromJson(
      sweep("henon_heiles", json::array({axis("map.0", -0.45, 0.6, 9), axis("map.1", -0.5, 0.5, 7)}), "megno",
            {{"megno.time", 20}, {"integrator.method", "rk4"}, {"integrator.step", 0.02}}, {{"lanes", 4}}),
      "sw.json");
  SweepQuantity counted = *plain.quantity; // the same quantity, its batches counted
  std::vector<std::size_t> widths;
  counted.evaluateLanes = [&](const SweepSpec& s, const std::vector<Scene>& scenes, const ToolControl& c) {
    widths.push_back(scenes.size());
    return plain.quantity->evaluateLanes(s, scenes, c);
  };
  SweepSpec spec = plain;
  spec.quantity = &counted;
  std::vector<long> chunk(static_cast<std::size_t>(spec.points()));
  std::iota(chunk.begin(), chunk.end(), 0L);
  std::vector<int> handed(chunk.size(), 0);
  long outside = 0;
  evaluateSweepPoints(spec, chunk, {}, [&](long index, const SweepRecord& record) {
    ++handed[static_cast<std::size_t>(index)];
    const SweepRecord alone = evaluateSweepPoint(plain, index, {});
    ASSERT_EQ(record.ok, alone.ok) << index;
    if (record.ok) {
      EXPECT_EQ(record.values, alone.values) << index;
    } else {
      EXPECT_EQ(record.reason, alone.reason) << index;
      ++outside;
    }
  });
  for (std::size_t i = 0; i < handed.size(); ++i)
    EXPECT_EQ(handed[i], 1) << i;
  ASSERT_GT(outside, 4); // enough points outside to have cut batches short
  const long inside = spec.points() - outside;
  // a last batch of one point is computed alone, off the lanes
  ASSERT_EQ(static_cast<long>(widths.size()), inside / 4 + (inside % 4 >= 2 ? 1 : 0));
  for (std::size_t b = 0; b + 1 < widths.size(); ++b)
    EXPECT_EQ(widths[b], 4U) << b;
}

// The largest Lyapunov exponent of Lorenz over rho with a parameter per lane
// (dynamics/tools/LyapunovLanes.h): the batched sweep writes the one-at-a-time sweep's numbers bit for bit,
// and they are the known ones -- negative where the orbit falls onto an equilibrium (rho below ~24: 4 to 20
// here), the chaotic attractor's 0.9056 at rho = 28 (Sprott 2003; within the 300 time units' convergence)
TEST(Sweep, LorenzExponentOverRhoOnLanesIsTheScalarOne) {
  const auto file = [](int lanes) {
    return sweepFromJson(sweep("lorenz", json::array({axis("rho", 4, 28, 7)}), "lyapunov.max",
                               {{"lyapunov.time", 300}}, {{"lanes", lanes}}),
                         "sw.json");
  };
  const SweepSpec single = file(1);
  EXPECT_EQ(sweepBatch(file(0)), laneWidth()); // the CPU's width
  auto b = sweepOnTwoThreads(single, "rho-single.store");
  for (int width : {4, 8}) { // AVX2's width and AVX-512's (SSE2 pairs where the CPU has neither)
    const SweepSpec batched = file(width);
    ASSERT_EQ(sweepBatch(batched), width);
    auto a = sweepOnTwoThreads(batched, "rho-lanes.store");
    for (long i = 0; i < batched.points(); ++i) {
      const SweepRecord x = a->read(i), y = b->read(i);
      ASSERT_TRUE(x.ok && y.ok) << i << ": " << x.reason << " / " << y.reason;
      EXPECT_EQ(x.values, y.values) << width << " lanes, rho " << batched.axisValues(i)[0];
      if (batched.axisValues(i)[0] <= 20) {
        EXPECT_LT(x.values[0], 0) << "rho " << batched.axisValues(i)[0];
      }
    }
    EXPECT_NEAR(a->read(6).values[0], 0.9056, 0.05);
    a->remove();
  }
  b->remove();
  EXPECT_NE(sweepError(sweep("lorenz", json::array({axis("rho", 4, 28, 7)}), "lyapunov.max", json::object(),
                             {{"lanes", 3}}))
                .find("options.lanes"),
            std::string::npos);
}

// A sweep of lyapunov.max follows one tangent vector (ToolRunner::narrowTo): the largest exponent's vector is
// advanced, projected and normalised without reading the others, so each point is the first exponent of the
// whole spectrum -- bit for bit with rk4 (the fused loop), to the integrator's accuracy where the steps of
// an adaptive method (or everhart's corrector, adams's starter) see the other vectors too -- with everhart,
// adams, rk4, merson (adaptive, a step per lane) and the projection on the integrals' level; the stopping
// rule reads every exponent, so with it the spectrum stays whole.
TEST(Sweep, TheLargestExponentAloneIsTheWholeSpectrumsFirst) {
  const ToolEntry& lyapunov = ToolRegistry::global().get("lyapunov");
  const auto check = [&](const std::string& problem, json axes, json set, int exponents) {
    set["lyapunov.time"] = 12;
    for (int lanes : {1, laneWidth()}) {
      const SweepSpec s =
          sweepFromJson(sweep(problem, axes, "lyapunov.max", set, {{"lanes", lanes}}), "sw.json");
      ASSERT_TRUE(s.quantity->narrow);
      std::vector<long> all(static_cast<std::size_t>(s.points()));
      std::iota(all.begin(), all.end(), 0L);
      const auto records = evaluateSweepPoints(s, all, {});
      for (long i = 0; i < s.points(); ++i) {
        Scene narrowed = sweepPointScene(s, i);
        s.quantity->narrow(narrowed);
        EXPECT_EQ(narrowed.settings(lyapunovSettingsTable(), "lyapunov").count, 1);
        const ToolResult whole = runTool(lyapunov, sweepPointScene(s, i), {});
        const auto& l = whole.fields.at("exponents");
        ASSERT_EQ(static_cast<int>(l.size()), exponents) << problem;
        ASSERT_TRUE(records[static_cast<std::size_t>(i)].ok) << records[static_cast<std::size_t>(i)].reason;
        const double alone = records[static_cast<std::size_t>(i)].values.at(0), first = l[0].get<double>();
        if (set.value("integrator.method", "") == "rk4")
          EXPECT_EQ(alone, first) << problem << " " << set.dump() << ", " << lanes << " lanes, point " << i;
        else
          EXPECT_NEAR(alone, first, 1e-6)
              << problem << " " << set.dump() << ", " << lanes << " lanes, point " << i;
      }
    }
  };
  const json rattleback = json::array({axis("b2", 0.3, 1.2, 3), axis("psi", -0.3, 0.3, 2)});
  check("ellipsoid_on_plane", rattleback, {{"initial.state.M3", -0.3}}, 6);
  check("ellipsoid_on_plane", rattleback,
        {{"initial.state.M3", -0.3},
         {"integrator.method", "adams"},
         {"integrator.step", 0.01},
         {"integrator.order", 12}},
        6);
  check("ellipsoid_on_plane", rattleback,
        {{"initial.state.M3", -0.3}, {"integrator.method", "rk4"}, {"integrator.step", 0.01}}, 6);
  // kept on the level set of its two integrals: the four exponents of its tangent space
  check("ellipsoid_on_plane", rattleback, {{"initial.state.M3", -0.3}, {"lyapunov.renormalize", "yes"}}, 4);
  // merson's steps: each lane's own, under its own error control
  check("ellipsoid_on_plane", rattleback, {{"initial.state.M3", -0.3}, {"integrator.method", "merson"}}, 6);
  check("lorenz", json::array({axis("rho", 10, 28, 5)}), json::object(), 3);
  // where the stopping rule or the perturbed method reads every exponent, nothing is narrowed
  for (const json& set : {json{{"lyapunov.successes", 3}}, json{{"lyapunov.mode", "perturbed"}}}) {
    const SweepSpec s =
        sweepFromJson(sweep("lorenz", json::array({axis("rho", 10, 28, 2)}), "lyapunov.max", set), "sw.json");
    Scene scene = sweepPointScene(s, 0);
    s.quantity->narrow(scene);
    EXPECT_EQ(scene.settings(lyapunovSettingsTable(), "lyapunov").count, 0) << set.dump();
  }
  // and the other outputs need every exponent
  const SweepSpec sum =
      sweepFromJson(sweep("lorenz", json::array({axis("rho", 10, 28, 2)}), "lyapunov.positive"), "sw.json");
  Scene scene = sweepPointScene(sum, 0);
  if (sum.quantity->narrow) sum.quantity->narrow(scene);
  EXPECT_EQ(scene.settings(lyapunovSettingsTable(), "lyapunov").count, 0);
}

// The trajectory quantities (observable.NAME, reversal) on lanes: a batch of points' orbits integrated at
// once (dynamics/tools/TrajectoryLanes.h) gives each point the one-at-a-time values bit for bit -- the
// rattleback's reversal over its spin and misalignment (a model per lane), an observable's end value and time
// average, with everhart and rk4; the batches do run on lanes (the quantity's evaluateLanes answers).
TEST(Sweep, TrajectoryQuantitiesOnLanesAreOneAtATimeBitForBit) {
  const json axes = json::array({axis("initial.state.M3", -0.5, 0.5, 3), axis("psi", -0.3, 0.3, 3)});
  std::vector<std::vector<double>> reversal; // the reversal chart's values
  const auto check = [&](const std::string& quantity, json set, json options) {
    options["time"] = 60;
    std::vector<std::vector<double>> values[2];
    std::vector<std::vector<std::uint64_t>> bits[2]; // compared bit for bit, NaN (no reversal) included
    for (int k = 0; k < 2; ++k) {
      options["lanes"] = k == 0 ? 1 : laneWidth();
      const SweepSpec s = sweepFromJson(sweep("ellipsoid_on_plane", axes, quantity, set, options), "sw.json");
      ASSERT_TRUE(s.quantity->evaluateLanes) << quantity;
      std::vector<long> all(static_cast<std::size_t>(s.points()));
      std::iota(all.begin(), all.end(), 0L);
      for (const SweepRecord& r : evaluateSweepPoints(s, all, {})) {
        ASSERT_TRUE(r.ok) << quantity << ": " << r.reason;
        values[k].push_back(r.values);
        bits[k].emplace_back();
        for (double v : r.values)
          bits[k].back().push_back(std::bit_cast<std::uint64_t>(v));
      }
      if (k == 1) {
        std::vector<Scene> scenes;
        for (long i = 0; i < 4; ++i)
          scenes.push_back(sweepPointScene(s, i));
        EXPECT_TRUE(s.quantity->evaluateLanes(s, scenes, {}).has_value()) << quantity << ": not on lanes";
      }
    }
    EXPECT_EQ(bits[1], bits[0]) << quantity << " " << set.dump();
    if (quantity == "reversal") reversal = values[0];
  };
  check("reversal", json::object(), json::object());
  int reversed = 0;
  for (const auto& v : reversal)
    reversed += v[0] == 1;
  EXPECT_GT(reversed, 0);
  EXPECT_LT(reversed, 9) << "the chart should hold both regimes";
  check("reversal", {{"integrator.method", "rk4"}, {"integrator.step", 0.01}}, json::object());
  check("observable.M3", json::object(), json::object());
  check("observable.M3", json::object(), {{"statistic", "mean"}});
}

// An orbit diagram of a flow on lanes: the Lorenz system's map points on z = 27 over rho (a parameter per
// lane), the crossings located lane by lane, each point's row the one-at-a-time one bit for bit; and a map
// that ends early (max_time) fails on its lane as alone.
TEST(Sweep, AnOrbitDiagramOfAFlowOnLanesIsOneAtATimeBitForBit) {
  const json axes = json::array({axis("rho", 24, 30, 7)});
  for (const json& set : {json{{"poincare.points", 2000}}, json{{"poincare.max_time", 20}}}) {
    std::vector<SweepRecord> records[2];
    for (int k = 0; k < 2; ++k) {
      const json options{{"lanes", k == 0 ? 1 : laneWidth()}, {"orbit_points", 20}, {"transient", 10}};
      const SweepSpec s = sweepFromJson(sweep("lorenz", axes, "orbit", set, options), "sw.json");
      std::vector<long> all(static_cast<std::size_t>(s.points()));
      std::iota(all.begin(), all.end(), 0L);
      records[k] = evaluateSweepPoints(s, all, {});
      if (k == 1) {
        std::vector<Scene> scenes;
        for (long i = 0; i < 4; ++i)
          scenes.push_back(sweepPointScene(s, i));
        EXPECT_TRUE(s.quantity->evaluateLanes(s, scenes, {}).has_value()) << "not on lanes";
      }
    }
    ASSERT_EQ(records[0].size(), 7u);
    for (std::size_t i = 0; i < records[0].size(); ++i) {
      EXPECT_EQ(records[1][i].ok, records[0][i].ok) << set.dump() << " point " << i;
      EXPECT_EQ(records[1][i].reason, records[0][i].reason) << set.dump() << " point " << i;
      if (records[0][i].ok) {
        EXPECT_EQ(records[1][i].values, records[0][i].values) << set.dump() << " point " << i;
        EXPECT_EQ(records[0][i].values.size(), 20u);
      }
    }
    // the points: on the section's far lobe or the near one, never at the origin's height
    if (records[0][0].ok) {
      for (double x : records[0][0].values)
        EXPECT_GT(std::abs(x), 1);
    }
    EXPECT_EQ(records[0][0].ok, !set.contains("poincare.max_time")) << records[0][0].reason;
  }
}

} // namespace
} // namespace rv
