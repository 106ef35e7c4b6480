// ChaplyginDiagram.h -- the bifurcation set of the Chaplygin ball with a gyrostat (manual §3.5.1, (31)-(34)):
// the critical values of the integral map (h, n) on the level |gamma| = 1, (M + K, gamma) = c.
// References: A. Yu. Moskvin, Chaplygin's ball with a gyrostat: singular solutions, Nelin. Dinam. 5 (2009)
//             345-356 (the manual's [4]); A. V. Borisov, I. S. Mamaev, Nonholonomic dynamical systems (2002)
//             §8; the corrections listed in design.md, "Known errata in the manual", §3.5.1.
//
// As corrected: H in (31)-(34) is the area constant c; (31)-(32) hold with J = I + D E. With
// omega_i = -K_i/(J_i - lambda) and s = (gamma, omega) = c/(lambda - D), the critical points are the uniform
// rotations M + K = lambda omega - D s gamma, which exist where s^2 <= |omega|^2, i.e. Phi(lambda) >= 0:
//   Phi(lambda) = sum K_i^2/(J_i - lambda)^2 - c^2/(D - lambda)^2,   n = c^2 + lambda^2 Phi(lambda),
//   2h = sum J_i K_i^2/(J_i - lambda)^2 - D c^2/(D - lambda)^2.
// The limits of the same family make the other branches: sigma0 (lambda = D, c = 0), the rays sigma_i
// (lambda = J_i, K_i = 0), tau (M + K parallel to gamma, n = c^2) and T0 (omega = 0, M = 0).
// The manual's second diagram "(c/n, h)" is read as design.md says: the same set cut at a fixed n and drawn
// in the plane (c, h); sigma there follows from solving n(lambda) = n for c^2.
#pragma once
#include "dynamics/core/Diagram.h"

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rv {

/// The bifurcation set at fixed body constants; every function is exact (closed form) except the ends of
/// tau, which come from the roots of a secular equation.
class ChaplyginBifurcationSet {
public:
  /// I: principal moments of inertia, D = m R^2, K: the gyrostat's momentum (body frame).
  ChaplyginBifurcationSet(const Eigen::Vector3d& I, double D, const Eigen::Vector3d& K);

  const Eigen::Vector3d& moments() const { return I_; }
  const Eigen::Vector3d& gyrostat() const { return K_; }
  double d() const { return D_; }
  /// J = I + D.
  Eigen::Vector3d j() const { return I_.array() + D_; }

  /// Phi(lambda) = sum K_i^2/(J_i - lambda)^2 - c^2/(D - lambda)^2 (n - c^2 = lambda^2 Phi on sigma).
  double phi(double c, double lambda) const;
  /// sigma, (31)-(32): the point (n, h) at lambda for the area constant c; nothing where Phi < 0 or at a
  /// pole.
  std::optional<DiagramPoint> sigma(double c, double lambda) const;
  /// sigma cut at fixed n: the points (c, h) and (-c, h) at lambda, with
  /// c^2 = (n - lambda^2 S)(D - lambda)^2 / (D (D - 2 lambda)), 2h = sum J_i K_i^2/(J_i - lambda)^2 -
  /// (n - lambda^2 S)/(D - 2 lambda), S = sum K_i^2/(J_i - lambda)^2; nothing unless 0 <= c^2 <= n.
  std::vector<DiagramPoint> sigmaAtN(double n, double lambda) const;
  /// The poles of sigma(c, .), ascending and distinct: J_i where K_i != 0, and D where c != 0.
  std::vector<double> sigmaPoles(double c) const;
  /// The poles of sigmaAtN(n, .), ascending and distinct: J_i where K_i != 0, and D / 2.
  std::vector<double> sigmaPolesAtN() const;

  /// sigma0, (33) (c = 0 only): n = 2 D h - D (I^-1 K, K) for n in [0, sigma0MaxN()].
  double sigma0H(double n) const;
  /// D^2 (I^-1 K, I^-1 K).
  double sigma0MaxN() const;

  /// Whether the ray sigma_i, (34), exists: K_i = 0 and no other axis with the same moment carries K.
  bool hasRay(int i) const;
  /// The ray sigma_i: h at n, from n = 2 J_i h - D c^2/I_i - J_i sum_{j != i} K_j^2/(I_j - I_i).
  double rayH(int i, double c, double n) const;
  /// Where the ray starts (the corrected range; meaningful when hasRay(i)):
  /// c^2 + J_i^2 max(0, sum_{j != i} K_j^2/(I_j - I_i)^2 - c^2/I_i^2).
  double rayMinN(int i, double c) const;

  /// tau: the least and greatest h on the sphere M = c gamma - K, |gamma| = 1 (the segment on n = c^2).
  std::pair<double, double> tauRange(double c) const;

  /// T0: h = 0, n = (K, K), present when c^2 <= (K, K).
  bool hasT0(double c) const { return c * c <= K_.squaredNorm(); }

  /// A state's integrals, for Diagram::place.
  struct Integrals {
    double h, c, n;
  };
  /// The diagrams "nh" ((n, h) at the area constant c) and "ch" ((c, h) at n = diagramN). `nScale` sets the
  /// default ranges: sigma's lambda ranges stop near the poles, about n = 2 nScale, and rays run over nScale.
  /// The branches keep a copy of this object.
  std::vector<Diagram> diagrams(double c, double diagramN, double nScale,
                                const std::function<Integrals(const double* x)>& integrals) const;

private:
  std::vector<DiagramBranch>
  sigmaBranches(const std::vector<double>& poles, double nScale, const std::string& what,
                const std::function<std::vector<DiagramPoint>(double)>& points) const;
  Eigen::Vector3d I_, K_;
  double D_;
};

} // namespace rv
