#include "dynamics/models/BallOnEllipsoid.h"

#include "dynamics/core/Errors.h"
#include "dynamics/kinematics/AndoyerDeprit.h"
#include "dynamics/kinematics/RootFinding.h"
#include "dynamics/models/BodyState.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace rv {

const ModelInfo& BallOnEllipsoid::staticInfo() {
  static const ModelInfo info{
      .id = "ball_on_ellipsoid",
      .title = "Homogeneous ball rolling on a triaxial ellipsoid (manual §3.3)",
      .reference =
          "Borisov, Mamaev, Nonholonomic dynamical systems (2002); manual §3.3 with the erratum to (20)",
      .parameters =
          {
              {.id = "energy",
               .label = "Energy",
               .defaultValue = 0.5,
               .min = 0,
               .description = "energy H of (14) at which a map point is completed"},
              {.id = "integral",
               .label = "Integral",
               .defaultValue = 0.2,
               .description =
                   "value of the integral K of (20) at which a 2D map point (l, L/G) is completed"},
              {.id = "mu",
               .label = "mu",
               .defaultValue = 0.4,
               .min = 0,
               .description = "central moment of inertia of the ball"},
              {.id = "D", .label = "D", .defaultValue = 1.0, .min = 0, .description = "D = m R^2"},
              {.id = "R", .label = "R", .defaultValue = 0.3, .min = 0, .description = "radius of the ball"},
              {.id = "b1",
               .label = "b1",
               .defaultValue = 1.5,
               .min = 0,
               .description = "semi-axis of the ellipsoid on which the centre moves, axis 1"},
              {.id = "b2",
               .label = "b2",
               .defaultValue = 1.1,
               .min = 0,
               .description = "semi-axis of the ellipsoid on which the centre moves, axis 2"},
              {.id = "b3",
               .label = "b3",
               .defaultValue = 0.8,
               .min = 0,
               .description = "semi-axis of the ellipsoid on which the centre moves, axis 3"},
              {.id = "k",
               .label = "k",
               .defaultValue = 0.0,
               .description = "field k |x|^2 / 2 of the centre x (19)"},
              {.id = "c1",
               .label = "c1",
               .defaultValue = 0.0,
               .min = 0,
               .description = "field c1 / x1^2 (19)"},
              {.id = "c2",
               .label = "c2",
               .defaultValue = 0.0,
               .min = 0,
               .description = "field c2 / x2^2 (19)"},
              {.id = "c3",
               .label = "c3",
               .defaultValue = 0.0,
               .min = 0,
               .description = "field c3 / x3^2 (19)"},
              {.id = "root_step",
               .label = "Step of root finding",
               .defaultValue = 1e-3,
               .min = 1e-9,
               .max = 1,
               .description = "scan step in H/G when a 2D map point is completed"},
              {.id = "root_accuracy",
               .label = "Accuracy of root finding",
               .defaultValue = 1e-15,
               .min = 0,
               .max = 1,
               .description = "accuracy of the completed H/G"},
          },
      .stateNames = {"M1", "M2", "M3", "gamma1", "gamma2", "gamma3", "q0", "q1", "q2", "q3", "s_surface",
                     "s_ball"},
      .coreDimension = 6,
      .integralNames = {"E", "geometric", "K"},
      .hasMeasure = true,
      .mapCoordinates = {"l", "L/G"},
      .section = "g",
  };
  return info;
}

BallOnEllipsoid::BallOnEllipsoid(const ParameterValues& p)
    : ModelWithField(staticInfo(), p), mu_(p["mu"]), D_(p["D"]), R_(p["R"]), k_(p["k"]) {
  if (!(mu_ > 0)) throw InputError("mu: the moment of inertia must be positive");
  if (!(D_ > 0)) throw InputError("D: D = m R^2 must be positive");
  if (!(R_ > 0)) throw InputError("R: the radius must be positive");
  for (int i = 0; i < 3; ++i) {
    const std::string id = "b" + std::to_string(i + 1);
    if (!(p[id] > 0)) throw InputError(id + ": a semi-axis must be positive");
    B_[i] = p[id] * p[id];
    Binv_[i] = 1 / B_[i];
  }
  // the ball touches the parallel surface x - R gamma: smooth only while R is below every radius of curvature
  double least = 1e300;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) least = std::min(least, B_[i] / std::sqrt(B_[j]));
  if (!(R_ < least)) {
    std::ostringstream os;
    os << "R = " << R_ << " is not below the least radius of curvature " << least
       << " of the centre's ellipsoid: the ball would touch the ellipsoid at more than one point";
    throw InputError(os.str());
  }
  c_ = {p["c1"], p["c2"], p["c3"]};
  coefficients_ = {.ball = ball_on_surface::ballCoefficients(mu_, D_, R_),
                   .B = {B_[0], B_[1], B_[2]},
                   .Binv = {Binv_[0], Binv_[1], Binv_[2]},
                   .twoC = {2 * c_[0], 2 * c_[1], 2 * c_[2]},
                   .k = k_};
  addStandardObservables();
  const auto M = [](const double* s) { return Eigen::Vector3d(s[0], s[1], s[2]); };
  const auto gam = [](const double* s) { return Eigen::Vector3d(s[3], s[4], s[5]); };
  for (int i = 0; i < 3; ++i) {
    const std::string n = std::to_string(i + 1);
    addObservable("omega" + n, "angular velocity, fixed axis " + n, [=, this](double, const double* s) {
      return ball_on_surface::omega(coefficients_.ball, M(s), gam(s))[i];
    });
    addObservable("x" + n, "centre of the ball, fixed axis " + n,
                  [=, this](double, const double* s) { return centre(gam(s))[i]; });
  }
  const auto ad = [M, gam](const double* s) { return toAndoyerDeprit(M(s), gam(s)); };
  addObservable("G", "Andoyer-Deprit G = |M|", [ad](double, const double* s) { return ad(s).G; });
  addObservable("l", "Andoyer-Deprit l", [ad](double, const double* s) { return ad(s).l; });
  observables_.back().angle = true;
  addObservable("g", "Andoyer-Deprit g", [ad](double, const double* s) { return ad(s).g; });
  observables_.back().angle = true;
  addObservable("L/G", "Andoyer-Deprit L/G", [ad](double, const double* s) { return ad(s).L / ad(s).G; });
  addObservable("H/G", "Andoyer-Deprit H/G", [ad](double, const double* s) { return ad(s).H / ad(s).G; });
  addObservable("Lsurface", "length of the contact point's trace on the ellipsoid",
                [](double, const double* s) { return s[10]; });
  addObservable("Lball", "length of the contact point's trace on the ball",
                [](double, const double* s) { return s[11]; });
  addObservable("Ldiff", "Lsurface - Lball", [](double, const double* s) { return s[10] - s[11]; });
}

double BallOnEllipsoid::energy(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const {
  const Eigen::Vector3d x = centre(g);
  double U = 0.5 * k_ * x.squaredNorm();
  for (int i = 0; i < 3; ++i)
    if (c_[i] != 0) U += c_[i] / (x[i] * x[i]); // no term (not 0 / 0) where the centre crosses x_i = 0
  return ball_on_surface::kinetic(coefficients_.ball, M, g) + U;
}

double BallOnEllipsoid::integralK(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const {
  const Eigen::Vector3d w = ball_on_surface::omega(coefficients_.ball, M, g), gw = g.cross(w);
  const Eigen::Vector3d x = centre(g);
  double field = k_;
  for (int i = 0; i < 3; ++i)
    if (c_[i] != 0) field -= 2 * c_[i] / (B_[i] * x[i] * x[i]);
  return gw.dot(Binv_.cwiseProduct(gw)) / g.dot(B_.cwiseProduct(g)) -
         x.dot(Binv_.cwiseProduct(Binv_.cwiseProduct(x))) * field / (mu_ + D_);
}

Eigen::VectorXd BallOnEllipsoid::integrals(const double* s) const {
  const Eigen::Vector3d M(s[0], s[1], s[2]), g(s[3], s[4], s[5]);
  Eigen::VectorXd v(3);
  v << energy(M, g), g.squaredNorm(), integralK(M, g);
  return v;
}

double BallOnEllipsoid::measureDensity(const double* s) const {
  const Eigen::Vector3d g(s[3], s[4], s[5]);
  const double gBg = g.dot(B_.cwiseProduct(g));
  return 1 / (gBg * gBg); // (17)
}

std::optional<BodyPose> BallOnEllipsoid::pose(const double* s) const {
  const Eigen::Vector3d g = Eigen::Vector3d(s[3], s[4], s[5]).normalized();
  BodyPose p;
  p.rotation = ball_on_surface::rotation(s + 6);
  p.centre = centre(g);
  p.contact = p.centre - R_ * g;
  p.supportNormal = g;
  return p;
}

std::optional<SupportSurface> BallOnEllipsoid::support() const {
  return SupportSurface{[this](double u, double v) {
    const double lon = 2 * std::numbers::pi * u, lat = std::numbers::pi * (v - 0.5);
    const Eigen::Vector3d g(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    return Eigen::Vector3d(centre(g) - R_ * g); // the surface the ball touches
  }};
}

Eigen::VectorXd BallOnEllipsoid::stateFrom(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(12);
  s.head<3>() = M;
  s.segment<3>(3) = g.normalized();
  s[6] = 1; // the ball starts unturned
  return s;
}

Eigen::VectorXd BallOnEllipsoid::stateFromNamed(const std::map<std::string, double>& named,
                                                const std::string& context) const {
  const auto [M, g] = body_state::momentumAndVertical(named, context);
  Eigen::VectorXd s = stateFrom(M, g);
  assignNamed(named, context, s);
  s.segment<3>(3).normalize();
  s.segment<4>(6).normalize();
  return s;
}

Eigen::VectorXd BallOnEllipsoid::stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                                              const std::string& context) const {
  if (point.size() != 2 && point.size() != 3)
    throw InputError(context + ": ball_on_ellipsoid map points are (l, L/G) or (l, L/G, H/G)");
  const double l = point[0], LG = point[1], E = params_["energy"];
  if (!(std::abs(LG) <= 1)) throw InputError(context + ": L/G must lie in [-1, 1]");
  // for fixed angles gamma and the direction of M are fixed and the energy is quadratic in G
  const auto complete = [&](double HG, Eigen::Vector3d& M, Eigen::Vector3d& g) {
    Eigen::Vector3d e;
    fromAndoyerDeprit({.L = LG, .G = 1, .H = HG, .l = l, .g = spec.sectionValue}, e, g);
    const double kinetic = E - energy(Eigen::Vector3d::Zero(), g);
    if (!(kinetic >= 0)) return false;
    M = std::sqrt(kinetic / ball_on_surface::kinetic(coefficients_.ball, e, g)) * e;
    return true;
  };
  std::ostringstream where;
  where << context << ": no state at this map point with energy " << E;
  Eigen::Vector3d M, g;
  if (point.size() == 3) {
    if (!(std::abs(point[2]) <= 1)) throw InputError(context + ": H/G must lie in [-1, 1]");
    if (!complete(point[2], M, g)) throw InputError(where.str() + " (outside the region of allowed motion)");
    return stateFrom(M, g);
  }
  const double K0 = params_["integral"];
  const auto gap = [&](double HG) {
    Eigen::Vector3d m, gg;
    return complete(HG, m, gg) ? integralK(m, gg) - K0 : std::nan("");
  };
  std::vector<double> roots;
  for (double r : findRoots(
           [&](double HG) {
             const double v = gap(HG);
             return std::isnan(v) ? 1e300 : v;
           },
           -1 + 1e-12, 1 - 1e-12, params_["root_step"], params_["root_accuracy"]))
    if (std::abs(gap(r)) < 1e-8 * std::max(1.0, std::abs(K0)))
      roots.push_back(r); // not a jump at a forbidden zone
  if (roots.empty() || spec.root < 1 || spec.root > static_cast<int>(roots.size())) {
    where << " and integral K = " << K0;
    if (roots.empty())
      where << " (the point lies outside the region of allowed motion)";
    else
      where << " with root " << spec.root << " (there are " << roots.size() << ")";
    throw InputError(where.str());
  }
  complete(roots[spec.root - 1], M, g);
  return stateFrom(M, g);
}

template class ModelWithField<BallOnEllipsoid, 12, 6>;

} // namespace rv
