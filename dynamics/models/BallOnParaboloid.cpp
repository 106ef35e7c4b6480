#include "dynamics/models/BallOnParaboloid.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace rv {

const ModelInfo& BallOnParaboloid::staticInfo() {
  static const ModelInfo info = [] {
    ModelInfo i{
        .id = "ball_on_paraboloid",
        .title = "Homogeneous ball rolling in a cubically perturbed paraboloid bowl (manual §3.4)",
        .reference =
            "Borisov, Mamaev, Nonholonomic dynamical systems (2002); manual §3.4 with the erratum to (22)",
        .parameters =
            {
                {.id = "energy",
                 .label = "Energy",
                 .defaultValue = 0.05,
                 .min = 0,
                 .description = "energy (M, w)/2 + m g z at which a map point is completed"},
                {.id = "p",
                 .label = "p",
                 .defaultValue = 1.0,
                 .min = 0,
                 .description = "radius of curvature of the centre's paraboloid along x (b1 of (21))"},
                {.id = "q",
                 .label = "q",
                 .defaultValue = 2.0,
                 .min = 0,
                 .description = "radius of curvature of the centre's paraboloid along y (b2 of (21))"},
                {.id = "R", .label = "R", .defaultValue = 0.3, .min = 0, .description = "radius of the ball"},
                {.id = "mu",
                 .label = "mu",
                 .defaultValue = 0.036,
                 .min = 0,
                 .description = "central moment of inertia of the ball"},
                {.id = "D", .label = "D", .defaultValue = 0.09, .min = 0, .description = "D = m R^2"},
                {.id = "m",
                 .label = "m",
                 .defaultValue = 1.0,
                 .min = 0,
                 .description = "mass of the ball (weight m g)"},
                {.id = "g",
                 .label = "g",
                 .defaultValue = 1.0,
                 .min = 0,
                 .description = "acceleration of gravity"},
                {.id = "Lambda1",
                 .label = "Lambda1",
                 .defaultValue = 0.0,
                 .description = "perturbation L1 x^3 / 3 of (21)"},
                {.id = "Lambda2",
                 .label = "Lambda2",
                 .defaultValue = 0.0,
                 .description = "perturbation L2 x^2 y / 3 of (21)"},
                {.id = "Lambda3",
                 .label = "Lambda3",
                 .defaultValue = 0.0,
                 .description = "perturbation L3 x y^2 / 3 of (21)"},
                {.id = "Lambda4",
                 .label = "Lambda4",
                 .defaultValue = 0.0,
                 .description = "perturbation L4 y^3 / 3 of (21)"},
            },
        .stateNames = {"M1", "M2", "M3", "x1", "x2", "q0", "q1", "q2", "q3", "s_surface", "s_ball"},
        .coreDimension = 5,
        .integralNames = {"E", "F"},
        .hasMeasure = true,
        .mapCoordinates = {"x1", "omega1", "omega2"},
        .section = "x2",
    };
    return i;
  }();
  return info;
}

BallOnParaboloid::BallOnParaboloid(const ParameterValues& p)
    : ModelWithField(staticInfo(), p), p_(p["p"]), q_(p["q"]), R_(p["R"]), mu_(p["mu"]), D_(p["D"]),
      m_(p["m"]), g_(p["g"]), L_{p["Lambda1"], p["Lambda2"], p["Lambda3"], p["Lambda4"]} {
  for (const char* id : {"p", "q", "R", "mu", "D", "m"})
    if (!(p[id] > 0)) throw InputError(std::string(id) + ": must be positive");
  if (!(R_ < std::min(p_, q_)))
    throw InputError(
        "R: the ball must be smaller than the bowl's least radius of curvature min(p, q) (here " +
        std::to_string(std::min(p_, q_)) + ")");
  c_ = {.ball = ball_on_surface::ballCoefficients(mu_, D_, R_),
        .byTwoP = 1 / (2 * p_),
        .byTwoQ = 1 / (2 * q_),
        .byP = 1 / p_,
        .byQ = 1 / q_,
        .L = {L_[0], L_[1], L_[2], L_[3]},
        .Lthird = {L_[0] / 3, L_[1] / 3, L_[2] / 3, L_[3] / 3},
        .twoThirdsL1 = 2 * L_[1] / 3,
        .twoThirdsL2 = 2 * L_[2] / 3,
        .twoL0 = 2 * L_[0],
        .twoL3 = 2 * L_[3],
        .weight = m_ * g_};
  addStandardObservables();
  const auto n = [this](const double* s) { return normalAt(s[3], s[4]); };
  const auto w = [this, n](const double* s) {
    return ball_on_surface::omega(c_.ball, Eigen::Vector3d(s[0], s[1], s[2]), n(s));
  };
  for (int i = 0; i < 3; ++i) {
    const std::string k = std::to_string(i + 1);
    addObservable("omega" + k, "angular velocity, fixed axis " + k,
                  [w, i](double, const double* s) { return w(s)[i]; });
    addObservable("gamma" + k, "normal of the bowl at the contact, axis " + k,
                  [n, i](double, const double* s) { return n(s)[i]; });
  }
  addObservable("x3", "height of the centre",
                [this](double, const double* s) { return height(s[3], s[4]).phi; });
  addObservable("Lsurface", "length of the contact point's trace on the bowl",
                [](double, const double* s) { return s[9]; });
  addObservable("Lball", "length of the contact point's trace on the ball",
                [](double, const double* s) { return s[10]; });
  addObservable("Ldiff", "Lsurface - Lball", [](double, const double* s) { return s[9] - s[10]; });
}

double BallOnParaboloid::energy(const double* s) const {
  const Eigen::Vector3d M(s[0], s[1], s[2]);
  return ball_on_surface::kinetic(c_.ball, M, normalAt(s[3], s[4])) + m_ * g_ * height(s[3], s[4]).phi;
}

Eigen::VectorXd BallOnParaboloid::integrals(const double* s) const {
  const Eigen::Vector3d M(s[0], s[1], s[2]), n = normalAt(s[3], s[4]);
  const Eigen::Vector3d nM = n.cross(M);
  const double F2 = (nM[0] * nM[0] / p_ + nM[1] * nM[1] / q_) / (n[2] * n[2]); // (24)
  Eigen::VectorXd v(2);
  v << energy(s), F2 + (mu_ + D_) * m_ * g_ * (n[0] * n[0] + n[1] * n[1]) / (n[2] * n[2]);
  return v;
}

double BallOnParaboloid::measureDensity(const double* s) const {
  // rho = g3^-4 of (23) on (M, gamma); on the sphere |gamma| = 1 parametrised by (g1, g2) the area element is
  // dg1 dg2 / g3, and (g1, g2) -> (u, v) brings the Jacobian determinant
  const Height<double> h = height(s[3], s[4]);
  const double w2 = 1 + h.pu * h.pu + h.pv * h.pv, w = std::sqrt(w2), w3 = w2 * w;
  const double su = h.pu * h.puu + h.pv * h.puv, sv = h.pu * h.puv + h.pv * h.pvv;
  const double j11 = -h.puu / w + h.pu * su / w3, j12 = -h.puv / w + h.pu * sv / w3;
  const double j21 = -h.puv / w + h.pv * su / w3, j22 = -h.pvv / w + h.pv * sv / w3;
  const double g3 = 1 / w;
  return std::abs(j11 * j22 - j12 * j21) / std::pow(g3, 5);
}

std::optional<BodyPose> BallOnParaboloid::pose(const double* s) const {
  BodyPose p;
  p.rotation = ball_on_surface::rotation(s + 5);
  p.centre = centre(s[3], s[4]);
  p.supportNormal = normalAt(s[3], s[4]);
  p.contact = p.centre - R_ * p.supportNormal;
  return p;
}

std::optional<SupportSurface> BallOnParaboloid::support() const {
  // the bowl the ball touches (the centre's surface moved by -R n), out to where the energy lets the centre
  // climb
  const double climb = std::max(params_["energy"] / (m_ * g_), 0.2 * std::max(p_, q_));
  const double ru = 1.4 * std::sqrt(2 * p_ * climb), rv = 1.4 * std::sqrt(2 * q_ * climb);
  return SupportSurface{[this, ru, rv](double a, double r) {
    const double u = r * ru * std::cos(2 * std::numbers::pi * a);
    const double v = r * rv * std::sin(2 * std::numbers::pi * a);
    return Eigen::Vector3d(centre(u, v) - R_ * normalAt(u, v));
  }};
}

Eigen::VectorXd BallOnParaboloid::stateFrom(const Eigen::Vector3d& w, double u, double v) const {
  const Eigen::Vector3d n = normalAt(u, v);
  Eigen::VectorXd s = Eigen::VectorXd::Zero(11);
  s.head<3>() = (mu_ + D_) * w - D_ * n * n.dot(w);
  s[3] = u, s[4] = v, s[5] = 1;
  return s;
}

Eigen::VectorXd BallOnParaboloid::stateFromNamed(const std::map<std::string, double>& named,
                                                 const std::string& context) const {
  for (const char* k : {"x1", "x2"})
    if (!named.count(k)) throw InputError(context + ": missing state component '" + k + "'");
  std::map<std::string, double> rest = named;
  Eigen::VectorXd s;
  if (named.count("omega1") || named.count("omega2") || named.count("omega3")) {
    Eigen::Vector3d w;
    for (int i = 0; i < 3; ++i) {
      const std::string k = "omega" + std::to_string(i + 1);
      if (!named.count(k)) throw InputError(context + ": missing '" + k + "' (give omega1..3 or M1..3)");
      w[i] = named.at(k);
      rest.erase(k);
    }
    s = stateFrom(w, named.at("x1"), named.at("x2"));
  } else {
    for (const char* k : {"M1", "M2", "M3"})
      if (!named.count(k))
        throw InputError(context + ": missing state component '" + k + "' (or give omega1..3)");
    s = stateFrom(Eigen::Vector3d::Zero(), named.at("x1"), named.at("x2"));
  }
  assignNamed(rest, context, s);
  s.segment<4>(5).normalize();
  return s;
}

Eigen::VectorXd BallOnParaboloid::stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                                               const std::string& context) const {
  if (point.size() != 3)
    throw InputError(context + ": ball_on_paraboloid map points are (x1, omega1, omega2)");
  const double u = point[0], v = spec.sectionValue, w1 = point[1], w2 = point[2], E = params_["energy"];
  const Eigen::Vector3d n = normalAt(u, v);
  // (M, w) = (mu + D)|w|^2 - D (n, w)^2 = 2 (E - m g z): a quadratic in w3
  const double nw12 = n[0] * w1 + n[1] * w2, kinetic = E - m_ * g_ * height(u, v).phi;
  const double a = 0.5 * ((mu_ + D_) - D_ * n[2] * n[2]), b = -D_ * n[2] * nw12;
  const double c = 0.5 * ((mu_ + D_) * (w1 * w1 + w2 * w2) - D_ * nw12 * nw12) - kinetic;
  const double disc = b * b - 4 * a * c;
  if (!(disc >= 0)) {
    std::ostringstream os;
    os << context << ": no state at (x1, omega1, omega2) = (" << u << ", " << w1 << ", " << w2
       << ") on x2 = " << v << " with energy " << E
       << " (the point lies outside the region of allowed motion)";
    throw InputError(os.str());
  }
  if (spec.root != 1 && spec.root != 2)
    throw InputError(context + ": root must be 1 (the smaller omega3) or 2");
  const double w3 = (-b + (spec.root == 1 ? -1 : 1) * std::sqrt(disc)) / (2 * a);
  return stateFrom(Eigen::Vector3d(w1, w2, w3), u, v);
}

template class ModelWithField<BallOnParaboloid, 11, 5>;

} // namespace rv
