// Andoyer-Deprit variables (manual §3.1.2 (7)): the formulas give |gamma| = 1, |P| = G, P3 = L,
// (P, gamma) = H, and the inverse recovers (L, G, H, l, g).
#include "dynamics/kinematics/AndoyerDeprit.h"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace rv {
namespace {

TEST(AndoyerDeprit, FormulaSevenHasTheMeaningOfItsVariables) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.99, 0.99), a(-3.1, 3.1);
  for (int i = 0; i < 200; ++i) {
    const AndoyerDeprit v{.L = 0, .G = 1.7, .H = 0, .l = a(rng), .g = a(rng)};
    AndoyerDeprit w = v;
    w.L = u(rng) * v.G, w.H = u(rng) * v.G;
    Eigen::Vector3d P, g;
    fromAndoyerDeprit(w, P, g);
    EXPECT_NEAR(g.norm(), 1, 1e-15);
    EXPECT_NEAR(P.norm(), w.G, 1e-14);
    EXPECT_NEAR(P[2], w.L, 1e-14);
    EXPECT_NEAR(P.dot(g), w.H, 1e-14);
    const AndoyerDeprit back = toAndoyerDeprit(P, g);
    EXPECT_NEAR(back.G, w.G, 1e-13);
    EXPECT_NEAR(back.L, w.L, 1e-13);
    EXPECT_NEAR(back.H, w.H, 1e-13);
    EXPECT_NEAR(std::remainder(back.l - w.l, 2 * M_PI), 0, 1e-13);
    EXPECT_NEAR(std::remainder(back.g - w.g, 2 * M_PI), 0, 1e-12);
  }
}

TEST(AndoyerDeprit, MatchesThePrintedComponentFormulas) {
  // gamma3 = (H/G)(L/G) - sqrt(1 - (L/G)^2) sqrt(1 - (H/G)^2) cos g, straight from (7)
  const double G = 2, L = 0.6, H = -0.8, l = 0.7, g = 2.1;
  Eigen::Vector3d P, gam;
  fromAndoyerDeprit({.L = L, .G = G, .H = H, .l = l, .g = g}, P, gam);
  const double lg = L / G, hg = H / G, sl = std::sqrt(1 - lg * lg), sh = std::sqrt(1 - hg * hg);
  EXPECT_NEAR(P[0], std::sqrt(G * G - L * L) * std::sin(l), 1e-15);
  EXPECT_NEAR(P[1], std::sqrt(G * G - L * L) * std::cos(l), 1e-15);
  EXPECT_NEAR(gam[0], (hg * sl + lg * sh * std::cos(g)) * std::sin(l) + sh * std::sin(g) * std::cos(l),
              1e-15);
  EXPECT_NEAR(gam[1], (hg * sl + lg * sh * std::cos(g)) * std::cos(l) - sh * std::sin(g) * std::sin(l),
              1e-15);
  EXPECT_NEAR(gam[2], hg * lg - sl * sh * std::cos(g), 1e-15);
}

} // namespace
} // namespace rv
