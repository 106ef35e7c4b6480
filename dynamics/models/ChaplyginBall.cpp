#include "dynamics/models/ChaplyginBall.h"

#include "dynamics/core/Errors.h"
#include "dynamics/kinematics/AndoyerDeprit.h"
#include "dynamics/kinematics/RootFinding.h"
#include "dynamics/models/BodyParameters.h"
#include "dynamics/models/BodyState.h"
#include "dynamics/models/ChaplyginDiagram.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace rv {

const ModelInfo& ChaplyginBall::staticInfo() {
  static const ModelInfo info{
      .id = "chaplygin_ball",
      .title = "Chaplygin ball with a gyrostat rolling on a plane (manual §3.5)",
      .reference =
          "Borisov, Mamaev, Nonholonomic dynamical systems (2002) §8; Moskvin, Nelin. Dinam. 5 (2009)",
      .parameters =
          {
              {.id = "energy",
               .label = "Energy",
               .defaultValue = 0.5,
               .min = 0,
               .max = 1e12,
               .description = "energy h = (M, omega)/2 at which a map point is completed into a state"},
              {.id = "c",
               .label = "c",
               .defaultValue = 0.3,
               .description = "area constant c = (M + K, gamma)"},
              {.id = "I1",
               .label = "I1",
               .defaultValue = 1.0,
               .min = 0,
               .description = "principal moment of inertia"},
              {.id = "I2",
               .label = "I2",
               .defaultValue = 1.4,
               .min = 0,
               .description = "principal moment of inertia"},
              {.id = "I3",
               .label = "I3",
               .defaultValue = 1.9,
               .min = 0,
               .description = "principal moment of inertia"},
              {.id = "R", .label = "R", .defaultValue = 1.0, .min = 0, .description = "radius of the ball"},
              {.id = "m", .label = "m", .defaultValue = 1.0, .min = 0, .description = "mass of the ball"},
              {.id = "K1",
               .label = "K1",
               .defaultValue = 0.0,
               .description = "gyrostat momentum, body axis 1"},
              {.id = "K2",
               .label = "K2",
               .defaultValue = 0.0,
               .description = "gyrostat momentum, body axis 2"},
              {.id = "K3",
               .label = "K3",
               .defaultValue = 0.0,
               .description = "gyrostat momentum, body axis 3"},
              {.id = "root_step",
               .label = "Step of root finding",
               .defaultValue = 1e-3,
               .min = 1e-12,
               .max = 1e6,
               .description =
                   "scan step in sqrt(G^2 - c^2) when a map point is completed through the energy"},
              {.id = "root_accuracy",
               .label = "Accuracy of root finding",
               .defaultValue = 1e-15,
               .min = 0,
               .max = 1,
               .description = "relative accuracy of the completed G"},
              {.id = "diagram_n",
               .label = "n of the (c, h) diagram",
               .defaultValue = 1.0,
               .min = 0,
               .description =
                   "n = |M + K|^2 at which the (c, h) bifurcation diagram cuts the bifurcation set"},
          },
      .stateNames = body_state::names(),
      .coreDimension = 6,
      .integralNames = {"E", "H", "geometric", "n"},
      .hasMeasure = true,
      .mapCoordinates = {"l", "L/G"},
      .section = "g",
  };
  return info;
}

ChaplyginBall::ChaplyginBall(const ParameterValues& p) : ModelWithField(staticInfo(), p) {
  I_ = rigid_body::principalMoments(p); // positive, triangle inequality, m > 0
  if (!(p["R"] > 0)) throw InputError("R: the radius must be positive");
  R_ = p["R"];
  D_ = p["m"] * R_ * R_;
  for (int i = 0; i < 3; ++i)
    Jinv_[i] = 1.0 / (I_[i] + D_);
  K_ = {p["K1"], p["K2"], p["K3"]};
  c_ = {{Jinv_[0], Jinv_[1], Jinv_[2]}, {K_[0], K_[1], K_[2]}, D_, R_};

  addStandardObservables();
  const auto M = [](const double* x) { return Eigen::Vector3d(x[0], x[1], x[2]); };
  const auto gam = [](const double* x) { return Eigen::Vector3d(x[3], x[4], x[5]); };
  const auto omega = [this, M, gam](const double* x) { return angularVelocity<double>(M(x), gam(x)); };
  addObservables(body_state::kinematicObservables(
      omega, [this, M](const double* x) { return Eigen::Vector3d(M(x) + K_); },
      [this, omega, gam](const double* x) { return Eigen::Vector3d(R_ * omega(x).cross(gam(x))); }));
}

Eigen::VectorXd ChaplyginBall::integrals(const double* x) const {
  const Eigen::Vector3d M(x[0], x[1], x[2]), g(x[3], x[4], x[5]);
  const Eigen::Vector3d w = angularVelocity<double>(M, g), P = M + K_;
  Eigen::VectorXd v(4);
  v << 0.5 * M.dot(w), P.dot(g), g.squaredNorm(), P.squaredNorm(); // (26)
  return v;
}

double ChaplyginBall::measureDensity(const double* x) const {
  const Eigen::Vector3d g(x[3], x[4], x[5]);
  return 1.0 / std::sqrt(1.0 - D_ * g.dot(Jinv_.cwiseProduct(g))); // (27)
}

std::optional<BodyPose> ChaplyginBall::pose(const double* x) const {
  BodyPose p;
  p.rotation = body_state::rotation(x);
  p.contact = {x[12], x[13], 0};
  p.centre = {x[12], x[13], R_};
  return p;
}

Eigen::VectorXd ChaplyginBall::stateFromNamed(const std::map<std::string, double>& named,
                                              const std::string& context) const {
  const auto [M, g] = body_state::momentumAndVertical(named, context);
  Eigen::VectorXd x = body_state::fromMomentumAndVertical(M, g);
  assignNamed(named, context, x); // explicit alpha, beta, x, y, trace lengths override the derived ones
  x.segment<3>(3).normalize();
  return x;
}

std::vector<Diagram> ChaplyginBall::diagrams() const {
  const double E = params_["energy"], c = params_["c"];
  // default ranges reach a few times the n of the scene's energy level: |M + K| <= sqrt(2 E max J) + |K|
  const double nLevel = std::pow(std::sqrt(2 * E / Jinv_.minCoeff()) + K_.norm(), 2);
  const double base = std::max({nLevel, c * c, K_.squaredNorm()});
  return ChaplyginBifurcationSet(I_, D_, K_)
      .diagrams(c, params_["diagram_n"], base > 0 ? 2 * base : 1.0, [this](const double* x) {
        const Eigen::VectorXd v = integrals(x);
        return ChaplyginBifurcationSet::Integrals{v[0], v[1], v[3]};
      });
}

std::vector<double> ChaplyginBall::completionRoots(double l, double LG, double g0) const {
  const double E = params_["energy"], c = params_["c"];
  // h(G) on the section: P = M + K from (l, L/G, G), H = c fixed, so H/G = c/G needs G >= |c|
  const auto energyGap = [&](double G) {
    Eigen::Vector3d M, g;
    stateOnSection(l, LG, g0, G, M, g);
    return 0.5 * M.dot(angularVelocity<double>(M, g)) - E;
  };
  // h >= |M|^2 / (2 max J), so every root has G <= sqrt(2 E max J) + |K|
  const double Gmax = std::sqrt(2 * E / Jinv_.minCoeff()) + K_.norm() + 1e-9;
  const double Gmin = std::max(std::abs(c), 1e-12);
  // The scan runs in rho = sqrt(G^2 - c^2), the length of the horizontal part of M + K, not in G: the state
  // is smooth in rho across the pole G = |c| (M + K vertical, where the node angle g is undefined) and only
  // as sqrt(G - |c|) in G, so two roots near the pole that lie 5e-4 apart in G lie 7e-3 apart in rho (the
  // Chaplygin ball's elliptic family near K1 = 0.6666, issue 41). rho increases with G: the roots keep their
  // order, and a step in rho is never coarser in G.
  const double c2 = Gmin * Gmin;
  const auto gOf = [c2](double rho) { return std::sqrt(c2 + rho * rho); };
  auto roots = findRoots([&](double rho) { return energyGap(gOf(rho)); }, 0.0, std::sqrt(Gmax * Gmax - c2),
                         params_["root_step"], params_["root_accuracy"]);
  for (double& r : roots)
    r = gOf(r);
  return roots;
}

void ChaplyginBall::stateOnSection(double l, double LG, double g0, double G, Eigen::Vector3d& M,
                                   Eigen::Vector3d& g) const {
  fromAndoyerDeprit({.L = LG * G, .G = G, .H = params_["c"], .l = l, .g = g0}, M, g);
  M -= K_;
}

int ChaplyginBall::sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const {
  const AndoyerDeprit ad = toAndoyerDeprit(x.head<3>() + K_, x.segment<3>(3));
  const auto roots = completionRoots(ad.l, ad.L / ad.G, spec.sectionValue);
  int best = 1;
  for (std::size_t i = 1; i < roots.size(); ++i)
    if (std::abs(roots[i] - ad.G) < std::abs(roots[best - 1] - ad.G)) best = static_cast<int>(i) + 1;
  return best;
}

Eigen::VectorXd ChaplyginBall::stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                                            const std::string& context) const {
  if (point.size() != 2) throw InputError(context + ": chaplygin_ball map points are (l, L/G)");
  const double l = point[0], LG = point[1], E = params_["energy"], c = params_["c"];
  if (!(std::abs(LG) <= 1)) throw InputError(context + ": L/G must lie in [-1, 1]");
  const auto roots = completionRoots(l, LG, spec.sectionValue);
  if (roots.empty() || spec.root < 1 || spec.root > static_cast<int>(roots.size())) {
    std::ostringstream os;
    os << context << ": no state at (l, L/G) = (" << l << ", " << LG << ") with energy " << E
       << " and c = " << c;
    if (roots.empty())
      os << " (the point lies outside the region of allowed motion)";
    else
      os << " with root " << spec.root << " (there are " << roots.size() << ")";
    throw InputError(os.str());
  }
  Eigen::Vector3d M, g;
  stateOnSection(l, LG, spec.sectionValue, roots[spec.root - 1], M, g);
  return body_state::fromMomentumAndVertical(M, g);
}

template class ModelWithField<ChaplyginBall, 16, 6>;

} // namespace rv
