// Poincare maps and Fourier spectra against known answers.
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/MapIteration.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/tools/FourierSpectrum.h"
#include "dynamics/tools/PoincareMap.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>

namespace rv {
namespace {

std::unique_ptr<Integrator> everhart(const Model& m, const Eigen::VectorXd& x0, double h = 0.05,
                                     int dir = +1) {
  auto e = std::make_unique<Everhart>(h, 15, 12);
  e->start(m, 0, x0, dir);
  return e;
}

TEST(PoincareMap, HenonHeilesStraightLineOrbitIsAFixedPoint) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  PoincareMap map(*m, everhart(*m, m->stateFromMap({0.0, 0.25}, {}, "t")), {});
  ASSERT_EQ(map.coordinateNames(), (std::vector<std::string>{"y", "py"}));
  for (int i = 0; i < 3; ++i) {
    const auto p = map.next();
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->coordinates[0], 0.0, 1e-9) << "crossing " << i;
    EXPECT_NEAR(p->coordinates[1], 0.25, 1e-9) << "crossing " << i;
    EXPECT_NEAR(map.lastState()[0], 0.0, 1e-12) << "on the section x = 0";
    EXPECT_GT(map.lastState()[2], 0) << "crossed with px > 0";
  }
}

// cells of a 60 x 60 grid over the points' bounding box that hold a point
int occupiedCells(const std::vector<MapPoint>& pts) {
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto& p : pts)
    for (int k = 0; k < 2; ++k)
      lo[k] = std::min(lo[k], p.coordinates[k]), hi[k] = std::max(hi[k], p.coordinates[k]);
  std::set<int> cells;
  for (const auto& p : pts) {
    const int i = std::min(59, static_cast<int>(60 * (p.coordinates[0] - lo[0]) / (hi[0] - lo[0] + 1e-300)));
    const int j = std::min(59, static_cast<int>(60 * (p.coordinates[1] - lo[1]) / (hi[1] - lo[1] + 1e-300)));
    cells.insert(i * 60 + j);
  }
  return static_cast<int>(cells.size());
}

TEST(PoincareMap, ARegularOrbitDrawsACurveAndAChaoticOneAnArea) {
  const auto run = [](double E, double y, double py) {
    const auto m = test::makeModel("henon_heiles", {{"energy", E}});
    PoincareMap map(*m, everhart(*m, m->stateFromMap({y, py}, {}, "t")), {});
    std::vector<MapPoint> pts;
    for (int i = 0; i < 1500; ++i)
      pts.push_back(*map.next());
    return pts;
  };
  const int regular = occupiedCells(run(0.125, 0.1, 0.1));
  const int chaotic = occupiedCells(run(1.0 / 6 - 1e-3, 0.0, -0.05));
  std::printf("  cells: regular %d, chaotic %d of 3600\n", regular, chaotic);
  EXPECT_LT(regular, 400);
  EXPECT_GT(chaotic, 2 * regular);
}

TEST(PoincareMap, BackwardIntegrationRetracesTheForwardPoints) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  PoincareMap fwd(*m, everhart(*m, m->stateFromMap({0.1, 0.1}, {}, "t")), {});
  std::vector<MapPoint> f;
  for (int i = 0; i < 6; ++i)
    f.push_back(*fwd.next());
  // from just past the last forward point, backward: the same points in reverse order
  SectionSettings back;
  back.backward = true;
  auto integ = std::make_unique<Everhart>(0.05, 15, 12);
  Eigen::VectorXd start = fwd.lastState();
  integ->start(*m, f.back().time, start, -1);
  integ->step(); // leave the section the way we came
  PoincareMap bwd(*m, std::move(integ), back);
  for (int i = 4; i >= 0; --i) {
    const auto p = bwd.next();
    ASSERT_TRUE(p);
    EXPECT_NEAR(p->coordinates[0], f[i].coordinates[0], 1e-9) << i;
    EXPECT_NEAR(p->coordinates[1], f[i].coordinates[1], 1e-9) << i;
    EXPECT_NEAR(p->time, f[i].time, 1e-8) << i;
  }
}

TEST(PoincareMap, AngleSectionsOfTheChaplyginBallAndItsSheets) {
  const auto m = test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.5, 0.2}, {}, "t");
  PoincareMap map(*m, everhart(*m, x0, 0.1), {});
  const int g = m->findObservable("g"), n = m->findObservable("n");
  const double n0 = m->integrals(x0.data())[3];
  for (int i = 0; i < 20; ++i) {
    const auto p = map.next();
    ASSERT_TRUE(p);
    EXPECT_NEAR(m->observables()[g].value(p->time, map.lastState().data()), 0.0, 1e-9)
        << "on g = 0, not g = pi";
    EXPECT_NEAR(m->observables()[n].value(p->time, map.lastState().data()), n0, 1e-9);
    EXPECT_EQ(p->sheet, 0) << "not determined in single-sheeted mode";
  }
}

TEST(PoincareMap, ExplicitMapsGiveTheirIterates) {
  const auto m = test::makeModel("standard_map", {{"K", 0.5}});
  auto it = std::make_unique<MapIteration>();
  Eigen::VectorXd x0(2);
  x0 << 1.0, 2.0;
  it->start(*m, 0, x0);
  SectionSettings s;
  s.order = 2;
  PoincareMap map(*m, std::move(it), s);
  const auto p = map.next();
  double x[2] = {1.0, 2.0}, y[2], z[2];
  m->rhs(x, y);
  m->rhs(y, z);
  EXPECT_DOUBLE_EQ(p->coordinates[0], z[0]);
  EXPECT_DOUBLE_EQ(p->coordinates[1], z[1]);
  EXPECT_EQ(p->time, 2.0);
}

TEST(PoincareMap, UnknownSectionIsAnInputError) {
  const auto m = test::makeModel("lorenz", {});
  SectionSettings s;
  s.observable = "nope";
  EXPECT_THROW(PoincareMap(*m, everhart(*m, Eigen::VectorXd::Ones(3)), s), InputError);
}

TEST(FourierSpectrum, FindsTheFrequenciesOfTwoSinusoids) {
  const double dt = 0.05, f1 = 0.37, f2 = 1.23;
  std::vector<double> x(8192);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = 2.0 * std::sin(2 * M_PI * f1 * i * dt) + 0.5 * std::cos(2 * M_PI * f2 * i * dt + 0.3) + 7;
  SpectrumSettings s;
  s.peaks = 2;
  const auto r = spectrumOf(x, dt, s);
  const double df = 1 / (x.size() * dt);
  ASSERT_EQ(r.peaks.size(), 2u);
  EXPECT_NEAR(r.peaks[0].frequency, f1, df / 4);
  EXPECT_NEAR(r.peaks[1].frequency, f2, df / 4);
  EXPECT_NEAR(r.peaks[0].amplitude, 2.0, 0.1);
  EXPECT_NEAR(r.peaks[1].amplitude, 0.5, 0.03);
}

TEST(FourierSpectrum, OfAHarmonicOscillatorAlongATrajectory) {
  // Henon-Heiles near the origin is two unit oscillators: x(t) has frequency 1 / (2 pi)
  const auto m = test::makeModel("henon_heiles", {});
  Eigen::VectorXd x0(4);
  x0 << 0.01, 0, 0, 0;
  Rk4 rk4(0.05);
  rk4.start(*m, 0, x0);
  SpectrumSettings s;
  s.function = "x";
  s.samples = 16384;
  s.peaks = 1;
  const auto r = fourierSpectrum(*m, rk4, s);
  EXPECT_NEAR(r.peaks[0].frequency, 1 / (2 * M_PI), 1 / (16384 * 0.05));
  EXPECT_NEAR(r.peaks[0].amplitude, 0.01, 5e-4);
  Merson merson(0.05, 1e-10, 1e-8, 0.1);
  merson.start(*m, 0, x0);
  EXPECT_THROW(fourierSpectrum(*m, merson, s), InputError);
}

} // namespace
} // namespace rv

namespace rv {
namespace {

TEST(PoincareMap, ManySheetedMapsKeepTheirSheet) {
  // with a gyrostat along the axis and a map point near it, |M + K| = G can be reached twice at a low energy
  const auto m = test::makeModel("chaplygin_ball", {{"energy", 0.1}, {"c", 0.0}, {"K3", 1.0}});
  const MapPointSpec one{.sectionValue = 0, .root = 1}, two{.sectionValue = 0, .root = 2};
  const Eigen::VectorXd a = m->stateFromMap({0.3, 0.9}, one, "t"), b = m->stateFromMap({0.3, 0.9}, two, "t");
  EXPECT_GT((a - b).norm(), 1e-3) << "two different states on the two sheets";
  EXPECT_NEAR(m->integrals(a.data())[0], 0.1, 1e-12);
  EXPECT_NEAR(m->integrals(b.data())[0], 0.1, 1e-12);
  EXPECT_EQ(m->sheetOf(a, one), 1);
  EXPECT_EQ(m->sheetOf(b, one), 2);
  SectionSettings s;
  s.manySheeted = true;
  s.root = 2;
  s.maxPoints = 10;
  PoincareMap map(*m, everhart(*m, b, 0.1), s);
  int n = 0;
  while (auto p = map.next()) {
    EXPECT_EQ(p->sheet, 2);
    EXPECT_EQ(m->sheetOf(map.lastState(), one), 2);
    ++n;
  }
  EXPECT_EQ(n, 10);
}

} // namespace
} // namespace rv
