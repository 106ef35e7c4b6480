// AndoyerDeprit.h -- Andoyer-Deprit variables (L, G, H, l, g) of a momentum P and the vertical gamma,
// manual §3.1.2 formula (7) and its inverse. Where a gyrostat is present P = M + K (design.md errata, §3.5).
// Reference: A. V. Borisov, I. S. Mamaev, Rigid Body Dynamics (2005), §1.
#pragma once
#include <Eigen/Core>

namespace rv {

struct AndoyerDeprit {
  double L = 0; ///< P3, the projection on the body's third axis
  double G = 0; ///< |P|
  double H = 0; ///< (P, gamma), the projection on the vertical
  double l = 0; ///< angle of P around the third axis: P1 = sqrt(G^2 - L^2) sin l, P2 = ... cos l
  double g = 0; ///< angle of gamma around P
};

/// (L, G, H, l, g) of P and a unit gamma. Undefined when P = 0 or P is along the third axis (l singular).
AndoyerDeprit toAndoyerDeprit(const Eigen::Vector3d& P, const Eigen::Vector3d& gamma);

/// P and gamma from (L, G, H, l, g), formula (7); |gamma| = 1 by construction. Needs |L|, |H| <= G.
void fromAndoyerDeprit(const AndoyerDeprit& v, Eigen::Vector3d& P, Eigen::Vector3d& gamma);

} // namespace rv
