// Fixed points, multipliers and continuation against analytic answers (Henon map, standard map, the
// straight-line orbit of Henon-Heiles), and finite-difference derivatives of Poincare maps against the
// variational equations.
#include "dynamics/tools/FixedPoint.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/BifurcationCurve.h"
#include "dynamics/tools/BifurcationTree.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace rv {
namespace {

constexpr double pi = std::numbers::pi;

SectionSettings order(int n) {
  SectionSettings s;
  s.order = n;
  return s;
}

TEST(FixedPoint, HenonMapBothPointsAreAnalyticAndHyperbolic) {
  const double a = 1.4, b = 0.3;
  const auto m = test::makeModel("henon_map", {{"a", a}, {"b", b}});
  const ReturnMap map(*m, test::everhartFactory(), order(1));
  for (double sign : {+1.0, -1.0}) {
    const double x = (-(1 - b) + sign * std::sqrt((1 - b) * (1 - b) + 4 * a)) / (2 * a);
    for (auto method : {DerivativeMethod::FiniteDifferences, DerivativeMethod::Variational}) {
      FixedPointSettings s;
      s.derivatives.method = method;
      s.accuracy = 1e-13;
      const auto r = findFixedPoint(map, Eigen::Vector2d(x + 0.05, b * x - 0.03), s);
      EXPECT_NEAR(r.point[0], x, 1e-12);
      EXPECT_NEAR(r.point[1], b * x, 1e-12);
      EXPECT_TRUE(isHyperbolic(r.type)) << toString(r.type);
      // det D = -b: the multipliers' product
      const auto prod = r.multipliers[0] * r.multipliers[1];
      EXPECT_NEAR(prod.real(), -b, 1e-8);
      EXPECT_NEAR(prod.imag(), 0, 1e-12);
      // each multiplier solves lambda^2 + 2 a x lambda - b = 0
      for (auto l : r.multipliers)
        EXPECT_NEAR(std::abs(l * l + 2 * a * x * l - b), 0, 1e-7);
    }
  }
}

TEST(FixedPoint, GradientDescentFindsTheHenonPointToo) {
  const auto m = test::makeModel("henon_map", {});
  const ReturnMap map(*m, test::everhartFactory(), order(1));
  FixedPointSettings s;
  s.method = FixedPointMethod::Gradient;
  s.maxIterations = 5000;
  s.accuracy = 1e-11;
  s.maxDistance = 0.01;
  const double x = (-0.7 + std::sqrt(0.49 + 5.6)) / 2.8;
  std::vector<double> distances;
  const auto r = findFixedPoint(map, Eigen::Vector2d(0.55, 0.25), s, {},
                                [&](const SearchPoint& p) { distances.push_back(p.residual); });
  EXPECT_NEAR(r.point[0], x, 1e-10);
  EXPECT_NEAR(r.point[1], 0.3 * x, 1e-10);
  ASSERT_GE(r.path.size(), 2u);
  for (std::size_t i = 1; i < r.path.size(); ++i) // descent, with bounded steps
    EXPECT_LE((r.path[i].point - r.path[i - 1].point).norm(), 0.01 + 1e-15);
}

TEST(FixedPoint, StandardMapCentreIsEllipticWithTraceTwoMinusK) {
  for (double K : {0.5, 1.5, 3.0, 3.9}) {
    const auto m = test::makeModel("standard_map", {{"K", K}});
    const ReturnMap map(*m, test::everhartFactory(), order(1));
    const auto r = findFixedPoint(map, Eigen::Vector2d(3.1, 0.05), {});
    EXPECT_NEAR(r.point[0], pi, 1e-12);
    EXPECT_NEAR(std::remainder(r.point[1], 2 * pi), 0, 1e-12);
    EXPECT_EQ(r.type, FixedPointType::Elliptic) << "K = " << K;
    EXPECT_NEAR((r.multipliers[0] + r.multipliers[1]).real(), 2 - K, 1e-9);
    EXPECT_NEAR(std::abs(r.multipliers[0]), 1, 1e-9);
  }
  const auto m = test::makeModel("standard_map", {{"K", 4.5}});
  const auto r =
      findFixedPoint(ReturnMap(*m, test::everhartFactory(), order(1)), Eigen::Vector2d(3.1, 0.05), {});
  EXPECT_EQ(r.type, FixedPointType::HyperbolicWithReflection);
  // the saddle at the origin, approached across the seam of the torus
  const auto m1 = test::makeModel("standard_map", {{"K", 1.5}});
  const auto o =
      findFixedPoint(ReturnMap(*m1, test::everhartFactory(), order(1)), Eigen::Vector2d(6.2, 0.05), {});
  EXPECT_NEAR(std::remainder(o.point[0], 2 * pi), 0, 1e-12);
  EXPECT_EQ(o.type, FixedPointType::Hyperbolic);
  EXPECT_NEAR((o.multipliers[0] + o.multipliers[1]).real(), 2 + 1.5, 1e-9);
}

TEST(FixedPoint, HenonHeilesStraightLineOrbitByNewton) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const ReturnMap map(*m, test::everhartFactory(), order(1));
  FixedPointSettings fd, var;
  var.derivatives.method = DerivativeMethod::Variational;
  const auto a = findFixedPoint(map, Eigen::Vector2d(0.03, 0.22), fd);
  const auto b = findFixedPoint(map, Eigen::Vector2d(0.03, 0.22), var);
  for (const auto* r : {&a, &b}) {
    // the line at 30 degrees through the origin, crossed at speed sqrt(2E) = 1/2: py = 1/2 sin 30
    EXPECT_NEAR(r->point[0], 0, 1e-9);
    EXPECT_NEAR(r->point[1], 0.25, 1e-9);
    EXPECT_EQ(r->type, FixedPointType::Elliptic);
    for (auto l : r->multipliers)
      EXPECT_NEAR(std::abs(l), 1, 1e-6);
  }
  EXPECT_LT((a.jacobian - b.jacobian).norm(), 1e-6) << a.jacobian << "\n\n" << b.jacobian;
}

// the variational derivative with the section correction equals finite differences on Poincare maps of the
// rolling bodies (2D and 3D maps)
TEST(ReturnMap, VariationalDerivativeMatchesFiniteDifferences) {
  struct Case {
    const char* id;
    std::vector<double> point;
  };
  for (const Case& c : {Case{"chaplygin_ball", {0.5, 0.2}}, Case{"ellipsoid_on_plane", {0.3, 0.4, 0.2}}}) {
    const auto m = test::makeModel(c.id, {});
    const ReturnMap map(*m, test::everhartFactory(0.02), order(1));
    const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(c.point.data(), c.point.size());
    DerivativeSettings fd;
    fd.linearRegion = 1e-4;
    DerivativeSettings var{.method = DerivativeMethod::Variational};
    const auto a = map.linearize(x, fd), b = map.linearize(x, var);
    EXPECT_LT(map.difference(a.image, b.image).norm(), 1e-10) << c.id;
    EXPECT_LT((a.jacobian - b.jacobian).norm(), 1e-6 * (1 + a.jacobian.norm()))
        << c.id << "\nFD:\n"
        << a.jacobian << "\nvariational:\n"
        << b.jacobian;
  }
}

TEST(FixedPoint, FailuresSayWhy) {
  const auto m = test::makeModel("henon_map", {});
  const ReturnMap map(*m, test::everhartFactory(), order(1));
  FixedPointSettings s;
  s.maxIterations = 2;
  s.maxDistance = 1e-3;
  try {
    findFixedPoint(map, Eigen::Vector2d(0.2, 0.0), s);
    FAIL() << "no convergence expected";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("no convergence in 2 iterations"), std::string::npos) << e.what();
  }
  FixedPointSettings z;
  z.derivatives.method = DerivativeMethod::FiniteDifferences;
  z.derivatives.accuracy = 1e-30; // a linear approximation never agrees this well: the step reaches zero
  z.derivatives.zero = 1e-6;
  try {
    findFixedPoint(map, Eigen::Vector2d(0.6, 0.2), z);
    FAIL() << "the derivative step should reach zero";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("value of zero"), std::string::npos) << e.what();
  }
  EXPECT_THROW(findFixedPoint(map, Eigen::Vector3d(0.6, 0.2, 0), {}), InputError);
}

TEST(Continuation, StandardMapPeriodDoublingAtKEqualsFour) {
  ContinuationSettings s;
  s.parameter = "K";
  s.to = 4.5;
  s.step = 0.05;
  const Continuation::ModelAt at = [](double K) { return test::makeModel("standard_map", {{"K", K}}); };
  Continuation c(at, test::everhartFactory(), order(1), 1.5, Eigen::Vector2d(3.14159, 0), s);
  ASSERT_TRUE(c.run({}));
  ASSERT_EQ(c.points().size(), 61u);
  for (const auto& p : c.points())
    EXPECT_NEAR((p.fixedPoint.multipliers[0] + p.fixedPoint.multipliers[1]).real(), 2 - p.parameter, 1e-9);
  ASSERT_EQ(c.changes().size(), 1u);
  const TypeChange& t = c.changes()[0];
  EXPECT_EQ(t.kind, TypeChange::Kind::MultiplierMinusOne);
  EXPECT_EQ(describe(t, "K").substr(0, 17), "type change at K ");
  EXPECT_EQ(t.from, FixedPointType::Elliptic);
  EXPECT_EQ(t.to, FixedPointType::HyperbolicWithReflection);
  EXPECT_NEAR(t.parameter, 4.0, 1e-8);
  EXPECT_NEAR(c.points().back().parameter, 4.5, 1e-15);
}

TEST(Continuation, StopsAtTypeChangeAndRejectsAWrongDirection) {
  ContinuationSettings s;
  s.parameter = "K";
  s.to = 4.5;
  s.step = 0.1;
  s.stopAtTypeChange = true;
  const Continuation::ModelAt at = [](double K) { return test::makeModel("standard_map", {{"K", K}}); };
  Continuation c(at, test::everhartFactory(), order(1), 3.0, Eigen::Vector2d(3.1, 0), s);
  ASSERT_TRUE(c.run({}));
  EXPECT_NEAR(c.points().back().parameter, 4.1, 1e-12);
  s.step = -0.1;
  EXPECT_THROW(Continuation(at, test::everhartFactory(), order(1), 3.0, Eigen::Vector2d(3.1, 0), s),
               InputError);
}

// The Henon map x' = 1 - a x^2 + y, y' = b x has its fixed points on a x^2 + (1 - b) x - 1 = 0, y = b x: two
// for a > -(1 - b)^2 / 4, born in a fold there at x = 2 / (1 - b) (multipliers 1 and -b); the one that exists
// at a = 0 doubles at a = 3 (1 - b)^2 / 4.
ContinuationSettings henonFamily(double to, double step, ContinuationMethod method) {
  ContinuationSettings s;
  s.parameter = "a";
  s.to = to;
  s.step = step;
  s.method = method;
  return s;
}
Continuation::ModelAt henonAt(double b) {
  return [b](double a) { return test::makeModel("henon_map", {{"a", a}, {"b", b}}); };
}

TEST(Continuation, ArclengthPassesTheHenonFoldAndLocatesIt) {
  for (const double b : {0.3, -1.0}) {
    SCOPED_TRACE(b);
    const double fold = -(1 - b) * (1 - b) / 4;
    ContinuationSettings s = henonFamily(-2, -0.05, ContinuationMethod::Arclength);
    s.maxPoints = 120;
    const double x0 = 1 / (1 - b); // the point at a = 0
    Continuation c(henonAt(b), test::everhartFactory(), order(1), 0.0, Eigen::Vector2d(x0, b * x0), s);
    ASSERT_TRUE(c.run({}));
    // every point is a fixed point of its a; the family goes down to the fold, then up on the other root
    double lowest = 0;
    bool turned = false;
    for (std::size_t i = 0; i < c.points().size(); ++i) {
      const auto& p = c.points()[i];
      const double a = p.parameter, x = p.fixedPoint.point[0];
      EXPECT_NEAR(a * x * x + (1 - b) * x - 1, 0, 1e-9 * std::max(1.0, x * x)) << i;
      EXPECT_NEAR(p.fixedPoint.point[1], b * x, 1e-9 * std::max(1.0, std::abs(x))) << i;
      EXPECT_GE(a, fold - 1e-12) << i;
      if (i > 0 && a > c.points()[i - 1].parameter) turned = true;
      if (turned) {
        EXPECT_GT(x, 2 / (1 - b)) << "the other root after the fold, at " << i;
      }
      lowest = std::min(lowest, a);
    }
    EXPECT_TRUE(turned);
    EXPECT_LT(lowest, fold + 0.01);
    ASSERT_EQ(c.changes().size(), 1u);
    const TypeChange& t = c.changes()[0];
    EXPECT_EQ(t.kind, TypeChange::Kind::Fold);
    EXPECT_NEAR(t.parameter, fold, 1e-9);
    EXPECT_NEAR(t.at.fixedPoint.point[0], 2 / (1 - b), 1e-6);
    // a multiplier +1 there: the other is -b (both +1 at b = -1)
    const auto& m = t.at.fixedPoint.multipliers;
    const double nearOne = std::min(std::abs(m[0] - 1.0), std::abs(m[1] - 1.0));
    EXPECT_LT(nearOne, 1e-4);
    EXPECT_NEAR((m[0] * m[1]).real(), -b, 1e-9);
    EXPECT_EQ(describe(t, "a").substr(0, 10), "fold at a ");
    EXPECT_NE(c.end().find("120 points"), std::string::npos) << c.end();
    // b = 0.3: a saddle meets a stable node; b = -1 (area-preserving): a saddle meets an elliptic point
    EXPECT_EQ(t.from, b > 0 ? FixedPointType::StableNode : FixedPointType::Elliptic);
    EXPECT_EQ(t.to, FixedPointType::Hyperbolic);
  }
}

TEST(Continuation, NaturalStopsAtTheHenonFoldWhereArclengthGoesOn) {
  const double b = 0.3, x0 = 1 / (1 - b);
  Continuation natural(henonAt(b), test::everhartFactory(), order(1), 0.0, Eigen::Vector2d(x0, b * x0),
                       henonFamily(-0.5, -0.01, ContinuationMethod::Natural));
  EXPECT_THROW(natural.run({}), ComputationError);
  EXPECT_LT(natural.points().back().parameter, -0.12);
  EXPECT_GT(natural.points().back().parameter, -0.1225 - 1e-8);
}

TEST(Continuation, BothMethodsLocateTheHenonPeriodDoubling) {
  for (const double b : {0.3, -1.0}) {
    for (const auto method : {ContinuationMethod::Natural, ContinuationMethod::Arclength}) {
      SCOPED_TRACE(b);
      const double x0 = 1 / (1 - b);
      Continuation c(henonAt(b), test::everhartFactory(), order(1), 0.0, Eigen::Vector2d(x0, b * x0),
                     henonFamily(3.5, 0.05, method));
      ASSERT_TRUE(c.run({}));
      ASSERT_EQ(c.changes().size(), 1u);
      EXPECT_EQ(c.changes()[0].kind, TypeChange::Kind::MultiplierMinusOne);
      EXPECT_NEAR(c.changes()[0].parameter, 3 * (1 - b) * (1 - b) / 4, 1e-9);
      EXPECT_NEAR(c.points().back().parameter, 3.5, 1e-15);
      EXPECT_NE(c.end().find("reached a = 3.5"), std::string::npos) << c.end();
    }
  }
}

TEST(Continuation, TheDoubledFamilyStartsAtALocatedPeriodDoubling) {
  // Henon, b = 0.3: continued down from a = 1.4, the point doubles at a = 3 (1 - b)^2 / 4; its 2-cycle
  // (x1, x2) has x1 + x2 = (1 - b) / a, x1 x2 = ((1 - b)^2 - a) / a^2 and lives at larger a, so the doubled
  // family is continued back up to the parent's start
  const double b = 0.3;
  for (const auto method : {ContinuationMethod::Natural, ContinuationMethod::Arclength}) {
    Continuation parent(henonAt(b), test::everhartFactory(), order(1), 1.4, Eigen::Vector2d(0.63, 0.19),
                        henonFamily(0, -0.05, method));
    ASSERT_TRUE(parent.run({}));
    ASSERT_EQ(parent.changes().size(), 1u);
    const auto doubled = parent.doubledFamily(parent.changes()[0], 0.05, henonFamily(0, 0.05, method), {});
    std::size_t reported = 0;
    ASSERT_TRUE(doubled->run({}, [&](const ContinuationPoint&) { ++reported; }));
    EXPECT_EQ(reported, doubled->points().size());
    EXPECT_GT(doubled->points().size(), 15u);
    EXPECT_LT(doubled->points().front().parameter, 0.3675 + 0.01);
    EXPECT_NEAR(doubled->points().back().parameter, 1.4, 1e-12);
    for (const auto& p : doubled->points()) {
      const double a = p.parameter, x = p.fixedPoint.point[0], sum = (1 - b) / a;
      EXPECT_NEAR(x * x - sum * x + ((1 - b) * (1 - b) - a) / (a * a), 0, 1e-9) << a;
      EXPECT_NEAR(p.fixedPoint.point[1], b * (sum - x), 1e-9) << a;
      EXPECT_GT(std::abs(x - (sum - x)), 1e-3) << "not the parent at " << a;
    }
    // the 2-cycle (D Map^2: trace 4 a^2 x1 x2 + 2 b, det b^2) doubles in turn where 1 + trace + det = 0, at
    // a = (1 - b)^2 + (1 + b)^2 / 4 = 0.9125
    std::vector<double> doublings;
    for (const auto& c : doubled->changes())
      if (c.kind == TypeChange::Kind::MultiplierMinusOne) doublings.push_back(c.parameter);
    ASSERT_EQ(doublings.size(), 1u);
    EXPECT_NEAR(doublings[0], 0.9125, 1e-8);
    EXPECT_THROW(parent.doubledFamily(parent.changes()[0], -1, henonFamily(0, 0.05, method), {}), InputError);
  }
}

TEST(Continuation, ArclengthReachesTheFiniteValueAlongAStraightFamily) {
  // the standard map's centre theta = pi, p = 0 for every K: a straight family; steps of at most 0.2
  const Continuation::ModelAt at = [](double K) { return test::makeModel("standard_map", {{"K", K}}); };
  ContinuationSettings s;
  s.parameter = "K";
  s.to = 3;
  s.step = 0.2;
  s.method = ContinuationMethod::Arclength;
  Continuation c(at, test::everhartFactory(), order(1), 1.0, Eigen::Vector2d(3.1, 0.01), s);
  ASSERT_TRUE(c.run({}));
  for (const auto& p : c.points()) {
    EXPECT_NEAR(p.fixedPoint.point[0], pi, 1e-10);
    EXPECT_NEAR((p.fixedPoint.multipliers[0] + p.fixedPoint.multipliers[1]).real(), 2 - p.parameter, 1e-9);
  }
  EXPECT_NEAR(c.points().back().parameter, 3, 1e-15);
  EXPECT_GE(c.points().size(), 11u);
  s.maxPoints = 1;
  EXPECT_THROW(Continuation(at, test::everhartFactory(), order(1), 1.0, Eigen::Vector2d(3.1, 0.01), s),
               InputError);
}

TEST(Continuation, ArclengthEndsWhereTheFamilyTurnsBackToTheStartValue) {
  // b = 0.3 from the point x = 2 at a = -0.1 down toward a = -0.5: the family turns at the fold a = -0.1225
  // and comes back to a = -0.1 on the other root, x = 5, where it ends
  const double b = 0.3;
  Continuation c(henonAt(b), test::everhartFactory(), order(1), -0.1, Eigen::Vector2d(2, 2 * b),
                 henonFamily(-0.5, -0.005, ContinuationMethod::Arclength));
  ASSERT_TRUE(c.run({}));
  EXPECT_NEAR(c.points().back().parameter, -0.1, 1e-15);
  EXPECT_NEAR(c.points().back().fixedPoint.point[0], 5, 1e-10);
  EXPECT_NE(c.end().find("returned to the start value a = -0.1"), std::string::npos) << c.end();
  ASSERT_EQ(c.changes().size(), 1u);
  EXPECT_EQ(c.changes()[0].kind, TypeChange::Kind::Fold);
}

// The Henon map's fold and period-doubling curves in the (a, b) plane: a = -(1 - b)^2 / 4 with the point
// x = 2 / (1 - b), and a = 3 (1 - b)^2 / 4 with x = 2 / (3 (1 - b)); along the fold curve the other
// multiplier is -b, along the doubling curve b, so at b = -1 (area-preserving) both meet a second multiplier
// (+1 and -1: the 1:1 and 1:2 resonances).
TEST(BifurcationCurve, HenonFoldAndPeriodDoublingCurvesFollowTheirFormulas) {
  const ModelAt2 at = [](double a, double b) { return test::makeModel("henon_map", {{"a", a}, {"b", b}}); };
  for (const auto kind : {CurveKind::Fold, CurveKind::PeriodDoubling}) {
    SCOPED_TRACE(toString(kind));
    const bool fold = kind == CurveKind::Fold;
    const auto aOf = [&](double b) { return (fold ? -0.25 : 0.75) * (1 - b) * (1 - b); };
    const auto xOf = [&](double b) { return (fold ? 2.0 : 2.0 / 3) / (1 - b); };
    BifurcationCurveSettings s;
    s.kind = kind;
    s.first = "a", s.second = "b";
    s.step = 0.05;
    s.secondMin = -1.1, s.secondMax = 0.6;
    const double b0 = 0.3;
    // a start slightly off the curve is corrected onto it
    const Eigen::Vector2d guess(xOf(b0) + 0.01, b0 * xOf(b0));
    const BifurcationCurveResult r =
        bifurcationCurve(at, test::everhartFactory(), order(1), aOf(b0) + 0.001, b0, guess, s);
    ASSERT_GT(r.points.size(), 30u);
    for (const auto& p : r.points) {
      EXPECT_NEAR(p.first, aOf(p.second), 1e-8) << p.second;
      EXPECT_NEAR(p.fixedPoint.point[0], xOf(p.second), 1e-8) << p.second;
      EXPECT_NEAR(p.fixedPoint.point[1], p.second * xOf(p.second), 1e-8) << p.second;
    }
    // from one side of the box to the other, in order along the curve
    EXPECT_NEAR(std::min(r.points.front().second, r.points.back().second), -1.1, 1e-12);
    EXPECT_NEAR(std::max(r.points.front().second, r.points.back().second), 0.6, 1e-12);
    EXPECT_NE(r.end.find("b = 0.6 reached"), std::string::npos) << r.end;
    EXPECT_NE(r.end.find("b = -1.1 reached"), std::string::npos) << r.end;
    for (std::size_t i = 1; i < r.points.size(); ++i)
      EXPECT_LT(std::abs(r.points[i].second - r.points[i - 1].second), 0.05 + 1e-12);
    // the second multiplier reaches +1 (fold) or -1 (doubling) at b = -1
    ASSERT_EQ(r.events.size(), 1u);
    const CurveEvent& e = r.events[0];
    EXPECT_NE(e.what.find(fold ? "second multiplier +1" : "second multiplier -1"), std::string::npos)
        << e.what;
    EXPECT_NEAR(e.at.second, -1, 1e-8);
    EXPECT_NEAR(e.at.first, aOf(-1), 1e-8);
  }
}

TEST(BifurcationCurve, RefusesAStartOffAnyCurveAndBadSettings) {
  const ModelAt2 at = [](double a, double b) { return test::makeModel("henon_map", {{"a", a}, {"b", b}}); };
  BifurcationCurveSettings s;
  s.first = "a", s.second = "b";
  s.kind = CurveKind::PeriodDoubling;
  // the Henon map's Jacobian has det = -b: at b = 0.3 no pair of multipliers has a product of 1, so there is
  // no Neimark-Sacker curve to start on
  s.kind = CurveKind::NeimarkSacker;
  try {
    bifurcationCurve(at, test::everhartFactory(), order(1), 1.4, 0.3, Eigen::Vector2d(0.63, 0.19), s);
    ADD_FAILURE() << "a Neimark-Sacker curve of the Henon map at b = 0.3";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("no Neimark-Sacker curve through a = 1.4, b = 0.3"),
              std::string::npos)
        << e.what();
  }
  s.kind = CurveKind::PeriodDoubling;
  s.second = "a";
  EXPECT_THROW(
      bifurcationCurve(at, test::everhartFactory(), order(1), 0.3675, 0.3, Eigen::Vector2d(0.95, 0.29), s),
      InputError);
  s.second = "b";
  s.step = 0;
  EXPECT_THROW(
      bifurcationCurve(at, test::everhartFactory(), order(1), 0.3675, 0.3, Eigen::Vector2d(0.95, 0.29), s),
      InputError);
}

} // namespace
} // namespace rv

namespace rv {
namespace {

// The area-preserving Henon map (b = -1) has the fixed point x = (sqrt(1 + a) - 1) / a with trace
// 2 - 2 sqrt(1 + a): it doubles at a = 3. Its 2-cycle has x1 + x2 = 2 / a, x1 x2 = (4 - a) / a^2 and
// tr D(P^2) = 4 a^2 x1 x2 - 2 = 14 - 4a: it doubles at a = 4. (The standard map's 2-cycle does not double:
// its trace touches -2 and turns back, which the tree correctly ignores.)
// the area-preserving Henon map at a, and a tree in a up to `to` with steps of 0.05
const Continuation::ModelAt areaPreservingHenon = [](double a) {
  return test::makeModel("henon_map", {{"a", a}, {"b", -1}});
};
BifurcationTreeSettings henonTree(double to, int levels) {
  BifurcationTreeSettings s;
  s.continuation.parameter = "a";
  s.continuation.to = to;
  s.continuation.step = 0.05;
  s.maxLevels = levels;
  return s;
}

TEST(BifurcationTree, AreaPreservingHenonCascadeMatchesTheAnalyticFirstTwoDoublings) {
  const BifurcationTreeSettings s = henonTree(4.2, 2);
  const Continuation::ModelAt& at = areaPreservingHenon;
  const auto r = bifurcationTree(at, test::everhartFactory(), order(1), 2.0, Eigen::Vector2d(0.4, -0.4), s);
  ASSERT_GE(r.doublings.size(), 2u);
  EXPECT_NEAR(r.doublings[0].parameter, 3.0, 1e-8);
  EXPECT_EQ(r.doublings[0].order, 1);
  EXPECT_NEAR(r.doublings[1].parameter, 4.0, 1e-8);
  EXPECT_EQ(r.doublings[1].order, 2);
  ASSERT_GE(r.branches.size(), 2u);
  EXPECT_EQ(r.branches[1].order, 2);
  for (const auto& p : r.branches[1].points) { // on the analytic 2-cycle: its partner is (-y, ...)
    const double a = p.parameter, x1 = p.fixedPoint.point[0], x2 = -p.fixedPoint.point[1];
    EXPECT_NEAR(x1 + x2, 2 / a, 1e-9) << "a = " << a;
    EXPECT_NEAR(x1 * x2, (4 - a) / (a * a), 1e-9) << "a = " << a;
  }
  if (r.doublings.size() >= 3) { // the period-4 orbit doubles a little later (Feigenbaum's ratio ~ 8.7)
    EXPECT_GT(r.doublings[2].parameter, 4.0);
    EXPECT_LT(r.doublings[2].parameter, 4.2);
  }
}

// The cascade to the limit of double precision, from the elliptic point at a = 2.5 (issue 15): every
// bifurcation value against 40-digit values of an independent formulation (the orbit as a cyclic recurrence
// x_{n+1} + x_{n-1} = 1 - a x_n^2 and tr M = -2, solved jointly by Newton in mpmath:
// tests/dynamics/reference/henon_cascade.py). Each doubled family must be of its minimal order: before the
// check, Newton near the pitchfork of Map^16 fell back onto the order-8 orbit and the tree stopped at four.
TEST(BifurcationTree, AreaPreservingHenonCascadeReachesOrder64AndFeigenbaumsRatio) {
  const BifurcationTreeSettings s = henonTree(5, 6);
  const Continuation::ModelAt& at = areaPreservingHenon;
  const auto r = bifurcationTree(at, test::everhartFactory(), order(1), 2.5, Eigen::Vector2d(0.35, -0.35), s);
  const double reference[] = {3.0,
                              4.0,
                              4.1204524973184659888,
                              4.1343639124567984248,
                              4.1359600588032131131,
                              4.1361430974114378415,
                              4.1361640856087688651};
  ASSERT_EQ(r.doublings.size(), 7u) << r.end;
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(r.doublings[k].order, 1 << k);
    EXPECT_NEAR(r.doublings[k].parameter, reference[k], 1e-9) << "order " << (1 << k);
  }
  const auto ratios = r.ratios();
  ASSERT_EQ(ratios.size(), 5u);
  EXPECT_NEAR(ratios[2], 8.72, 0.05);
  EXPECT_NEAR(ratios[4], 8.7210972, 2e-4); // Greene, MacKay, Vivaldi & Feigenbaum 1981
  EXPECT_NE(r.end.find("levels"), std::string::npos) << r.end;
  for (const auto& b : r.branches) { // no point of a doubled family is its parent counted twice
    if (b.order < 2) continue;
    SectionSettings half = order(b.order / 2);
    for (const auto& p : b.points) {
      const auto m = at(p.parameter);
      const ReturnMap map(*m, test::everhartFactory(), half);
      EXPECT_GT(map.difference(map(p.fixedPoint.point), p.fixedPoint.point).norm(), 1e-8)
          << "order " << b.order << " at a = " << p.parameter;
    }
  }
}

TEST(BifurcationTree, RefusesAHyperbolicStart) {
  BifurcationTreeSettings s;
  s.continuation.parameter = "K";
  s.continuation.to = 2;
  s.continuation.step = 0.1;
  const Continuation::ModelAt at = [](double K) { return test::makeModel("standard_map", {{"K", K}}); };
  try {
    bifurcationTree(at, test::everhartFactory(), order(1), 1.0, Eigen::Vector2d(0.01, 0.01), s);
    FAIL();
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("not elliptic"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace rv

namespace rv {
namespace {

// A balanced ball through the generic rigid body on a plane (a 3D map l, L/G, H/G) is the Chaplygin ball
// (a 2D map at fixed c): H/G is conserved, so the 3D map has a unit multiplier and a line of fixed points;
// the "2D section" search at the Chaplygin point's H/G must land on the Chaplygin point, with the same other
// multipliers. Two independent formulations, one answer.
TEST(FixedPoint, SectionModeOnA3DMapMatchesTheChaplyginBallsFixedPoint) {
  const auto ball =
      test::makeModel("chaplygin_ball", {{"K1", 0}, {"K2", 0}, {"K3", 0}, {"c", 0.3}, {"energy", 0.5}});
  const ReturnMap map2(*ball, test::everhartFactory(0.02), order(1));
  const auto a = findFixedPoint(map2, Eigen::Vector2d(4.5, 0.0), {});
  ASSERT_EQ(a.type, FixedPointType::Elliptic);
  const Eigen::VectorXd s = ball->stateFromMap({a.point[0], a.point[1]}, {}, "test");
  const Eigen::Vector3d M = s.head<3>(), g = s.segment<3>(3);
  const double HG = M.dot(g) / M.norm();

  const auto body = test::makeModel("ellipsoid_on_plane", {{"I1", 1.0},
                                                           {"I2", 1.4},
                                                           {"I3", 1.9},
                                                           {"m", 1.0},
                                                           {"g", 0.0},
                                                           {"b1", 1.0},
                                                           {"b2", 1.0},
                                                           {"b3", 1.0},
                                                           {"a1", 0.0},
                                                           {"a2", 0.0},
                                                           {"a3", 0.0},
                                                           {"phi", 0.0},
                                                           {"theta", 0.0},
                                                           {"psi", 0.0},
                                                           {"energy", 0.5}});
  const ReturnMap map3(*body, test::everhartFactory(0.02), order(1));
  ASSERT_EQ(map3.dimension(), 3);
  FixedPointSettings sec;
  sec.section2D = true;
  const auto b = findFixedPoint(map3, Eigen::Vector3d(4.5, 0.0, HG), sec);
  EXPECT_NEAR(b.point[0], a.point[0], 1e-8);
  EXPECT_NEAR(b.point[1], a.point[1], 1e-8);
  EXPECT_NEAR(b.point[2], HG, 1e-14) << "the search stays on the plane z = const";
  ASSERT_EQ(b.multipliers.size(), 3u);
  int unit = 0;
  for (auto m : b.multipliers)
    unit += std::abs(m - 1.0) < 1e-6;
  EXPECT_EQ(unit, 1) << "H/G is conserved: one multiplier is 1";
  EXPECT_EQ(b.type, FixedPointType::Elliptic);
  for (auto m : a.multipliers) { // the others are the Chaplygin map's
    double best = 1e9;
    for (auto n : b.multipliers)
      best = std::min(best, std::abs(m - n));
    EXPECT_LT(best, 1e-6);
  }
}

} // namespace
} // namespace rv
