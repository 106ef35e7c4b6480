#include "dynamics/kinematics/AndoyerDeprit.h"

#include <algorithm>
#include <cmath>

namespace rv {

namespace {
// the orthonormal frame (e, u, w) of (7): e = P/G, gamma = (H/G) e + sqrt(1 - (H/G)^2)(cos g u + sin g w)
void frame(double l, double LG, Eigen::Vector3d& e, Eigen::Vector3d& u, Eigen::Vector3d& w) {
  const double s = std::sqrt(std::max(0.0, 1 - LG * LG));
  e = {s * std::sin(l), s * std::cos(l), LG};
  u = {LG * std::sin(l), LG * std::cos(l), -s};
  w = {std::cos(l), -std::sin(l), 0};
}
} // namespace

AndoyerDeprit toAndoyerDeprit(const Eigen::Vector3d& P, const Eigen::Vector3d& gamma) {
  AndoyerDeprit v;
  v.G = P.norm();
  v.L = P[2];
  v.H = P.dot(gamma);
  v.l = std::atan2(P[0], P[1]);
  Eigen::Vector3d e, u, w;
  frame(v.l, std::clamp(v.L / v.G, -1.0, 1.0), e, u, w);
  v.g = std::atan2(gamma.dot(w), gamma.dot(u));
  return v;
}

void fromAndoyerDeprit(const AndoyerDeprit& v, Eigen::Vector3d& P, Eigen::Vector3d& gamma) {
  Eigen::Vector3d e, u, w;
  frame(v.l, v.L / v.G, e, u, w);
  const double HG = v.H / v.G, r = std::sqrt(std::max(0.0, 1 - HG * HG));
  P = v.G * e;
  gamma = HG * e + r * (std::cos(v.g) * u + std::sin(v.g) * w);
}

} // namespace rv
