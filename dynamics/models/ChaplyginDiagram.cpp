#include "dynamics/models/ChaplyginDiagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

namespace rv {

namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// sorted, without exact duplicates (equal moments give equal poles)
std::vector<double> sortedUnique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// the root of f = 1 between lo and hi (f - 1 changes sign once there), by bisection down to adjacent doubles
template <class F> double bisect(const F& f, double lo, double hi) {
  const bool rising = f(lo) < 1;
  for (int it = 0; it < 2000; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > std::min(lo, hi) && mid < std::max(lo, hi))) break;
    ((f(mid) < 1) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

} // namespace

ChaplyginBifurcationSet::ChaplyginBifurcationSet(const Eigen::Vector3d& I, double D, const Eigen::Vector3d& K)
    : I_(I), K_(K), D_(D) {}

double ChaplyginBifurcationSet::phi(double c, double lambda) const {
  const Eigen::Vector3d J = j();
  double s = 0;
  for (int i = 0; i < 3; ++i)
    if (K_[i] != 0) s += K_[i] * K_[i] / ((J[i] - lambda) * (J[i] - lambda)); // a zero K_i has no pole
  if (c != 0) s -= c * c / ((D_ - lambda) * (D_ - lambda));
  return s;
}

std::optional<DiagramPoint> ChaplyginBifurcationSet::sigma(double c, double lambda) const {
  const Eigen::Vector3d J = j();
  const double Phi = phi(c, lambda);
  if (!std::isfinite(Phi) || Phi < 0) return std::nullopt; // s^2 > |omega|^2: no gamma on the unit sphere
  double twoH = c != 0 ? -D_ * c * c / ((D_ - lambda) * (D_ - lambda)) : 0.0;
  for (int i = 0; i < 3; ++i)
    if (K_[i] != 0) twoH += J[i] * K_[i] * K_[i] / ((J[i] - lambda) * (J[i] - lambda));
  const DiagramPoint p{c * c + lambda * lambda * Phi, 0.5 * twoH};
  if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return std::nullopt;
  return p;
}

std::vector<DiagramPoint> ChaplyginBifurcationSet::sigmaAtN(double n, double lambda) const {
  const Eigen::Vector3d J = j();
  double S = 0, T = 0;
  for (int i = 0; i < 3; ++i)
    if (K_[i] != 0) {
      const double t = K_[i] * K_[i] / ((J[i] - lambda) * (J[i] - lambda));
      S += t, T += J[i] * t;
    }
  // n - lambda^2 S = c^2 D (D - 2 lambda)/(D - lambda)^2; q = c^2/(D - lambda)^2 = s^2 must be >= 0 even
  // where D - lambda = 0 (there c = 0 and q is sigma0's s^2)
  const double rest = n - lambda * lambda * S, q = rest / (D_ * (D_ - 2 * lambda));
  const double c2 = q * (D_ - lambda) * (D_ - lambda), h = 0.5 * (T - rest / (D_ - 2 * lambda));
  if (!std::isfinite(q) || !std::isfinite(h) || q < 0 || c2 > n) return {};
  const double c = std::sqrt(c2);
  return {{c, h}, {-c, h}};
}

std::vector<double> ChaplyginBifurcationSet::sigmaPoles(double c) const {
  std::vector<double> p;
  for (int i = 0; i < 3; ++i)
    if (K_[i] != 0) p.push_back(I_[i] + D_);
  if (c != 0) p.push_back(D_);
  return sortedUnique(p);
}

std::vector<double> ChaplyginBifurcationSet::sigmaPolesAtN() const {
  std::vector<double> p{0.5 * D_};
  for (int i = 0; i < 3; ++i)
    if (K_[i] != 0) p.push_back(I_[i] + D_);
  return sortedUnique(p);
}

double ChaplyginBifurcationSet::sigma0H(double n) const {
  return (n + D_ * K_.dot(K_.cwiseQuotient(I_))) / (2 * D_);
}

double ChaplyginBifurcationSet::sigma0MaxN() const {
  return D_ * D_ * K_.cwiseQuotient(I_).squaredNorm();
}

bool ChaplyginBifurcationSet::hasRay(int i) const {
  if (K_[i] != 0) return false;
  // an axis with the same moment and K_j != 0 makes lambda = J_i a pole: (J - lambda) omega = -K has no root
  for (int j = 0; j < 3; ++j)
    if (j != i && I_[j] == I_[i] && K_[j] != 0) return false;
  return true;
}

double ChaplyginBifurcationSet::rayH(int i, double c, double n) const {
  const double Ji = I_[i] + D_;
  double sum = 0;
  for (int j = 0; j < 3; ++j)
    if (j != i && K_[j] != 0) sum += K_[j] * K_[j] / (I_[j] - I_[i]);
  return (n + D_ * c * c / I_[i] + Ji * sum) / (2 * Ji);
}

double ChaplyginBifurcationSet::rayMinN(int i, double c) const {
  const double Ji = I_[i] + D_;
  double sum = 0;
  for (int j = 0; j < 3; ++j)
    if (j != i && K_[j] != 0) sum += K_[j] * K_[j] / ((I_[j] - I_[i]) * (I_[j] - I_[i]));
  // omega_i^2 >= 0 and s^2 = c^2/I_i^2 <= |omega|^2 (the manual drops the max)
  return c * c + Ji * Ji * std::max(0.0, sum - c * c / (I_[i] * I_[i]));
}

std::pair<double, double> ChaplyginBifurcationSet::tauRange(double c) const {
  // h on the sphere M = c gamma - K has the gradient (c + D s) omega: it is critical on a circle where
  // s = -c/D (then omega = -J^-1 K), and where omega = kappa gamma, i.e. (kappa I_i - c) gamma_i = -K_i
  // with |gamma| = 1. There h = kappa (c - (K, gamma))/2. The extremes are among these values.
  std::vector<double> hs;
  const Eigen::Vector3d JiK = K_.cwiseQuotient(j());
  if (std::abs(c) / D_ <= JiK.norm()) hs.push_back(0.5 * (K_.dot(JiK) - c * c / D_));

  // omega = kappa gamma on generic kappa: sum K_i^2/(kappa I_i - c)^2 = 1, convex between its poles c/I_i
  const auto f = [&](double k) {
    double s = 0;
    for (int i = 0; i < 3; ++i)
      if (K_[i] != 0) s += K_[i] * K_[i] / ((k * I_[i] - c) * (k * I_[i] - c));
    return s;
  };
  const auto hAt = [&](double k) {
    double s = c;
    for (int i = 0; i < 3; ++i)
      if (K_[i] != 0) s += K_[i] * K_[i] / (k * I_[i] - c);
    return 0.5 * k * s;
  };
  std::vector<double> poles;
  for (int i = 0; i < 3; ++i)
    if (K_[i] != 0) poles.push_back(c / I_[i]);
  poles = sortedUnique(poles);
  if (!poles.empty()) {
    // outside the poles f falls monotonically from +inf to 0: one root on each side
    for (const double dir : {-1.0, 1.0}) {
      const double p = dir < 0 ? poles.front() : poles.back();
      double far = p + dir * (1 + std::abs(p));
      while (f(far) >= 1)
        far = p + 2 * (far - p);
      hs.push_back(hAt(bisect(f, far, std::nextafter(p, far))));
    }
    for (std::size_t k = 0; k + 1 < poles.size(); ++k) {
      // between two poles: the minimum of the convex f by golden section, then a root on each side of it
      double a = poles[k], b = poles[k + 1];
      const double g = 0.5 * (std::sqrt(5.0) - 1);
      double x1 = b - g * (b - a), x2 = a + g * (b - a);
      for (int it = 0; it < 200 && b - a > 1e-15 * (std::abs(a) + std::abs(b)); ++it) {
        if (f(x1) < f(x2))
          b = x2, x2 = x1, x1 = b - g * (b - a);
        else
          a = x1, x1 = x2, x2 = a + g * (b - a);
      }
      const double m = 0.5 * (a + b);
      if (f(m) > 1) continue;
      hs.push_back(hAt(bisect(f, m, std::nextafter(poles[k], m))));
      hs.push_back(hAt(bisect(f, m, std::nextafter(poles[k + 1], m))));
    }
  }
  // kappa = c / I_i on an axis without gyrostat: gamma_i takes up what the other components leave
  for (int i = 0; i < 3; ++i) {
    if (K_[i] != 0) continue;
    const double k = c / I_[i];
    double used = 0, s = c;
    bool ok = true;
    for (int jx = 0; jx < 3; ++jx) {
      const bool free = c == 0 || I_[jx] == I_[i]; // kappa I_j = c
      if (free) {
        ok = ok && K_[jx] == 0;
      } else if (K_[jx] != 0) {
        used += K_[jx] * K_[jx] / ((k * I_[jx] - c) * (k * I_[jx] - c));
        s += K_[jx] * K_[jx] / (k * I_[jx] - c);
      }
    }
    if (ok && used <= 1) hs.push_back(0.5 * k * s);
  }
  const auto [lo, hi] = std::minmax_element(hs.begin(), hs.end());
  return {*lo, *hi};
}

std::vector<DiagramBranch>
ChaplyginBifurcationSet::sigmaBranches(const std::vector<double>& poles, double nScale,
                                       const std::string& what,
                                       const std::function<std::vector<DiagramPoint>(double)>& points) const {
  // lambda intervals between the poles; the outer ones run to +-L, where sigma is within a few per cent of
  // T0 (it tends to T0 as lambda -> +-inf)
  const double L = 20 * j().maxCoeff();
  std::vector<double> edges{-L};
  edges.insert(edges.end(), poles.begin(), poles.end());
  edges.push_back(L);
  // stop short of a pole J_i where the term lambda^2 K_i^2/(J_i - lambda)^2 reaches 2 nScale (the other terms
  // of n are far smaller there)
  const auto margin = [&](std::size_t e) {
    if (e == 0 || e + 1 == edges.size() || !std::isfinite(nScale)) return 0.0;
    double m = 0;
    for (int i = 0; i < 3; ++i)
      if (K_[i] != 0 && I_[i] + D_ == edges[e])
        m = std::max(m, edges[e] * std::abs(K_[i]) / std::sqrt(2 * nScale));
    return std::min(m, 0.45 * std::min(edges[e] - edges[e - 1], edges[e + 1] - edges[e]));
  };
  std::vector<DiagramBranch> out;
  for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
    // the default range: the part of the interval that has points (Phi >= 0; in the (c, h) cut, c^2 <= n),
    // found on a fine grid; none, no branch
    double lo = edges[e] + margin(e), hi = edges[e + 1] - margin(e + 1);
    const int fine = 20000, samples = 2000;
    int first = -1, last = -1;
    for (int k = 0; k <= fine; ++k)
      if (!points(lo + (hi - lo) * k / fine).empty()) last = k, first = first < 0 ? k : first;
    if (first < 0) continue;
    const double dl = (hi - lo) / fine;
    std::tie(lo, hi) = std::pair(std::max(lo, lo + (first - 1) * dl), std::min(hi, lo + (last + 1) * dl));
    const std::string from = e == 0 ? "-inf" : fmt(edges[e]),
                      to = e + 2 == edges.size() ? "+inf" : fmt(edges[e + 1]);
    out.push_back(
        {.id = std::string("sigma_") + char('a' + out.size()),
         .description = "sigma (31)-(32) for lambda in (" + from + ", " + to + "), between poles; " + what,
         .parameter = "lambda",
         .min = lo,
         .max = hi,
         .step = (hi - lo) / samples,
         .points = points});
  }
  return out;
}

std::vector<Diagram>
ChaplyginBifurcationSet::diagrams(double c, double N, double nScale,
                                  const std::function<Integrals(const double*)>& integrals) const {
  const double K2 = K_.squaredNorm();
  const ChaplyginBifurcationSet set = *this; // the branches outlive this object: they keep a copy
  const auto pointBranch = [](std::string id, std::string description, std::optional<DiagramPoint> p) {
    return DiagramBranch{
        .id = std::move(id),
        .description = std::move(description),
        .parameter = "none",
        .min = 0,
        .max = 0,
        .step = 1,
        .points = [p](double) { return p ? std::vector<DiagramPoint>{*p} : std::vector<DiagramPoint>{}; }};
  };
  const std::string axisName[3] = {"1", "2", "3"};

  // (n, h) at the area constant c
  Diagram nh{.id = "nh",
             .title = "bifurcation set in the plane of the integrals (n, h) at the area constant c = " +
                      fmt(c) + " (manual §3.5.1)",
             .axes = {"n", "h"},
             .place = [integrals](const double* x) {
               const Integrals v = integrals(x);
               return DiagramPoint{v.n, v.h};
             }};
  nh.branches =
      sigmaBranches(sigmaPoles(c), nScale, "no points where Phi(lambda) < 0", [set, c](double lambda) {
        const auto p = set.sigma(c, lambda);
        return p ? std::vector<DiagramPoint>{*p} : std::vector<DiagramPoint>{};
      });
  const double n0 = sigma0MaxN();
  nh.branches.push_back({.id = "sigma0",
                         .description = "sigma0 (33), the segment n = 2 D h - D (I^-1 K, K), n in [0, " +
                                        fmt(n0) + "]; only at c = 0",
                         .parameter = "n",
                         .min = 0,
                         .max = n0,
                         .step = n0 > 0 ? n0 / 200 : 1,
                         .points = [set, c, n0](double n) {
                           if (c != 0 || n < 0 || n > n0) return std::vector<DiagramPoint>{};
                           return std::vector<DiagramPoint>{{n, set.sigma0H(n)}};
                         }});
  for (int i = 0; i < 3; ++i) {
    const double from = hasRay(i) ? rayMinN(i, c) : 0;
    nh.branches.push_back(
        {.id = "sigma" + axisName[i],
         .description = "sigma" + axisName[i] + " (34), the ray n = 2 J" + axisName[i] + " h - D c^2/I" +
                        axisName[i] + " - J" + axisName[i] + " sum_j K_j^2/(I_j - I" + axisName[i] +
                        ") for n >= c^2 + J" + axisName[i] + "^2 max(0, sum_j K_j^2/(I_j - I" + axisName[i] +
                        ")^2 - c^2/I" + axisName[i] + "^2)" +
                        (hasRay(i) ? " = " + fmt(from)
                                   : "; absent here (it needs K" + axisName[i] +
                                         " = 0 on every axis with the moment I" + axisName[i] + ")"),
         .parameter = "n",
         .min = from,
         .max = from + nScale,
         .step = nScale / 200,
         .points = [set, i, c, from](double n) {
           if (!set.hasRay(i) || n < from) return std::vector<DiagramPoint>{};
           return std::vector<DiagramPoint>{{n, set.rayH(i, c, n)}};
         }});
  }
  const auto [tLo, tHi] = tauRange(c);
  nh.branches.push_back({.id = "tau",
                         .description = "tau, the segment n = c^2, h in [" + fmt(tLo) + ", " + fmt(tHi) +
                                        "] (the extremes of h on M = c gamma - K); t = 0 at the least h",
                         .parameter = "t",
                         .min = 0,
                         .max = 1,
                         .step = 0.01,
                         // init-captures: clang before 16 cannot capture structured bindings
                         .points = [c, lo = tLo, hi = tHi](double t) {
                           return std::vector<DiagramPoint>{{c * c, lo + t * (hi - lo)}};
                         }});
  nh.branches.push_back(
      pointBranch("T0", "T0, the point h = 0, n = (K, K) (M = 0); present when c^2 <= (K, K)",
                  hasT0(c) ? std::optional<DiagramPoint>(DiagramPoint{K2, 0}) : std::nullopt));

  // (c, h) at n = N: the same set cut across c
  Diagram ch{.id = "ch",
             .title = "bifurcation set in the plane (c, h) at n = " + fmt(N) +
                      " (the manual's \"(c/n, h)\" diagram, read as in design.md)",
             .axes = {"c", "h"},
             .place = [integrals](const double* x) {
               const Integrals v = integrals(x);
               return DiagramPoint{v.c, v.h};
             }};
  // no margins at the poles: there c^2 grows past n and the points stop by themselves
  ch.branches = sigmaBranches(sigmaPolesAtN(), std::numeric_limits<double>::infinity(),
                              "points (+-c, h), none unless 0 <= c^2 <= n",
                              [set, N](double lambda) { return set.sigmaAtN(N, lambda); });
  ch.branches.push_back(pointBranch(
      "sigma0", "sigma0 (33) at c = 0: h = (n + D (I^-1 K, K))/(2 D); present when n <= " + fmt(n0),
      N <= n0 ? std::optional<DiagramPoint>(DiagramPoint{0, sigma0H(N)}) : std::nullopt));
  const double cMax = std::sqrt(std::max(N, 0.0));
  for (int i = 0; i < 3; ++i)
    ch.branches.push_back({.id = "sigma" + axisName[i],
                           .description = "sigma" + axisName[i] + " (34) at fixed n, the parabola 2 J" +
                                          axisName[i] + " h = n + D c^2/I" + axisName[i] + " + J" +
                                          axisName[i] + " sum_j K_j^2/(I_j - I" + axisName[i] +
                                          ") where n >= c^2 + J" + axisName[i] +
                                          "^2 max(0, sum_j K_j^2/(I_j - I" + axisName[i] + ")^2 - c^2/I" +
                                          axisName[i] + "^2); only when K" + axisName[i] + " = 0",
                           .parameter = "c",
                           .min = -cMax,
                           .max = cMax,
                           .step = cMax > 0 ? cMax / 100 : 1,
                           .points = [set, i, N](double cc) {
                             if (!set.hasRay(i) || N < set.rayMinN(i, cc)) return std::vector<DiagramPoint>{};
                             return std::vector<DiagramPoint>{{cc, set.rayH(i, cc, N)}};
                           }});
  const auto [sLo, sHi] = tauRange(cMax); // h on the sphere is even in c
  ch.branches.push_back(
      {.id = "tau",
       .description = "tau on c = +-sqrt(n), h in [" + fmt(sLo) + ", " + fmt(sHi) + "]; t = 0 at the least h",
       .parameter = "t",
       .min = 0,
       .max = 1,
       .step = 0.01,
       .points = [cMax, lo = sLo, hi = sHi](double t) {
         const double h = lo + t * (hi - lo);
         return std::vector<DiagramPoint>{{cMax, h}, {-cMax, h}};
       }});
  const double Kn = std::sqrt(K2);
  const bool atT0 = std::abs(N - K2) <= 1e-12 * std::max(1.0, K2);
  ch.branches.push_back({.id = "T0",
                         .description = "T0 at fixed n: the segment h = 0, |c| <= |K|; only when n = (K, K)",
                         .parameter = "c",
                         .min = -Kn,
                         .max = Kn,
                         .step = Kn > 0 ? Kn / 50 : 1,
                         .points = [atT0, Kn](double cc) {
                           if (!atT0 || std::abs(cc) > Kn) return std::vector<DiagramPoint>{};
                           return std::vector<DiagramPoint>{{cc, 0}};
                         }});
  return {nh, ch};
}

} // namespace rv
