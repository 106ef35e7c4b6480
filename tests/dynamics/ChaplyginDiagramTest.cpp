// ChaplyginDiagramTest.cpp -- the bifurcation diagrams of the Chaplygin ball with a gyrostat (manual §3.5.1,
// corrected as design.md says) against the integral map (h, C, |gamma|^2, n) of the model itself:
//  - each branch point is the value of a critical point: the state built for it (a uniform rotation) has a
//    rank-deficient Jacobian of the model's integrals, found by finite differences;
//  - at fixed (n, c), the critical values of h on the level set, found by a blind search (no formula), are
//    exactly the branch values there, and the manual's printed (31)-(32) (I in place of J) fail this;
//  - tau's ends are the extremes of h on the sphere M = c gamma - K, found by brute force;
//  - integrated trajectories stay between the lowest and highest branch crossing their n (taken from the
//    Diagram objects the GUI draws), and these are the extremes of h on the level set.
#include "dynamics/models/ChaplyginDiagram.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/models/ChaplyginBall.h"
#include "tests/dynamics/TestSupport.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace rv {
namespace {

using V3 = Eigen::Vector3d;
using V6 = Eigen::Matrix<double, 6, 1>;
constexpr double kPi = std::numbers::pi;

// a ball and its area constant
struct Case {
  const char* name;
  V3 I;
  double m, R;
  V3 K;
  double c;
  double D() const { return m * R * R; }
  ChaplyginBifurcationSet set() const { return {I, D(), K}; }
};

const Case kGeneric{"generic", {1.0, 1.4, 1.9}, 1.3, 0.8, {0.2, -0.1, 0.3}, 0.3};
const Case kZeroC{"c = 0", {1.0, 1.4, 1.9}, 1.3, 0.8, {0.2, -0.1, 0.3}, 0.0};
const Case kZeroK3{"K3 = 0", {1.0, 1.4, 1.9}, 1.3, 0.8, {0.2, -0.1, 0.0}, 0.3};
const Case kZeroK2BigC{"K2 = 0, c^2 > (K, K)", {1.2, 1.5, 2.1}, 1.0, 1.0, {0.3, 0.0, 0.25}, 0.8};
const Case kZeroK2HugeC{"K2 = 0, c = 2", {1.2, 1.5, 2.1}, 1.0, 1.0, {0.3, 0.0, 0.25}, 2.0};
const Case kScene{"scene", {1.0, 1.4, 1.9}, 1.0, 1.0, {0.2, 0.1, 0.3}, 0.3}; // scenes/chaplygin_ball.json

std::unique_ptr<Model> makeBall(const Case& k, double diagramN = 1.0, double energy = 0.5) {
  const ModelEntry& e = ModelRegistry::global().get("chaplygin_ball");
  ParameterValues p(e.info->parameters);
  const char* names[3][2] = {{"I1", "K1"}, {"I2", "K2"}, {"I3", "K3"}};
  for (int i = 0; i < 3; ++i)
    p.set(names[i][0], k.I[i]), p.set(names[i][1], k.K[i]);
  p.set("m", k.m), p.set("R", k.R), p.set("c", k.c), p.set("diagram_n", diagramN), p.set("energy", energy);
  return e.create(p);
}

// the model's integrals (h, C, |gamma|^2, n) at y = (M, gamma), gamma not normalised
Eigen::Vector4d integralsAt(const Model& m, const V6& y) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m.dimension());
  x.head<6>() = y;
  return m.integrals(x.data());
}

// d(h, C, |gamma|^2, n)/d(M, gamma) by fourth-order central differences
Eigen::Matrix<double, 4, 6> integralJacobian(const Model& m, const V6& y, double step = 1e-3) {
  Eigen::Matrix<double, 4, 6> J;
  for (int k = 0; k < 6; ++k) {
    const auto at = [&](double d) {
      V6 z = y;
      z[k] += d;
      return integralsAt(m, z);
    };
    J.col(k) = (8 * (at(step) - at(-step)) - (at(2 * step) - at(-2 * step))) / (12 * step);
  }
  return J;
}

// the smallest singular value of the Jacobian with unit rows: 0 exactly where the integrals are dependent
double rankDefect(const Model& m, const V6& y) {
  Eigen::Matrix<double, 4, 6> J = integralJacobian(m, y);
  for (int r = 0; r < 4; ++r)
    J.row(r).normalize();
  return Eigen::JacobiSVD<Eigen::Matrix<double, 4, 6>>(J).singularValues()[3];
}

// how far grad h is from the span of grad C, grad |gamma|^2, grad n (squared, relative): 0 at critical points
// of h on the level set of the other three
double criticality(const Model& m, const V6& y, double step = 1e-3) {
  const Eigen::Matrix<double, 4, 6> J = integralJacobian(m, y, step);
  const Eigen::Matrix<double, 6, 3> A = J.bottomRows<3>().transpose();
  const V6 gh = J.row(0).transpose();
  const V6 r = gh - A * A.colPivHouseholderQr().solve(gh);
  return r.squaredNorm() / gh.squaredNorm();
}

// a point of the level set {|gamma| = 1, (P, gamma) = c, |P|^2 = n}, P = M + K: gamma at the angles (theta,
// phi), P - c gamma turned by psi about gamma
V6 onLevel(const V3& K, double n, double c, const V3& a) {
  const double th = a[0], ph = a[1], ps = a[2];
  const V3 g(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  const V3 e1(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), -std::sin(th)), e2 = g.cross(e1);
  const V3 P = c * g + std::sqrt(std::max(0.0, n - c * c)) * (std::cos(ps) * e1 + std::sin(ps) * e2);
  V6 y;
  y << P - K, g;
  return y;
}

// Nelder-Mead in three variables, restarted from the best vertex until it stops improving
template <class F> V3 nelderMead(const F& f, V3 x, double size) {
  for (int restart = 0; restart < 4; ++restart, size *= 0.1) {
    std::array<V3, 4> p;
    std::array<double, 4> v;
    for (int i = 0; i < 4; ++i) {
      p[i] = x;
      if (i > 0) p[i][i - 1] += size;
      v[i] = f(p[i]);
    }
    for (int it = 0; it < 3000; ++it) {
      std::array<int, 4> o{0, 1, 2, 3};
      std::sort(o.begin(), o.end(), [&](int a, int b) { return v[a] < v[b]; });
      const int best = o[0], worst = o[3], second = o[2];
      double diam = 0;
      for (int i = 1; i < 4; ++i)
        diam = std::max(diam, (p[o[i]] - p[best]).norm());
      if (diam < 1e-14) break;
      const V3 centre = (p[o[0]] + p[o[1]] + p[o[2]]) / 3;
      const V3 r = centre + (centre - p[worst]);
      const double fr = f(r);
      if (fr < v[best]) {
        const V3 e = centre + 2 * (centre - p[worst]);
        const double fe = f(e);
        fe < fr ? (p[worst] = e, v[worst] = fe) : (p[worst] = r, v[worst] = fr);
      } else if (fr < v[second]) {
        p[worst] = r, v[worst] = fr;
      } else {
        const V3 k = centre + 0.5 * (p[worst] - centre);
        const double fk = f(k);
        if (fk < v[worst]) {
          p[worst] = k, v[worst] = fk;
        } else {
          for (int i = 1; i < 4; ++i)
            p[o[i]] = p[best] + 0.5 * (p[o[i]] - p[best]), v[o[i]] = f(p[o[i]]);
        }
      }
    }
    x = p[std::min_element(v.begin(), v.end()) - v.begin()];
  }
  return x;
}

// a grid over the level set's angles, with the value of f at each node, and the nodes that are no worse than
// their six neighbours
struct Grid {
  int nt, np, ns;
  std::vector<double> f;
  V3 angles(int i, int j, int k) const {
    return {(i + 0.5) * kPi / nt, (j + 0.37) * 2 * kPi / np, (k + 0.21) * 2 * kPi / ns};
  }
  template <class F> Grid(int nt_, int np_, int ns_, const F& fn) : nt(nt_), np(np_), ns(ns_) {
    f.resize(std::size_t(nt) * np * ns);
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < np; ++j)
        for (int k = 0; k < ns; ++k)
          f[idx(i, j, k)] = fn(angles(i, j, k));
  }
  std::size_t idx(int i, int j, int k) const {
    return (std::size_t(i) * np + (j + np) % np) * ns + (k + ns) % ns;
  }
  std::vector<V3> localMinima() const {
    std::vector<V3> out;
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < np; ++j)
        for (int k = 0; k < ns; ++k) {
          const double v = f[idx(i, j, k)];
          bool low = v <= f[idx(i, j + 1, k)] && v <= f[idx(i, j - 1, k)] && v <= f[idx(i, j, k + 1)] &&
                     v <= f[idx(i, j, k - 1)];
          if (i > 0) low = low && v <= f[idx(i - 1, j, k)];
          if (i + 1 < nt) low = low && v <= f[idx(i + 1, j, k)];
          if (low) out.push_back(angles(i, j, k));
        }
    return out;
  }
};

// distinct values (within tol), ascending
std::vector<double> distinct(std::vector<double> v, double tol) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > tol) out.push_back(x);
  return out;
}

double distanceTo(const std::vector<double>& set, double x) {
  double d = INFINITY;
  for (double s : set)
    d = std::min(d, std::abs(s - x));
  return d;
}

// the critical values of h on the level set {|gamma| = 1, C = c, n}, by a blind search: local minima of the
// criticality on a grid, refined by Nelder-Mead, kept when it vanishes
std::vector<double> criticalValuesOfH(const Model& m, const V3& K, double n, double c) {
  const auto crit = [&](const V3& a) { return criticality(m, onLevel(K, n, c, a)); };
  const Grid grid(20, 40, 40, [&](const V3& a) { return criticality(m, onLevel(K, n, c, a), 1e-4); });
  std::vector<double> values;
  for (const V3& a0 : grid.localMinima()) {
    const V3 a = nelderMead(crit, a0, 0.05);
    if (crit(a) < 1e-18) values.push_back(integralsAt(m, onLevel(K, n, c, a))[0]);
  }
  return distinct(values, 1e-9);
}

// the least and greatest h on the level set, by brute force (grid, then Nelder-Mead from the best nodes)
std::pair<double, double> extremesOfH(const Model& m, const V3& K, double n, double c) {
  const auto h = [&](const V3& a) { return integralsAt(m, onLevel(K, n, c, a))[0]; };
  double lo = INFINITY, hi = -INFINITY;
  for (const double sign : {1.0, -1.0}) {
    const auto f = [&](const V3& a) { return sign * h(a); };
    const Grid grid(16, 32, 32, f);
    std::vector<V3> starts = grid.localMinima();
    for (const V3& a0 : starts) {
      const double v = h(nelderMead(f, a0, 0.05));
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
  }
  return {lo, hi};
}

// the values at n of a curve lambda -> (n, h) over the whole real line cut at its poles: sign changes of
// n(lambda) - n on a dense grid (uniform on finite intervals, in arctan on the infinite ones), then bisection
template <class Sigma>
std::vector<double> crossings(const Sigma& sigma, const std::vector<double>& poles, double n, double scale) {
  std::vector<double> edges{-INFINITY};
  edges.insert(edges.end(), poles.begin(), poles.end());
  edges.push_back(INFINITY);
  std::vector<double> out;
  for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
    const double a = edges[e], b = edges[e + 1];
    const auto lambda = [&](double u) { // u in (0, 1)
      if (std::isfinite(a) && std::isfinite(b)) return a + (b - a) * u;
      if (std::isfinite(a)) return a + scale * std::tan(kPi / 2 * u);
      if (std::isfinite(b)) return b - scale * std::tan(kPi / 2 * (1 - u));
      return scale * std::tan(kPi * (u - 0.5));
    };
    const int N = 40000;
    std::optional<DiagramPoint> prev;
    double uPrev = 0;
    for (int k = 1; k < N; ++k) {
      const double u = double(k) / N;
      const std::optional<DiagramPoint> p = sigma(lambda(u));
      if (p && prev && ((*p)[0] - n) * ((*prev)[0] - n) <= 0) {
        double lo = uPrev, hi = u;
        const bool lowBelow = (*prev)[0] < n;
        for (int it = 0; it < 200; ++it) {
          const double mid = 0.5 * (lo + hi);
          const auto q = sigma(lambda(mid));
          if (!q) break;
          (((*q)[0] < n) == lowBelow ? lo : hi) = mid;
        }
        if (const auto q = sigma(lambda(0.5 * (lo + hi)))) out.push_back((*q)[1]);
      }
      prev = p, uPrev = u;
    }
  }
  return out;
}

// the diagram's values at n (sigma, rays, sigma0) from the closed forms of the library
std::vector<double> branchValues(const Case& k, double n) {
  const ChaplyginBifurcationSet s = k.set();
  std::vector<double> v =
      crossings([&](double l) { return s.sigma(k.c, l); }, s.sigmaPoles(k.c), n, s.j().maxCoeff());
  for (int i = 0; i < 3; ++i)
    if (s.hasRay(i) && n >= s.rayMinN(i, k.c)) v.push_back(s.rayH(i, k.c, n));
  if (k.c == 0 && n <= s.sigma0MaxN()) v.push_back(s.sigma0H(n));
  return distinct(v, 1e-9);
}

// the manual's (31)-(32) as printed, with I where J belongs: the negative control
std::optional<DiagramPoint> printedSigma(const Case& k, double lambda) {
  double S = 0, T = 0;
  for (int i = 0; i < 3; ++i) {
    const double t = k.K[i] * k.K[i] / ((k.I[i] - lambda) * (k.I[i] - lambda));
    S += t, T += k.I[i] * t;
  }
  const double q = k.c * k.c / ((k.D() - lambda) * (k.D() - lambda));
  const double n = lambda * lambda * (S - q) + k.c * k.c;
  if (!(n > k.c * k.c) || !std::isfinite(n)) return std::nullopt;
  return DiagramPoint{n, 0.5 * (T - k.D() * q)};
}

std::vector<double> printedValues(const Case& k, double n) {
  std::vector<double> poles{k.I[0], k.I[1], k.I[2], k.D()};
  std::sort(poles.begin(), poles.end());
  return distinct(crossings([&](double l) { return printedSigma(k, l); }, poles, n, k.I.maxCoeff()), 1e-9);
}

// The critical points on sigma are uniform rotations: with omega_i = -K_i/(J_i - lambda) and
// s = (gamma, omega) = c/(lambda - D), gamma is any unit vector with (gamma, omega) = s and
// M + K = lambda omega - D s gamma. (`J` may be replaced by I to build the printed formula's states.)
std::optional<V6> uniformRotation(const V3& J, double D, const V3& K, double c, double lambda, double angle) {
  const V3 w = -K.cwiseQuotient(J - V3::Constant(lambda));
  const double s = c / (lambda - D), w2 = w.squaredNorm();
  if (!(s * s < w2)) return std::nullopt;
  V3 e = w.cross(V3(0.3, -0.5, 0.8)).normalized();
  e = std::cos(angle) * e + std::sin(angle) * w.normalized().cross(e); // anywhere on the circle
  const V3 g = s / w2 * w + std::sqrt(1 - s * s / w2) * e;
  V6 y;
  y << lambda * w - D * s * g - K, g;
  return y;
}

// lambdas spread over the intervals between the poles (the outer ones bounded at -+L)
std::vector<double> sampleLambdas(const std::vector<double>& poles, double L, int perInterval) {
  std::vector<double> edges{-L};
  edges.insert(edges.end(), poles.begin(), poles.end());
  edges.push_back(L);
  std::vector<double> out;
  for (std::size_t e = 0; e + 1 < edges.size(); ++e)
    for (int k = 1; k <= perInterval; ++k)
      out.push_back(edges[e] + (edges[e + 1] - edges[e]) * (k - 0.5 + 0.1 * std::sin(k)) / perInterval);
  return out;
}

TEST(ChaplyginDiagram, SigmaPointsAreValuesOfRankDeficientUniformRotations) {
  for (const Case& k : {kGeneric, kZeroC, kZeroK3, kZeroK2BigC}) {
    SCOPED_TRACE(k.name);
    const auto model = makeBall(k);
    const ChaplyginBifurcationSet s = k.set();
    int tested = 0;
    double worstValue = 0, worstRank = 0, wrongRank = INFINITY;
    for (const double lambda : sampleLambdas(s.sigmaPoles(k.c), 6 * s.j().maxCoeff(), 40)) {
      const auto p = s.sigma(k.c, lambda);
      const auto y = uniformRotation(s.j(), k.D(), k.K, k.c, lambda, 0.7 * lambda);
      ASSERT_EQ(p.has_value(), y.has_value()) << "lambda " << lambda; // Phi >= 0 iff a gamma exists
      if (!p) continue;
      const Eigen::Vector4d v = integralsAt(*model, *y);
      EXPECT_NEAR(v[1], k.c, 1e-12);
      EXPECT_NEAR(v[2], 1, 1e-12);
      worstValue = std::max({worstValue, std::abs(v[3] - (*p)[0]) / std::max(1.0, (*p)[0]),
                             std::abs(v[0] - (*p)[1]) / std::max(1.0, std::abs((*p)[1]))});
      worstRank = std::max(worstRank, rankDefect(*model, *y));
      ++tested;
      // the manual's I in place of J builds states that are not critical
      if (const auto bad = uniformRotation(k.I, k.D(), k.K, k.c, lambda, 0.7 * lambda))
        wrongRank = std::min(wrongRank, rankDefect(*model, *bad));
    }
    EXPECT_GE(tested, 20);
    EXPECT_LE(worstValue, test::tol(1e-12));
    EXPECT_LE(worstRank, test::tol(1e-9));
    EXPECT_GT(wrongRank, 1e-4);
    std::printf(
        "[ %s ] sigma: %d points, |(n, h) - branch| <= %.1e, rank defect <= %.1e (printed I: >= %.1e)\n",
        k.name, tested, worstValue, worstRank, wrongRank);
  }
}

TEST(ChaplyginDiagram, SigmaPointsAreUniformRotations) {
  // omega is constant in the body along these states: a relative equilibrium, seen through the flow
  const auto model = makeBall(kGeneric);
  const auto& ball = dynamic_cast<const ChaplyginBall&>(*model);
  const ChaplyginBifurcationSet s = kGeneric.set();
  int tested = 0;
  for (const double lambda : sampleLambdas(s.sigmaPoles(kGeneric.c), 6 * s.j().maxCoeff(), 10)) {
    const auto y = uniformRotation(s.j(), kGeneric.D(), kGeneric.K, kGeneric.c, lambda, 1.0);
    if (!y) continue;
    ++tested;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(16), f(16);
    x.head<6>() = *y;
    model->rhs(x.data(), f.data());
    const double eps = 1e-6;
    const auto omega = [&](double t) {
      const V6 z = *y + t * f.head<6>();
      return ball.angularVelocity<double>(V3(z.head<3>()), V3(z.tail<3>()));
    };
    EXPECT_LE((omega(eps) - omega(-eps)).norm() / (2 * eps), 1e-8 * omega(0).norm()) << lambda;
    EXPECT_GT(f.segment<3>(3).norm(), 1e-3) << "gamma moves"; // it is a rotation, not a rest point
  }
  EXPECT_GE(tested, 10);
}

TEST(ChaplyginDiagram, ChPointsAreValuesOfRankDeficientStatesAtFixedN) {
  for (const Case& k : {kGeneric, kZeroK3, kZeroK2BigC}) {
    SCOPED_TRACE(k.name);
    const double N = 1.7;
    const auto model = makeBall(k, N);
    const ChaplyginBifurcationSet s = k.set();
    int tested = 0;
    double worst = 0, worstRank = 0;
    for (const double lambda : sampleLambdas(s.sigmaPolesAtN(), 6 * s.j().maxCoeff(), 300)) {
      const auto pts = s.sigmaAtN(N, lambda);
      if (pts.empty()) continue;
      ASSERT_EQ(pts.size(), 2u);
      for (const DiagramPoint& p : pts) {
        const auto y = uniformRotation(s.j(), k.D(), k.K, p[0], lambda, 0.3);
        if (!y) {
          // only where s^2 = |omega|^2 within rounding, on the line n = c^2
          EXPECT_NEAR(p[0] * p[0], N, 1e-9);
          continue;
        }
        const Eigen::Vector4d v = integralsAt(*model, *y);
        worst = std::max({worst, std::abs(v[1] - p[0]), std::abs(v[3] - N), std::abs(v[0] - p[1])});
        worstRank = std::max(worstRank, rankDefect(*model, *y));
        ++tested;
      }
    }
    EXPECT_GE(tested, 20);
    EXPECT_LE(worst, test::tol(1e-11));
    EXPECT_LE(worstRank, test::tol(1e-9));
    std::printf("[ %s ] ch sigma at n = %g: %d points, |(c, n, h) - branch| <= %.1e, rank defect <= %.1e\n",
                k.name, N, tested, worst, worstRank);
  }
}

TEST(ChaplyginDiagram, Sigma0RaysAndT0AreValuesOfRankDeficientStates) {
  // sigma0: lambda = D at c = 0, s = (gamma, omega) anywhere in [-|omega|, |omega|]
  {
    const auto model = makeBall(kZeroC);
    const ChaplyginBifurcationSet s = kZeroC.set();
    const double D = kZeroC.D();
    const V3 w = -kZeroC.K.cwiseQuotient(kZeroC.I);
    for (const double f : {-0.999, -0.6, 0.0, 0.3, 0.95}) {
      const double sv = f * w.norm();
      const V3 e = w.cross(V3(1, 2, 3)).normalized();
      const V3 g = sv / w.squaredNorm() * w + std::sqrt(1 - f * f) * e;
      V6 y;
      y << D * w - D * sv * g - kZeroC.K, g;
      const Eigen::Vector4d v = integralsAt(*model, y);
      EXPECT_NEAR(v[1], 0, 1e-13);
      EXPECT_NEAR(v[0], s.sigma0H(v[3]), 1e-12) << f;
      EXPECT_GE(v[3], 0);
      EXPECT_LE(v[3], s.sigma0MaxN() * (1 + 1e-12));
      EXPECT_LE(rankDefect(*model, y), test::tol(1e-9)) << f;
    }
  }
  // sigma_i: lambda = J_i with K_i = 0, omega_i = w free; the ray starts where w^2 = max(0, c^2/I_i^2 - S_i)
  for (const auto& [k, i] : {std::pair{kZeroK3, 2}, std::pair{kZeroK2BigC, 1}, std::pair{kZeroK2HugeC, 1}}) {
    SCOPED_TRACE(k.name);
    const auto model = makeBall(k);
    const ChaplyginBifurcationSet s = k.set();
    ASSERT_TRUE(s.hasRay(i));
    const double Ji = k.I[i] + k.D(), sv = k.c / k.I[i];
    V3 w;
    double S = 0;
    for (int j = 0; j < 3; ++j)
      if (j != i) w[j] = -k.K[j] / (k.I[j] - k.I[i]), S += w[j] * w[j];
    const double wMin = std::sqrt(std::max(0.0, sv * sv - S));
    // (34) as printed starts the ray at c^2 + J_i^2 (S - c^2/I_i^2): below c^2 when c is large, where no
    // state exists at all (n >= c^2 always); the corrected start is where omega_i = wMin
    const double printedStart = k.c * k.c + Ji * Ji * (S - sv * sv);
    EXPECT_EQ(printedStart<k.c * k.c, wMin> 0);
    EXPECT_GE(s.rayMinN(i, k.c), k.c * k.c);
    for (const double extra : {0.0, 0.2, 0.9}) {
      w[i] = wMin + extra;
      const double w2 = w.squaredNorm();
      const V3 e = w.cross(V3(1, -2, 0.5)).normalized();
      const V3 g = sv / w2 * w + std::sqrt(std::max(0.0, 1 - sv * sv / w2)) * e;
      V6 y;
      y << Ji * w - k.D() * sv * g - k.K, g;
      const Eigen::Vector4d v = integralsAt(*model, y);
      EXPECT_NEAR(v[1], k.c, 1e-12);
      EXPECT_NEAR(v[2], 1, 1e-12);
      EXPECT_NEAR(v[0], s.rayH(i, k.c, v[3]), 1e-12);
      if (extra == 0) {
        EXPECT_NEAR(v[3], s.rayMinN(i, k.c), 1e-12) << "the ray starts here";
      }
      EXPECT_GE(v[3], s.rayMinN(i, k.c) - 1e-12);
      EXPECT_LE(rankDefect(*model, y), test::tol(1e-9)) << extra;
    }
  }
  // T0: M = 0 with (K, gamma) = c
  {
    const auto model = makeBall(kGeneric);
    const V3 K = kGeneric.K, e = K.cross(V3(0, 1, 0)).normalized();
    const double f = kGeneric.c / K.squaredNorm();
    V6 y;
    y << V3::Zero(), f * K + std::sqrt(1 - f * f * K.squaredNorm()) * e;
    const Eigen::Vector4d v = integralsAt(*model, y);
    EXPECT_NEAR(v[0], 0, 1e-15);
    EXPECT_NEAR(v[1], kGeneric.c, 1e-13);
    EXPECT_NEAR(v[3], K.squaredNorm(), 1e-13);
    EXPECT_TRUE(kGeneric.set().hasT0(kGeneric.c));
    EXPECT_FALSE(kZeroK2BigC.set().hasT0(kZeroK2BigC.c));
  }
}

TEST(ChaplyginDiagram, CriticalValuesAtFixedNAreTheBranchValuesAndThePrintedFormulaIsNot) {
  struct Cut {
    Case k;
    double n;
  };
  // n across the regions of each case; K3 = 0 at large n puts the least h on the ray sigma3, c = 0 has
  // sigma0; with c = 2 the printed start of the ray sigma2 (n = 0.22) lies below c^2, the corrected one at
  // c^2
  const std::vector<Cut> cuts{{kGeneric, 0.35},   {kGeneric, 1.3},     {kGeneric, 3.0},    {kZeroC, 0.05},
                              {kZeroC, 0.6},      {kZeroK3, 0.5},      {kZeroK3, 2.5},     {kZeroK2BigC, 0.9},
                              {kZeroK2BigC, 2.0}, {kZeroK2HugeC, 4.3}, {kZeroK2HugeC, 6.0}};
  for (const Cut& cut : cuts) {
    SCOPED_TRACE(std::string(cut.k.name) + ", n = " + std::to_string(cut.n));
    const auto model = makeBall(cut.k);
    const std::vector<double> found = criticalValuesOfH(*model, cut.k.K, cut.n, cut.k.c);
    const std::vector<double> branch = branchValues(cut.k, cut.n);
    ASSERT_FALSE(found.empty());
    ASSERT_FALSE(branch.empty());
    double worst = 0;
    for (double b : branch)
      worst = std::max(worst, distanceTo(found, b));
    for (double f : found)
      worst = std::max(worst, distanceTo(branch, f));
    EXPECT_LE(worst, test::tol(1e-9)) << found.size() << " found, " << branch.size() << " on the diagram";
    // the printed formula puts points where h has no critical value (or misses its extremes)
    const std::vector<double> printed = printedValues(cut.k, cut.n);
    double printedWorst = 0;
    for (double p : printed)
      printedWorst = std::max(printedWorst, distanceTo(found, p));
    printedWorst =
        std::max({printedWorst, distanceTo(printed, found.front()), distanceTo(printed, found.back())});
    EXPECT_GT(printedWorst, 1e-3);
    std::printf("[ %s, n = %g ] critical values of h: %zu found, %zu on the diagram, mismatch %.1e "
                "(printed (31)-(32): %.1e)\n",
                cut.k.name, cut.n, found.size(), branch.size(), worst, printedWorst);
  }
}

TEST(ChaplyginDiagram, TauRunsBetweenTheExtremesOfHOnTheSphere) {
  std::vector<Case> cases{kGeneric, kZeroK3, kZeroK2BigC};
  cases.push_back({"K = 0", {1.0, 1.4, 1.9}, 1.3, 0.8, {0, 0, 0}, 0.3});
  cases.push_back({"K along an axis", {1.0, 1.4, 1.9}, 1.3, 0.8, {0, 0, 0.4}, 0.3});
  double worst = 0;
  for (Case k : cases)
    for (const double c : {0.0, 0.05, 0.3, -0.7, 1.6}) {
      k.c = c;
      SCOPED_TRACE(std::string(k.name) + ", c = " + std::to_string(c));
      const auto model = makeBall(k);
      // M = c gamma - K: the level set at n = c^2 (psi plays no part)
      const auto h = [&](const V3& a) { return integralsAt(*model, onLevel(k.K, c * c, c, a))[0]; };
      double lo = INFINITY, hi = -INFINITY;
      for (const double sign : {1.0, -1.0}) {
        const auto f = [&](const V3& a) { return sign * h(V3(a[0], a[1], 0)); };
        const Grid grid(60, 120, 1, f);
        for (const V3& a0 : grid.localMinima()) {
          const double v = h(nelderMead(f, a0, 0.02));
          lo = std::min(lo, v), hi = std::max(hi, v);
        }
      }
      const auto [tLo, tHi] = k.set().tauRange(c);
      EXPECT_NEAR(tLo, lo, test::tol(1e-10));
      EXPECT_NEAR(tHi, hi, test::tol(1e-10));
      worst = std::max({worst, std::abs(tLo - lo), std::abs(tHi - hi)});
      if (c == 0) { // design.md: h in [(J^-1 K, K)/2, (I^-1 K, K)/2]
        EXPECT_NEAR(tLo, 0.5 * k.K.dot(k.K.cwiseQuotient(k.set().j())), 1e-14);
        EXPECT_NEAR(tHi, 0.5 * k.K.dot(k.K.cwiseQuotient(k.I)), 1e-14);
      }
    }
  std::printf("tau: its ends agree with the brute-force extremes of h on the sphere to %.1e\n", worst);
}

// the h values where a diagram's branches cross the vertical line x = x0, using only the Diagram API
std::vector<double> diagramCrossings(const Diagram& d, double x0) {
  std::vector<double> out;
  for (const DiagramBranch& b : d.branches) {
    if (!(b.max > b.min)) continue; // single points
    const int N = int(std::ceil((b.max - b.min) / b.step)) * 4;
    std::vector<std::vector<DiagramPoint>> pts(N + 1);
    for (int k = 0; k <= N; ++k)
      pts[k] = b.points(b.min + (b.max - b.min) * k / N);
    for (int k = 0; k < N; ++k)
      for (std::size_t r = 0; r < std::min(pts[k].size(), pts[k + 1].size()); ++r) {
        if ((pts[k][r][0] - x0) * (pts[k + 1][r][0] - x0) > 0 || pts[k][r][0] == pts[k + 1][r][0]) continue;
        double lo = b.min + (b.max - b.min) * k / N, hi = b.min + (b.max - b.min) * (k + 1) / N;
        const bool lowBelow = pts[k][r][0] < x0;
        for (int it = 0; it < 200; ++it) {
          const double mid = 0.5 * (lo + hi);
          const auto q = b.points(mid);
          if (q.size() <= r) break;
          ((q[r][0] < x0) == lowBelow ? lo : hi) = mid;
        }
        const auto q = b.points(0.5 * (lo + hi));
        if (q.size() > r) out.push_back(q[r][1]);
      }
  }
  return out;
}

const Diagram& findDiagram(const std::vector<Diagram>& ds, const std::string& id) {
  for (const Diagram& d : ds)
    if (d.id == id) return d;
  throw std::runtime_error("no diagram " + id);
}

TEST(ChaplyginDiagram, TrajectoriesStayBetweenTheLowestAndHighestBranchesAtTheirN) {
  struct Start {
    Case k;
    double energy;
    std::vector<double> map;
  };
  const std::vector<Start> starts{{kScene, 0.5, {0.5, 0.2}},
                                  {kScene, 0.5, {2.0, -0.6}},
                                  {kScene, 1.2, {1.0, 0.8}},
                                  {kGeneric, 0.8, {0.3, -0.2}},
                                  {kZeroK3, 1.5, {2.5, 0.5}}};
  for (const Start& st : starts) {
    SCOPED_TRACE(std::string(st.k.name) + ", energy " + std::to_string(st.energy));
    auto model = makeBall(st.k, 1.0, st.energy);
    const Eigen::VectorXd x0 = model->stateFromMap(st.map, {}, "test");
    const Eigen::VectorXd I0 = model->integrals(x0.data());
    const double n = I0[3], c = I0[1];
    ASSERT_NEAR(c, st.k.c, 1e-12);

    // the nh diagram crossed at the trajectory's n, and the ch diagram (cut at this n) crossed at its c
    const std::vector<double> nh = diagramCrossings(findDiagram(model->diagrams(), "nh"), n);
    const auto cut = makeBall(st.k, n, st.energy);
    const std::vector<double> ch = diagramCrossings(findDiagram(cut->diagrams(), "ch"), c);
    ASSERT_FALSE(nh.empty());
    ASSERT_FALSE(ch.empty());
    const double lo = *std::min_element(nh.begin(), nh.end()), hi = *std::max_element(nh.begin(), nh.end());
    EXPECT_NEAR(*std::min_element(ch.begin(), ch.end()), lo, 1e-9);
    EXPECT_NEAR(*std::max_element(ch.begin(), ch.end()), hi, 1e-9);
    // ... and these are the extremes of h on the level set
    const auto [bLo, bHi] = extremesOfH(*model, st.k.K, n, c);
    EXPECT_NEAR(bLo, lo, test::tol(1e-9));
    EXPECT_NEAR(bHi, hi, test::tol(1e-9));

    Everhart ev(0.05, 15, 12);
    ev.start(*model, 0, x0);
    const Diagram nhd = findDiagram(model->diagrams(), "nh");
    double margin = INFINITY, drift = 0;
    while (ev.time() < 40) {
      ev.step();
      const Eigen::VectorXd& x = ev.state();
      const DiagramPoint p = nhd.place(x.data());
      const Eigen::VectorXd I = model->integrals(x.data());
      EXPECT_EQ(p[0], I[3]);
      EXPECT_EQ(p[1], I[0]);
      drift = std::max({drift, std::abs(p[0] - n), std::abs(p[1] - I0[0])});
      margin = std::min({margin, p[1] - lo, hi - p[1]});
    }
    EXPECT_LE(drift, 1e-10);
    EXPECT_GT(margin, 0);
    std::printf("[ %s, E = %g ] n = %.6f: h = %.6f in [%.6f, %.6f] (brute force [%.6f, %.6f], |diff| %.1e); "
                "ch cut agrees; drift %.1e\n",
                st.k.name, st.energy, n, I0[0], lo, hi, bLo, bHi,
                std::max(std::abs(bLo - lo), std::abs(bHi - hi)), drift);
  }
}

TEST(ChaplyginDiagram, TheModelListsBothDiagramsWithTheirBranches) {
  struct Listing {
    Case k;
    std::vector<std::string> empty; // branches with no point at these parameters
  };
  // generic: c != 0 (no sigma0), every K_i != 0 (no ray); K3 = 0: the ray sigma3, and c^2 > (K, K) (no T0)
  for (const auto& [k, empty] : {Listing{kGeneric, {"sigma0", "sigma1", "sigma2", "sigma3"}},
                                 Listing{kZeroK3, {"sigma0", "sigma1", "sigma2", "T0"}}}) {
    SCOPED_TRACE(k.name);
    const double N = 1.3, energy = 0.5;
    const auto model = makeBall(k, N, energy);
    const std::vector<Diagram> ds = model->diagrams();
    ASSERT_EQ(ds.size(), 2u);
    const Diagram &nh = ds[0], &ch = ds[1];
    EXPECT_EQ(nh.id, "nh");
    EXPECT_EQ(ch.id, "ch");
    EXPECT_EQ(nh.axes, (std::array<std::string, 2>{"n", "h"}));
    EXPECT_EQ(ch.axes, (std::array<std::string, 2>{"c", "h"}));
    const ChaplyginBifurcationSet s = k.set();
    const double L = 20 * s.j().maxCoeff();
    for (const Diagram& d : ds) {
      SCOPED_TRACE(d.id);
      EXPECT_FALSE(d.title.empty());
      std::vector<std::string> ids;
      std::vector<std::pair<double, double>> sigmaRanges;
      for (const DiagramBranch& b : d.branches) {
        ids.push_back(b.id);
        EXPECT_FALSE(b.description.empty()) << b.id;
        EXPECT_FALSE(b.parameter.empty()) << b.id;
        EXPECT_LE(b.min, b.max) << b.id;
        EXPECT_GT(b.step, 0) << b.id;
        EXPECT_LE((b.max - b.min) / b.step, 1e4) << b.id;
        const bool isSigma = b.id.rfind("sigma_", 0) == 0;
        if (isSigma) sigmaRanges.emplace_back(b.min, b.max);
        // what the branches draw is the library's closed forms
        int withPoints = 0;
        for (int i = 0; i <= std::lround((b.max - b.min) / b.step); ++i) {
          const double t = b.min + i * b.step;
          const auto pts = b.points(t);
          withPoints += !pts.empty();
          if (isSigma) {
            std::vector<DiagramPoint> expected =
                d.id == "ch" ? s.sigmaAtN(N, t) : std::vector<DiagramPoint>{};
            if (d.id == "nh")
              if (const auto p = s.sigma(k.c, t)) expected.push_back(*p);
            ASSERT_EQ(pts, expected) << b.id << " at " << t;
          }
        }
        if (d.id == "nh") {
          EXPECT_EQ(withPoints == 0, std::find(empty.begin(), empty.end(), b.id) != empty.end()) << b.id;
        } else if (b.id == "tau") {
          EXPECT_GT(withPoints, 0) << b.id;
        }
        if (isSigma) {
          EXPECT_GE(withPoints, 200) << b.id << ": the default range is mostly where the curve is";
        }
      }
      for (const char* id : {"sigma_a", "sigma0", "sigma1", "sigma2", "sigma3", "tau", "T0"})
        EXPECT_NE(std::find(ids.begin(), ids.end(), id), ids.end()) << id;
      // the default lambda ranges hold every real point of sigma in [-L, L] below twice the energy level's n
      const double nLevel = std::pow(std::sqrt(2 * energy * s.j().maxCoeff()) + k.K.norm(), 2);
      int outside = 0, real = 0;
      for (double l = -L; l <= L; l += L * 1.234e-5) {
        const bool has =
            d.id == "nh" ? s.sigma(k.c, l) && (*s.sigma(k.c, l))[0] <= 2 * nLevel : !s.sigmaAtN(N, l).empty();
        if (!has) continue;
        ++real;
        outside += std::none_of(sigmaRanges.begin(), sigmaRanges.end(),
                                [&](const auto& r) { return r.first <= l && l <= r.second; });
      }
      EXPECT_GT(real, 100);
      EXPECT_EQ(outside, 0);
    }
  }
  // sigma tends to T0 as lambda -> +-inf, and meets tau at lambda = 0 (when Phi(0) >= 0)
  const ChaplyginBifurcationSet s = kGeneric.set();
  for (const double l : {-1e8, 1e8}) {
    const auto far = s.sigma(kGeneric.c, l);
    ASSERT_TRUE(far);
    EXPECT_NEAR((*far)[0], kGeneric.K.squaredNorm(), 1e-7);
    EXPECT_NEAR((*far)[1], 0, 1e-7);
  }
  const auto zero = kZeroC.set().sigma(0, 0);
  ASSERT_TRUE(zero);
  EXPECT_EQ((*zero)[0], 0);
  EXPECT_NEAR((*zero)[1], kZeroC.set().tauRange(0).first, 1e-15);
}

TEST(ChaplyginDiagram, DegenerateBodiesGiveFinitePoints) {
  // no gyrostat; no area constant; a gyrostat along one axis; equal moments (a ray blocked by a pole)
  const std::vector<Case> cases{{"K = 0, c = 0", {1.0, 1.4, 1.9}, 1.0, 1.0, {0, 0, 0}, 0.0},
                                {"K = 0", {1.0, 1.4, 1.9}, 1.0, 1.0, {0, 0, 0}, 0.4},
                                {"K along 3, c = 0", {1.0, 1.4, 1.9}, 1.0, 1.0, {0, 0, 0.3}, 0.0},
                                {"I1 = I2, K2 = 0", {1.2, 1.2, 1.9}, 1.0, 1.0, {0.2, 0, 0.3}, 0.3},
                                {"I1 = I2, K1 = K2 = 0", {1.2, 1.2, 1.9}, 1.0, 1.0, {0, 0, 0.3}, 0.3}};
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    const auto model = makeBall(k, 0.8);
    int points = 0;
    for (const Diagram& d : model->diagrams())
      for (const DiagramBranch& b : d.branches) {
        ASSERT_TRUE(std::isfinite(b.min) && std::isfinite(b.max) && b.step > 0) << d.id << " " << b.id;
        for (int i = 0; i <= std::lround((b.max - b.min) / b.step); ++i)
          for (const DiagramPoint& p : b.points(b.min + i * b.step)) {
            ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1])) << d.id << " " << b.id;
            EXPECT_GE(p[1], -1e-12) << d.id << " " << b.id << ": the energy is not negative";
            ++points;
          }
      }
    EXPECT_GT(points, 0);
  }
  // a K_j on an axis with the same moment blocks the ray: lambda = J_i is its pole
  EXPECT_FALSE(ChaplyginBifurcationSet({1.2, 1.2, 1.9}, 1, {0.2, 0, 0.3}).hasRay(1));
  EXPECT_TRUE(ChaplyginBifurcationSet({1.2, 1.2, 1.9}, 1, {0, 0, 0.3}).hasRay(1));
}

} // namespace
} // namespace rv
