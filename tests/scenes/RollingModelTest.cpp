// Rolling bodies from their geometry (scenes/RollingModel.h, examples/rolling): the model language's exact
// derivatives against derivatives taken by hand; each built-in body on a plane, restated by its geometry,
// gives the built-in model's field, Jacobian, integrals, measure and trajectory; marble and rubber rolling
// keep their energy, rubber rolling its zero spin about the normal; the tippe top turns over exactly inside
// its inertia window (Bou-Rabee, Marsden & Romero 2004; Rauch-Wojciechowski & Rutstam 2014) with Jellett's
// integral kept; a malformed description is named at the field the user wrote.
#include "scenes/RollingModel.h"
#include "dynamics/core/BodyShapes.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/FixedPoint.h"
#include "scenes/ModelFile.h"
#include "tests/scenes/ModelFileSupport.h"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <tuple>

namespace rv {
namespace {
using namespace testing_model_files; // NOLINT(google-build-using-namespace): the shared helpers, unqualified
using nlohmann::json;

std::unique_ptr<Model> instance(const ModelEntry& e, const std::map<std::string, double>& set = {}) {
  ParameterValues p(e.info->parameters);
  for (const auto& [k, v] : set)
    p.set(k, v);
  return e.create(p);
}

double observable(const Model& m, const std::string& id, const double* x) {
  const int i = m.findObservable(id);
  EXPECT_GE(i, 0) << id;
  return i < 0 ? NAN : m.observables()[static_cast<std::size_t>(i)].value(0, x);
}

TEST(ModelLanguage, DerivativeGradientAndJacobianAreTheDerivativesTakenByHand) {
  const json model = {
      {"id", "derivatives_by_hand"},
      {"state", {"x", "y"}},
      {"definitions", {{"f", "x^3*sin(y) + exp(x*y) + atan2(y, x) + sqrt(x^2 + y^2) + max(x, 2*y)"}}},
      {"equations", {{"x", "derivative(f, [x, y], [2, 3])"}, {"y", "gradient(f, [x, y])[1]"}}},
      {"observables",
       {{"fy", {{"value", "jacobian([f, x*y], [x, y])[1, 2]"}}},
        {"dxy_dx", {{"value", "jacobian([f, x*y], [x, y])[2, 1]"}}}}}};
  const auto m = instance(modelEntryFromJson(model, "<derivatives>"));
  const double x = 0.7, y = 0.4, r = std::hypot(x, y), s[2] = {x, y};
  // by hand; max(x, 2y) takes 2y here
  const double fx = 3 * x * x * std::sin(y) + y * std::exp(x * y) - y / (r * r) + x / r;
  const double fy = x * x * x * std::cos(y) + x * std::exp(x * y) + x / (r * r) + y / r + 2;
  double f[2];
  m->rhs(s, f);
  EXPECT_NEAR(f[0], 2 * fx + 3 * fy, 1e-13);
  EXPECT_NEAR(f[1], fx, 1e-14);
  EXPECT_NEAR(observable(*m, "fy", s), fy, 1e-14);
  EXPECT_NEAR(observable(*m, "dxy_dx", s), y, 1e-15);
  // the field's own Jacobian goes through the derivative nodes: second derivatives, against differences
  Eigen::Matrix<double, 2, 2, Eigen::RowMajor> J;
  m->jacobian(s, J.data());
  const double h = 1e-6;
  for (int j = 0; j < 2; ++j) {
    double plus[2] = {x, y}, minus[2] = {x, y}, fp[2], fm[2];
    plus[j] += h;
    minus[j] -= h;
    m->rhs(plus, fp);
    m->rhs(minus, fm);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(J(i, j), (fp[i] - fm[i]) / (2 * h), 1e-7 * (1 + std::abs(J(i, j))));
  }
}

TEST(ModelLanguage, ADerivativeNeedsVariablesAndARateOfTheirShape) {
  json model = {{"id", "bad_derivative"}, {"state", {"x", "y"}}, {"equations", {{"x", "y"}, {"y", ""}}}};
  model["equations"]["y"] = "derivative(x^2, 2, 1)";
  EXPECT_NE(modelFileError(model).find("argument 2 of 'derivative' must be variables"), std::string::npos)
      << modelFileError(model);
  model["equations"]["y"] = "derivative(x^2, x, [1, 2])";
  EXPECT_NE(modelFileError(model).find("argument 3 of 'derivative' must be the shape of argument 2"),
            std::string::npos)
      << modelFileError(model);
  // derivatives of derivatives grow geometrically: an error naming where, not a hang
  json nested = {{"id", "nested_derivatives"}, {"state", {"x", "y"}}};
  nested["definitions"]["f1"] = "sin(x*y)*exp(x)/(1 + y^2)";
  for (int k = 2; k <= 30; ++k)
    nested["definitions"]["f" + std::to_string(k)] = "gradient(f" + std::to_string(k - 1) + ", [x, y])[1]";
  nested["equations"] = {{"x", "f30"}, {"y", "x"}};
  EXPECT_NE(modelFileError(nested).find("operations (derivatives of derivatives grow geometrically)"),
            std::string::npos)
      << modelFileError(nested);
}

/// The built-in and the restated field agree where the motion lives (|gamma| = 1; off it the two may extend
/// the field differently): the field, its Jacobian along directions that keep |gamma|, the tangent products,
/// the measure and every observable of the same name.
void expectTheSameMotion(const Model& a, const Model& b, const Eigen::VectorXd& x) {
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const int n = a.dimension(), m = a.info().coreDimension, k = 4;
  ASSERT_EQ(n, b.dimension());
  ASSERT_EQ(m, b.info().coreDimension);
  // directions along the motion's manifold: the frame (gamma, alpha, beta) turned together by a random eta
  const auto& names = a.info().stateNames;
  const auto at = [&](const char* name) {
    return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  Eigen::MatrixXd V = Eigen::MatrixXd::Random(n, k);
  for (int c = 0; c < k; ++c) {
    const Eigen::Vector3d eta = Eigen::Vector3d::Random();
    for (const char* frame : {"gamma1", "alpha1", "beta1"}) // those the model has
      if (const int i = at(frame); i < n) V.col(c).segment<3>(i) = x.segment<3>(i).cross(eta);
  }
  Eigen::VectorXd fa(n), fb(n);
  a.rhs(x.data(), fa.data());
  b.rhs(x.data(), fb.data());
  EXPECT_LT((fa - fb).cwiseAbs().maxCoeff(), 1e-13 * (1 + fa.cwiseAbs().maxCoeff()));
  RowMajor ja(n, n), jb(n, n);
  a.jacobian(x.data(), ja.data());
  b.jacobian(x.data(), jb.data());
  EXPECT_LT((ja * V - jb * V).cwiseAbs().maxCoeff(), 1e-12 * (1 + (ja * V).cwiseAbs().maxCoeff()));
  const Eigen::MatrixXd W = V.topRows(m);
  Eigen::MatrixXd dWa(m, k), dWb(m, k);
  a.tangentRhs(x.data(), W.data(), k, fa.data(), dWa.data());
  b.tangentRhs(x.data(), W.data(), k, fb.data(), dWb.data());
  EXPECT_LT((dWa - dWb).cwiseAbs().maxCoeff(), 1e-12 * (1 + dWa.cwiseAbs().maxCoeff()));
  EXPECT_NEAR(a.measureDensity(x.data()), b.measureDensity(x.data()), 1e-13);
  int same = 0;
  for (const auto& o : a.observables()) {
    const int i = b.findObservable(o.id);
    if (i < 0) continue;
    ++same;
    const double va = o.value(0.5, x.data()),
                 vb = b.observables()[static_cast<std::size_t>(i)].value(0.5, x.data());
    EXPECT_NEAR(va, vb, 1e-12 * (1 + std::abs(va))) << o.id;
  }
  EXPECT_GE(same, 5);
}

struct Restated {
  const char* id;
  std::map<std::string, double> parameters, state;
};

TEST(RollingModel, EachBuiltInRollingBodyRestatedByItsGeometryIsTheBuiltInModel) {
  const double g3 = std::sqrt(1 - 0.005);
  const std::vector<Restated> bodies{
      {"ellipsoid_on_plane",
       {{"B11", 0.1}, {"B12", 0.02}, {"B22", 0.05}, {"a1", 0.05}, {"phi", 0.3}, {"theta", 0.2}},
       {{"M1", 0.1}, {"M2", 0.05}, {"M3", 0.3}, {"gamma1", 0.05}, {"gamma2", 0.05}, {"gamma3", g3}}},
      {"paraboloid_on_plane",
       {{"h", 0.7}, {"delta", 0.4}},
       {{"M1", 0.3},
        {"M2", -0.2},
        {"M3", 0.5},
        {"gamma1", 0.1},
        {"gamma2", 0.2},
        {"gamma3", std::sqrt(0.95)}}},
      {"chaplygin_ball",
       {{"K1", 0.1}, {"K3", -0.2}, {"R", 0.8}},
       {{"M1", 0.3}, {"M2", 0.5}, {"M3", 0.4}, {"gamma1", 0.0}, {"gamma2", 0.6}, {"gamma3", 0.8}}},
      {"ball_on_ellipsoid", // on a curved support: the ellipsoid the centre moves on, in a field
       {{"k", 0.5}, {"R", 0.25}},
       {{"M1", 0.2},
        {"M2", -0.1},
        {"M3", 0.3},
        {"gamma1", 0.3 / std::sqrt(0.98)},
        {"gamma2", 0.5 / std::sqrt(0.98)},
        {"gamma3", 0.8 / std::sqrt(0.98)}}},
      {"ball_on_paraboloid", // the centre's surface as a height over the plane, perturbed
       {{"Lambda1", 0.1}, {"Lambda3", 0.05}, {"Lambda4", -0.02}},
       {{"M1", 0.05}, {"M2", 0.1}, {"M3", 0.02}, {"x1", 0.2}, {"x2", 0.1}}}};
  for (const Restated& b : bodies) {
    SCOPED_TRACE(b.id);
    const Pair p = pairOf(b.id, std::string("rolling/") + b.id + ".json", b.parameters);
    const Eigen::VectorXd x = named(*p.builtin, b.state);
    EXPECT_LT((x - named(*p.file, b.state)).cwiseAbs().maxCoeff(), 1e-15); // the frame completed alike
    expectTheSameMotion(*p.builtin, *p.file, x);
    EXPECT_LT(trajectoryDifference(*p.builtin, *p.file, x, 10), 1e-9);
    const auto pa = p.builtin->pose(x.data()), pb = p.file->pose(x.data());
    ASSERT_TRUE(pa && pb);
    EXPECT_LT((pa->centre - pb->centre).norm() + (pa->contact - pb->contact).norm() +
                  (pa->rotation - pb->rotation).norm(),
              1e-13);
    EXPECT_EQ(p.builtin->geometry()->shape, p.file->geometry()->shape);
  }
}

/// A run of an example model from `start` to T, its states every `every`.
struct ExampleRun {
  std::vector<Eigen::VectorXd> states;
  std::unique_ptr<Model> model;
};

ExampleRun runModel(std::unique_ptr<Model> model, const std::map<std::string, double>& start, double T,
                    double every) {
  ExampleRun r{{}, std::move(model)};
  auto integrator = verner(1e-13);
  integrator->start(*r.model, 0, named(*r.model, start));
  Eigen::VectorXd y(r.model->dimension());
  for (double t = 0; t <= T + 1e-12; t += every) {
    while (integrator->time() < t)
      integrator->step();
    integrator->interpolate(t, y);
    r.states.push_back(y);
  }
  return r;
}

ExampleRun runExample(const std::string& file, const std::map<std::string, double>& set,
                      const std::map<std::string, double>& start, double T, double every) {
  return runModel(instance(modelFileEntry(examples(file, "rolling")), set), start, T, every);
}

std::vector<double> along(const ExampleRun& r, const std::string& id) {
  std::vector<double> v;
  for (const Eigen::VectorXd& x : r.states)
    v.push_back(observable(*r.model, id, x.data()));
  return v;
}

double relativeDrift(const std::vector<double>& v) {
  double worst = 0;
  for (double e : v)
    worst = std::max(worst, std::abs(e - v.front()));
  return worst / std::abs(v.front());
}

TEST(RollingModel, MarbleAndRubberRollingKeepTheirEnergyAndRubberNeverSpinsAboutTheNormal) {
  const ExampleRun rubber = runExample("rubber_rattleback.json", {},
                                       {{"M1", 0.1},
                                        {"M2", 0.3},
                                        {"M3", 0.2}, // its normal part is the constraint's
                                        {"gamma1", 0.05},
                                        {"gamma2", 0.05},
                                        {"gamma3", std::sqrt(1 - 0.005)}},
                                       20, 0.5);
  EXPECT_LT(relativeDrift(along(rubber, "E")), 1e-10);
  for (double s : along(rubber, "spin_normal"))
    EXPECT_LT(std::abs(s), 1e-13);
  // M's part along gamma is the constraint's to choose: 0.3 more of it is the same motion
  const ExampleRun shifted = runExample("rubber_rattleback.json", {},
                                        {{"M1", 0.1 + 0.3 * 0.05},
                                         {"M2", 0.3 + 0.3 * 0.05},
                                         {"M3", 0.2 + 0.3 * std::sqrt(1 - 0.005)},
                                         {"gamma1", 0.05},
                                         {"gamma2", 0.05},
                                         {"gamma3", std::sqrt(1 - 0.005)}},
                                        20, 0.5);
  for (const char* id : {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "E"}) {
    const std::vector<double> a = along(rubber, id), b = along(shifted, id);
    for (std::size_t i = 0; i < a.size(); ++i)
      EXPECT_NEAR(a[i], b[i], 1e-8) << id << " at t = " << 0.5 * static_cast<double>(i);
  }
  const ExampleRun disk = runExample("disk.json", {},
                                     {{"M1", 0.0},
                                      {"M2", 0.1},
                                      {"M3", 2.0},
                                      {"gamma1", 0.0},
                                      {"gamma2", 0.9},
                                      {"gamma3", std::sqrt(1 - 0.81)}},
                                     20, 0.5);
  EXPECT_LT(relativeDrift(along(disk, "E")), 1e-10);
  double lowest = 1;
  for (double z : along(disk, "Z"))
    lowest = std::min(lowest, z);
  EXPECT_GT(lowest, 0.3); // it leans into its turn and rolls on, never falling flat
}

// The rolling disk's steady circular motion, derived by hand from Newton-Euler in the Euler angles' (Resal)
// frame (E. J. Routh, Advanced Dynamics of a System of Rigid Bodies (1905) §244; O. M. O'Reilly, The
// dynamics of rolling disks and sliding disks, Nonlinear Dyn. 10 (1996) 287-305). The symmetry axis e3 is at
// theta from the upward vertical k; e1 = k x e3 / sin(theta) is horizontal, e2 = e3 x e1 lies in the disk's
// plane with k = sin(theta) e2 + cos(theta) e3, and the contact (the rim's lowest point) is r = -R e2 from
// the centre G. With psi the heading and n = omega3 the spin about the axis, omega = theta' e1 + psi'
// sin(theta) e2 + n e3. A steady motion has theta' = 0, psi' = Omega and n constant:
//  - no slip: v_G = omega x (R e2) = -R n e1; the frame turns at Omega k, so a_G = -R n Omega k x e1 =
//    R n Omega (sin(theta) e3 - cos(theta) e2): G circles at radius R n / Omega;
//  - the contact force F = m a_G + m g k;
//  - H_G = I1 Omega sin(theta) e2 + I3 n e3 is constant in the frame: dH_G/dt = Omega k x H_G =
//    Omega sin(theta) (I3 n - I1 Omega cos(theta)) e1, and the torque of F about G is
//    -R e2 x F = -R (m R n Omega sin(theta) + m g cos(theta)) e1; so
//      I1 Omega^2 sin(theta) cos(theta) - (I3 + m R^2) n Omega sin(theta) = m g R cos(theta).
// (n = 0, the centre at rest, gives I1 Omega^2 sin(theta) = m g R: Euler's disk, Omega^2 = 4 g / (R
// sin(theta)) for a uniform disk.) In the model's body variables cos(theta) = gamma3, n = omega3 and, from
// (omega, k) = psi' sin^2(theta) + n cos(theta), Omega = ((omega, gamma) - omega3 gamma3) / (1 - gamma3^2).
// In (M, gamma) a steady motion is a periodic orbit (gamma turns about e3) of a two-parameter family (the
// disk's energy and Chaplygin's two integrals), so a fixed point of the map on gamma1 = 0 where D Map - I has
// rank 2 of 4: the search takes least-norm steps and ends at the family's point nearest a perturbed guess.
TEST(RollingModel, TheRollingDisksSteadyMotionIsAFixedPointWithRouthsRelation) {
  const double R = 1, m = 1, I1 = 0.25, I3 = 0.5, g = 1; // disk.json's defaults: a uniform disk
  const auto disk = instance(modelFileEntry(examples("disk.json", "rolling")));
  const ReturnMap map(
      *disk, [] { return verner(1e-13); }, SectionSettings{});
  const auto relation = [&](double cosTheta, double n, double Omega) {
    const double sinTheta = std::sqrt(1 - cosTheta * cosTheta);
    return I1 * Omega * Omega * sinTheta * cosTheta - (I3 + m * R * R) * n * Omega * sinTheta -
           m * g * R * cosTheta;
  };
  for (const double sinTheta : {0.9, 0.8}) {
    SCOPED_TRACE(sinTheta);
    // a steady motion to start near: on the section e1, e2 are body axes 1, 2, omega = (0, Omega sin, n)
    // and M = A omega with A = diag(I1 + m R^2, I1, I3 + m R^2) about the contact (0, -R, 0); Omega the
    // slow root of the relation for a spin n
    const double cosTheta = std::sqrt(1 - sinTheta * sinTheta), n = 2 * sinTheta;
    const double a = I1 * sinTheta * cosTheta, b = -(I3 + m * R * R) * n * sinTheta,
                 c = -m * g * R * cosTheta;
    const double Omega = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
    ASSERT_NEAR(relation(cosTheta, n, Omega), 0, 1e-14);
    const Eigen::Vector4d steady(0, I1 * Omega * sinTheta, (I3 + m * R * R) * n, sinTheta);
    const Eigen::Vector4d guess = steady + Eigen::Vector4d(0.02, 0.03, -0.04, -0.015);
    FixedPointSettings settings;
    settings.accuracy = 1e-10;
    const FixedPointResult r = findFixedPoint(map, guess, settings);
    EXPECT_EQ(r.family, 2);
    EXPECT_EQ(r.type, FixedPointType::Elliptic) << toString(r.type);
    EXPECT_LT(r.residual, 1e-10);
    EXPECT_LT((r.point - guess).norm(), 0.06);  // the family's point nearest the guess, not one far along it
    EXPECT_GT((r.point - steady).norm(), 1e-3); // another steady motion than the one perturbed
    // the motion found keeps its tilt, spin and turning rate, and they obey the relation
    const Eigen::VectorXd x = map.stateOf(r.point);
    const ExampleRun run = runModel(
        instance(modelFileEntry(examples("disk.json", "rolling"))),
        {{"M1", x[0]}, {"M2", x[1]}, {"M3", x[2]}, {"gamma1", x[3]}, {"gamma2", x[4]}, {"gamma3", x[5]}}, 10,
        0.5);
    for (const Eigen::VectorXd& y : run.states) {
      const double cosY = y[5], nY = observable(*run.model, "omega3", y.data());
      const double OmegaY = (observable(*run.model, "omega1", y.data()) * y[3] +
                             observable(*run.model, "omega2", y.data()) * y[4]) /
                            (1 - cosY * cosY);
      EXPECT_NEAR(cosY, x[5], 1e-9);
      EXPECT_NEAR(nY, observable(*disk, "omega3", x.data()), 1e-9);
      EXPECT_NEAR(relation(cosY, nY, OmegaY), 0, 1e-9);
    }
  }
}

// The balanced, dynamically asymmetric ball rubber-rolling on a plane has an invariant measure (A. V.
// Borisov, I. S. Mamaev, I. A. Bizyaev, Nelin. Dinam. 9 (2013) 141-202; J. Koiller, K. M. Ehlers, Rubber
// rolling over a sphere, Regul. Chaotic Dyn. 12 (2007) 127-152: a power of the reduced Legendre transform's
// determinant). Derived here: r = -R gamma and omega normal to gamma make the momentum about the contact A
// omega = (I + m R^2 E) omega = J omega, with J constant, and the contact's rate term m R^2 gamma' x (omega x
// gamma) = m R^2 (gamma x omega) x (omega x gamma) vanishes, so (J omega)' = J omega x omega + lambda gamma,
// gamma' = gamma x omega, lambda = -(J^-1 gamma, J omega x omega) / (gamma, J^-1 gamma) keeping (omega,
// gamma) = 0 -- Veselova's system (L. E. Veselova, 1986). In (omega, gamma) the Euler part is free of
// divergence (tr of J^-1 times a skew matrix) and the couple's part has divergence (grad_omega lambda, J^-1
// gamma) = -(J^-1 gamma, gamma x omega) / (gamma, J^-1 gamma) = -(1/2) d/dt ln (gamma, J^-1 gamma), so the
// density is (gamma, J^-1 gamma)^(1/2) = (det of J restricted to gamma's normal plane / det J)^(1/2). The
// model's state is (M, gamma) with M = A omega + sigma gamma: sigma (the constraint's gauge) is constant
// along the motion and the map (omega, sigma) -> M has determinant det J (gamma, J^-1 gamma), so in the
// model's own variables the density is rho = (gamma, J^-1 gamma)^(-1/2) (with J = I + m R^2 |gamma|^2 E, the
// ball the model describes off |gamma| = 1), and div(rho f) = rho (tr Df - (J^-1 gamma, gamma') / (gamma,
// J^-1 gamma)) must vanish: tr Df from the model's exact Jacobian, at random states and gauges.
TEST(RollingModel, TheBalancedRubberBallKeepsItsInvariantMeasure) {
  const json ball = json::parse(R"({"kind": "rolling", "id": "balanced_rubber_ball",
      "parameters": {"R": 0.7, "m": 1.3, "I1": 0.2, "I2": 0.35, "I3": 0.5},
      "body": {"shape": "sphere", "radius": "R", "mass": "m", "inertia": ["I1", "I2", "I3"]},
      "gravity": 9.81, "contact": "rubber"})");
  const auto model = instance(modelEntryFromJson(ball, "<rubber ball>"));
  const double R = 0.7, m = 1.3;
  const Eigen::Matrix3d I = Eigen::Vector3d(0.2, 0.35, 0.5).asDiagonal();
  const int n = model->dimension();
  std::srand(62);
  for (int k = 0; k < 8; ++k) {
    SCOPED_TRACE(k);
    const Eigen::Vector3d gamma = Eigen::Vector3d::Random().normalized();
    const Eigen::Vector3d w = gamma.cross(Eigen::Vector3d::Random()) * 3;
    const Eigen::Matrix3d A = I + m * R * R * (Eigen::Matrix3d::Identity() - gamma * gamma.transpose());
    const Eigen::Vector3d M = A * w + 0.5 * Eigen::Vector3d::Random()[0] * gamma; // any gauge
    const Eigen::VectorXd x = named(*model, {{"M1", M[0]},
                                             {"M2", M[1]},
                                             {"M3", M[2]},
                                             {"gamma1", gamma[0]},
                                             {"gamma2", gamma[1]},
                                             {"gamma3", gamma[2]}});
    EXPECT_NEAR(observable(*model, "omega1", x.data()), w[0], 1e-13); // the motion meant
    Eigen::VectorXd f(n);
    model->rhs(x.data(), f.data());
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Df(n, n);
    model->jacobian(x.data(), Df.data());
    const Eigen::Matrix3d J = I + m * R * R * gamma.squaredNorm() * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d Jg = J.inverse() * gamma, dgamma = f.segment<3>(3);
    const double densityRate = Jg.dot(dgamma) / gamma.dot(Jg); // -d/dt ln rho
    EXPECT_GT(std::abs(densityRate), 1e-2);                    // not a check that holds for any density
    EXPECT_NEAR(Df.trace() - densityRate, 0, 1e-12 * (1 + Df.diagonal().cwiseAbs().sum()));
    // the model offers it as its invariant measure
    EXPECT_NEAR(model->measureDensity(x.data()), 1 / std::sqrt(gamma.dot(Jg)), 1e-14);
  }
  EXPECT_TRUE(model->hasInvariantMeasure());
}

TEST(RollingModel, AnEllipsoidGivenByItsImplicitSurfaceRollsAsTheClosedFormEllipsoid) {
  // the rattleback's ellipsoid as F = (x/b1)^2 + (y/b2)^2 + (z/b3)^2 - 1: the contact by Newton's method,
  // carried in the state, against the closed-form inverse Gauss map
  json implicit = json::parse(std::ifstream(examples("ellipsoid_on_plane.json", "rolling")));
  implicit["id"] = "implicit_rattleback";
  implicit["body"]["shape"] = "implicit";
  implicit["body"].erase("semi_axes");
  implicit["body"]["F"] = "(x/b1)^2 + (y/b2)^2 + (z/b3)^2 - 1";
  implicit["body"]["size"] = "b2";
  const std::map<std::string, double> set{{"a1", 0.05}, {"B11", 0.1}, {"B12", 0.02}};
  const std::map<std::string, double> start{{"M1", 0.1},      {"M2", 0.05},
                                            {"M3", 0.3},      {"gamma1", 0.05},
                                            {"gamma2", 0.05}, {"gamma3", std::sqrt(1 - 0.005)}};
  const ExampleRun a =
      runModel(instance(modelFileEntry(examples("ellipsoid_on_plane.json", "rolling")), set), start, 10, 0.5);
  const ExampleRun b = runModel(instance(modelEntryFromJson(implicit, "<implicit>"), set), start, 10, 0.5);
  for (const char* id : {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "Z", "E"}) {
    const std::vector<double> x = along(a, id), y = along(b, id);
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_NEAR(x[i], y[i], 1e-9) << id << " at t = " << 0.5 * static_cast<double>(i);
  }
  for (double d : along(b, "contact_drift"))
    EXPECT_LT(d, 1e-9);
}

TEST(RollingModel, ARoundedCubeGivenOnlyByItsSurfaceKeepsItsEnergy) {
  const ExampleRun cube = runExample(
      "rounded_cube.json", {},
      {{"M1", 0.4}, {"M2", 0.1}, {"M3", 0.6}, {"gamma1", 0.2}, {"gamma2", 0.1}, {"gamma3", std::sqrt(0.95)}},
      20, 0.5);
  EXPECT_LT(relativeDrift(along(cube, "E")), 1e-10);
  for (double d : along(cube, "contact_drift"))
    EXPECT_LT(d, 1e-9);
}

/// The contact of `body` at the state `start`, in the body's frame about the pose's centre (the centre of
/// mass), lies on the surface the 3D view samples, with the centre of mass inside it at the height the pose
/// puts it.
void expectDrawnThroughTheContact(const Model& body, const std::map<std::string, double>& start) {
  const auto* drawn = dynamic_cast<const DrawnFromMesh*>(&body);
  ASSERT_TRUE(drawn && drawn->bodySurface());
  const ImplicitSurface surface = *drawn->bodySurface();
  const Eigen::VectorXd x = named(body, start);
  const auto pose = body.pose(x.data());
  ASSERT_TRUE(pose);
  const Eigen::Vector3d contact = pose->rotation.transpose() * (pose->contact - pose->centre);
  EXPECT_NEAR(surface.F(contact), 0, 1e-12);
  EXPECT_LT(surface.F(Eigen::Vector3d::Zero()), 0); // the centre of mass inside
  EXPECT_GE(surface.size, contact.norm());
  const Eigen::Vector3d gamma =
      Eigen::Vector3d(start.at("gamma1"), start.at("gamma2"), start.at("gamma3")).normalized();
  EXPECT_NEAR(contact.dot(gamma), -(pose->centre[2] - pose->contact[2]), 1e-12);
}

TEST(RollingModel, AnImplicitBodyIsDrawnFromItsOwnSurfaceThroughTheContact) {
  const auto cube = instance(modelFileEntry(examples("rounded_cube.json", "rolling")), {{"h", 0.2}});
  expectDrawnThroughTheContact(
      *cube,
      {{"M1", 0.4}, {"M2", 0.1}, {"M3", 0.6}, {"gamma1", 0.2}, {"gamma2", 0.1}, {"gamma3", std::sqrt(0.95)}});
}

/// Each observable `ids` of two runs, sample by sample, within `tolerance`.
void expectTheSameRun(const ExampleRun& a, const ExampleRun& b, std::initializer_list<const char*> ids,
                      double tolerance, double every) {
  for (const char* id : ids) {
    const std::vector<double> x = along(a, id), y = along(b, id);
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_NEAR(x[i], y[i], tolerance) << id << " at t = " << every * static_cast<double>(i);
  }
}

/// The largest difference of the observables `ids` between two runs sampled alike.
double largestGap(const ExampleRun& a, const ExampleRun& b, std::initializer_list<const char*> ids) {
  double worst = 0;
  for (const char* id : ids) {
    const std::vector<double> x = along(a, id), y = along(b, id);
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
      worst = std::max(worst, std::abs(x[i] - y[i]));
  }
  return worst;
}

/// The superellipsoid brick (examples/rolling/superellipsoid.json) rocking on a face, spinning.
const std::map<std::string, double> kBrickStart{
    {"M1", 0.3}, {"M2", 0.2}, {"M3", 0.8}, {"gamma1", 0.2}, {"gamma2", 0.1}, {"gamma3", std::sqrt(0.95)}};

/// The rattleback (b1 = 0.6) tilted in a bowl, rocking and spinning.
const std::map<std::string, double> kInTheBowlStart{
    {"M1", 0.1}, {"M2", 0.05}, {"M3", 0.3}, {"gamma1", 0.3}, {"gamma2", 0.05}, {"gamma3", std::sqrt(0.9075)}};

const std::map<std::string, double> kRattlebackStart{{"M1", 0.1},      {"M2", 0.05},
                                                     {"M3", 0.3},      {"gamma1", 0.05},
                                                     {"gamma2", 0.05}, {"gamma3", std::sqrt(1 - 0.005)}};

TEST(RollingModel, ASuperellipsoidOfExponentTwoRollsAsTheClosedFormEllipsoid) {
  // |x/a1|^p + |y/a2|^p + |z/a3|^p = 1 at p = 2 (a parameter: the general power's derivatives at 0), no
  // bulge: the contact by Newton's method against the closed-form inverse Gauss map
  json named = json::parse(std::ifstream(examples("ellipsoid_on_plane.json", "rolling")));
  named["id"] = "superellipsoid_rattleback";
  named["parameters"]["p"] = {{"default", 2}};
  named["body"]["shape"] = "superellipsoid";
  named["body"]["exponent"] = "p";
  const std::map<std::string, double> set{{"a1", 0.05}, {"B11", 0.1}, {"B12", 0.02}};
  const ExampleRun a = runModel(instance(modelFileEntry(examples("ellipsoid_on_plane.json", "rolling")), set),
                                kRattlebackStart, 10, 0.5);
  const ExampleRun b =
      runModel(instance(modelEntryFromJson(named, "<named>"), set), kRattlebackStart, 10, 0.5);
  expectTheSameRun(a, b, {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "Z", "E"}, 1e-9, 0.5);
  for (double d : along(b, "contact_drift"))
    EXPECT_LT(d, 1e-9);
}

TEST(RollingModel, ASpheroidGivenByItsProfileRollsAsTheClosedFormSpheroid) {
  // a top-heavy oblate spheroid: semi-axes [a, a, c], and its profile rho(z) = a sqrt(1 - z^2/c^2) (or
  // rho^2) about body axis 3
  const json closed = json::parse(R"({"kind": "rolling", "id": "spheroid_closed",
      "parameters": {"a": 0.6, "c": 0.35, "h": 0.08, "m": 1, "I1": 0.1, "I3": 0.14, "g": 1},
      "body": {"shape": "ellipsoid", "semi_axes": "[a, a, c]", "centre": "[0, 0, h]", "mass": "m",
               "inertia": ["I1", "I1", "I3"]}, "gravity": "g"})");
  json profile = closed, squared = closed;
  profile["id"] = "spheroid_profile";
  profile["body"].erase("semi_axes");
  profile["body"]["shape"] = "revolution";
  profile["body"]["heights"] = "[-c, c]";
  squared = profile;
  squared["id"] = "spheroid_squared";
  profile["body"]["profile"] = "a*sqrt(1 - z^2/c^2)";
  squared["body"]["profile_squared"] = "a^2*(1 - (z/c)^2)";
  const std::map<std::string, double> start{{"M1", 0.1},     {"M2", 0.05},    {"M3", 0.5},
                                            {"gamma1", 0.3}, {"gamma2", 0.1}, {"gamma3", std::sqrt(0.9)}};
  const ExampleRun a = runModel(instance(modelEntryFromJson(closed, "<closed>")), start, 10, 0.5);
  for (const json& revolution : {profile, squared}) {
    SCOPED_TRACE(revolution["id"].get<std::string>());
    const auto model = instance(modelEntryFromJson(revolution, "<revolution>"));
    expectDrawnThroughTheContact(*model, start);
    const ExampleRun b = runModel(instance(modelEntryFromJson(revolution, "<revolution>")), start, 10, 0.5);
    expectTheSameRun(a, b, {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "Z", "E"}, 1e-9, 0.5);
    for (double d : along(b, "contact_drift"))
      EXPECT_LT(d, 1e-9);
  }
}

TEST(RollingModel, ASuperellipsoidKeepsItsEnergyAndIsDrawnThroughItsContact) {
  // a rounded brick, exponent 6: energy and the contact carried in the state, over many rockings
  const ExampleRun brick = runExample("superellipsoid.json", {}, kBrickStart, 20, 0.5);
  EXPECT_LT(relativeDrift(along(brick, "E")), 1e-10);
  for (double d : along(brick, "contact_drift"))
    EXPECT_LT(d, 1e-9);
  expectDrawnThroughTheContact(*brick.model, kBrickStart);
  // the rounded cube written by name is the one written as F = x^4 + y^4 + z^4 + c (x^2 + y^2 + z^2 - 1) - 1
  json cube = json::parse(std::ifstream(examples("rounded_cube.json", "rolling")));
  const ExampleRun implicit =
      runModel(instance(modelEntryFromJson(cube, "<implicit>")), kBrickStart, 10, 0.5);
  cube["id"] = "rounded_cube_by_name";
  cube["body"].erase("F");
  cube["body"].erase("size");
  cube["body"]["shape"] = "superellipsoid";
  cube["body"]["semi_axes"] = "[1, 1, 1]";
  cube["body"]["exponent"] = 4;
  cube["body"]["bulge"] = "c";
  const ExampleRun byName = runModel(instance(modelEntryFromJson(cube, "<by name>")), kBrickStart, 10, 0.5);
  expectTheSameRun(implicit, byName, {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "Z", "E"},
                   1e-9, 0.5);
}

/// The rattleback's ellipsoid (examples/rolling/ellipsoid_on_plane.json without its extra potential) on
/// `support` (none: the plane).
json rattlebackOn(const json& support) {
  json body = json::parse(std::ifstream(examples("ellipsoid_on_plane.json", "rolling")));
  body.erase("potential");
  body["id"] =
      "rattleback_on_" + (support.is_null() ? std::string("plane") : support["surface"].get<std::string>());
  if (!support.is_null()) body["support"] = support;
  return body;
}

TEST(RollingModel, AShapeThatIsNotStrictlyConvexWhereItTouchesStopsTheRunSayingWhy) {
  const auto stops = [&](std::unique_ptr<Model> model, const std::string& why) {
    try {
      runModel(std::move(model), kBrickStart, 2, 1);
      ADD_FAILURE() << "the run went on";
    } catch (const ComputationError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  // flat face centres: an exponent above 2 with no bulge
  stops(instance(modelFileEntry(examples("superellipsoid.json", "rolling")), {{"bulge", 0}}),
        "definitions.not_strictly_convex");
  // a ball cut flat below z = -0.5 (the profile's radius does not fall to zero there), standing on its cut
  const json cut = json::parse(R"j({"kind": "rolling", "id": "cut_ball", "gravity": 1,
      "body": {"shape": "revolution", "profile": "sqrt(1 - z^2)", "heights": "[-0.5, 1]", "mass": 1,
               "inertia": [0.4, 0.4, 0.4]}})j");
  stops(instance(modelEntryFromJson(cut, "<cut>")), "definitions.leaves_the_profile");
  // the rattleback (radii of curvature up to b1^2/b3 = 10) in a bowl of radius 2: where it is flatter than
  // the bowl it would touch it along a curve, then cut into it
  stops(instance(modelEntryFromJson(rattlebackOn({{"surface", "sphere"}, {"radius", 2}, {"side", "inside"}}),
                                    "<bowl>")),
        "definitions.flatter_than_the_support");
}

TEST(RollingModel, ABallInASphericalBowlFromItsGeometryFollowsTheBowlWrittenByHand) {
  // the same ball (radius b = 0.2, k = 2/5, in a sphere of radius a = 1 under gravity 9.81) described by its
  // geometry, and written by hand in other variables (examples/models/ball_in_spherical_bowl.json: w, n from
  // the bowl's centre to the contact; here M about the contact and gamma = -n)
  const json geometry = json::parse(R"({"kind": "rolling", "id": "ball_in_a_bowl_by_geometry",
      "body": {"shape": "sphere", "radius": 0.2, "mass": 1, "inertia": "0.4*0.2^2"},
      "support": {"surface": "sphere", "radius": 1, "side": "inside"}, "gravity": 9.81})");
  const Eigen::Vector3d w(1, 4, 2), n(std::sin(0.5), 0, -std::cos(0.5)), gamma = -n;
  const double mu = 0.4 * 0.04, D = 0.04;
  const Eigen::Vector3d M = mu * w + D * gamma.cross(w.cross(gamma));
  const std::map<std::string, double> a{{"M1", M[0]},         {"M2", M[1]},         {"M3", M[2]},
                                        {"gamma1", gamma[0]}, {"gamma2", gamma[1]}, {"gamma3", gamma[2]}};
  std::map<std::string, double> b{{"w1", 1}, {"w2", 4}, {"w3", 2}, {"n1", n[0]}, {"n2", n[1]}, {"n3", n[2]}};
  for (const char* e : {"e11", "e22", "e33"})
    b[e] = 1;
  for (const char* e : {"e12", "e13", "e21", "e23", "e31", "e32"})
    b[e] = 0;
  const ExampleRun ra = runModel(instance(modelEntryFromJson(geometry, "<bowl>")), a, 10, 0.5);
  const ExampleRun rb =
      runModel(instance(modelFileEntry(examples("ball_in_spherical_bowl.json"))), b, 10, 0.5);
  for (const auto& [mine, theirs, sign] :
       std::vector<std::tuple<std::string, std::string, double>>{{"omega1", "w1", 1},
                                                                 {"omega2", "w2", 1},
                                                                 {"omega3", "w3", 1},
                                                                 {"gamma1", "n1", -1},
                                                                 {"gamma3", "n3", -1},
                                                                 {"E", "E", 1}}) {
    const std::vector<double> x = along(ra, mine), y = along(rb, theirs);
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_NEAR(x[i], sign * y[i], 1e-9 * (1 + std::abs(y[i])))
          << mine << " at t = " << 0.5 * static_cast<double>(i);
  }
  EXPECT_LT(relativeDrift(along(ra, "E")), 1e-11);
  EXPECT_LT(relativeDrift(along(ra, "spin_normal")), 1e-10); // Routh: the spin about the normal is kept
}

TEST(RollingModel, ARubberBallInASphericalBowlRollsAsTheMarbleOneThatDoesNotSpin) {
  // on a sphere a marble ball keeps its spin about the normal (Routh): started without it, it needs no
  // couple, and the rubber ball -- which cannot spin -- follows the same motion; M's part along gamma is the
  // rubber constraint's to choose
  json rubber = json::parse(std::ifstream(examples("rubber_ball_on_sphere.json", "rolling")));
  json marble = rubber;
  marble["id"] = "marble_ball_in_a_bowl";
  marble["contact"] = "marble";
  const Eigen::Vector3d gamma(std::sin(0.5), 0, std::cos(0.5));
  const Eigen::Vector3d M = Eigen::Vector3d(0.05, -0.02, 0.03).cross(gamma); // normal to gamma: no spin
  const auto start = [&](double along) {
    const Eigen::Vector3d m = M + along * gamma;
    return std::map<std::string, double>{{"M1", m[0]},         {"M2", m[1]},         {"M3", m[2]},
                                         {"gamma1", gamma[0]}, {"gamma2", gamma[1]}, {"gamma3", gamma[2]}};
  };
  const ExampleRun a = runModel(instance(modelEntryFromJson(marble, "<marble>")), start(0), 20, 0.5);
  const ExampleRun b = runModel(instance(modelEntryFromJson(rubber, "<rubber>")), start(0), 20, 0.5);
  const ExampleRun c = runModel(instance(modelEntryFromJson(rubber, "<rubber>")), start(0.04), 20, 0.5);
  for (const char* id : {"omega1", "omega2", "omega3", "x1", "x2", "x3", "E"}) {
    const std::vector<double> x = along(a, id), y = along(b, id), z = along(c, id);
    for (std::size_t i = 0; i < x.size(); ++i) {
      EXPECT_NEAR(x[i], y[i], 1e-9) << id << " at t = " << 0.5 * static_cast<double>(i);
      EXPECT_NEAR(y[i], z[i], 1e-9) << id << " at t = " << 0.5 * static_cast<double>(i);
    }
  }
  EXPECT_LT(relativeDrift(along(c, "E")), 1e-11);
  for (double s : along(c, "spin_normal"))
    EXPECT_LT(std::abs(s), 1e-13);
}

TEST(RollingModel, AnyBodyOnACurvedSupportRollsAsTheBalancedBallWhenItIsOne) {
  // the general path (any body, in body axes: a sphere given three moments takes it) against the balanced
  // ball's fixed-frame equations, in a spherical bowl and on an ellipsoid; started with the body axes along
  // the fixed ones (q = 1), so M, gamma and the ball's fixed-frame M, gamma start alike
  // the same for rubber rolling (the couple that stops the spin: M's part along gamma is the constraint's)
  for (const auto& [support, contact] : std::vector<std::pair<const char*, const char*>>{
           {R"({"surface": "sphere", "radius": 1, "side": "inside"})", "marble"},
           {R"({"surface": "ellipsoid", "semi_axes": "[1.2, 1, 0.8]"})", "marble"},
           {R"({"surface": "sphere", "radius": 1, "side": "inside"})", "rubber"},
           {R"({"surface": "ellipsoid", "semi_axes": "[1.2, 1, 0.8]"})", "rubber"},
           {R"({"surface": "ellipsoid", "semi_axes": "[1.2, 1, 0.8]", "side": "inside"})", "marble"}}) {
    SCOPED_TRACE(std::string(support) + " " + contact);
    json ball = json::parse(R"({"kind": "rolling", "id": "balanced_ball",
        "body": {"shape": "sphere", "radius": 0.2, "mass": 1, "inertia": "0.4*0.2^2"}, "gravity": 9.81})");
    ball["support"] = json::parse(support);
    ball["contact"] = contact;
    json body = ball;
    body["id"] = "any_body";
    body["body"]["inertia"] = {"0.4*0.2^2", "0.4*0.2^2", "0.4*0.2^2"};
    for (int i = 1; i <= 3; ++i) // the angular velocity in fixed axes, as the ball's omega is
      body["observables"]["omega" + std::to_string(i)] = "(rotation*omega)[" + std::to_string(i) + "]";
    const Eigen::Vector3d w(1, 4, 2),
        gamma = Eigen::Vector3d(-std::sin(0.5), 0.1, std::cos(0.5)).normalized();
    const Eigen::Vector3d M = 0.016 * w + 0.04 * gamma.cross(w.cross(gamma));
    std::map<std::string, double> start{{"M1", M[0]},         {"M2", M[1]},         {"M3", M[2]},
                                        {"gamma1", gamma[0]}, {"gamma2", gamma[1]}, {"gamma3", gamma[2]}};
    const ExampleRun a = runModel(instance(modelEntryFromJson(ball, "<ball>")), start, 10, 0.5);
    start.insert({{"q0", 1}, {"q1", 0}, {"q2", 0}, {"q3", 0}});
    const ExampleRun b = runModel(instance(modelEntryFromJson(body, "<body>")), start, 10, 0.5);
    expectTheSameRun(a, b, {"omega1", "omega2", "omega3", "x1", "x2", "x3", "E", "spin_normal"}, 1e-9, 0.5);
  }
}

TEST(RollingModel, ABodyOnASphereOfGrowingRadiusTendsToTheSameBodyOnThePlane) {
  // on top of a sphere of radius a the support's curvature 1/a is all that differs from the plane: the
  // motion from the same start (gamma along the fixed vertical) tends to the plane's as a grows
  const ExampleRun plane =
      runModel(instance(modelEntryFromJson(rattlebackOn(nullptr), "<plane>")), kRattlebackStart, 10, 0.5);
  std::vector<double> gap;
  for (const double a : {100.0, 1000.0}) {
    const ExampleRun sphere = runModel(
        instance(modelEntryFromJson(rattlebackOn({{"surface", "sphere"}, {"radius", a}}), "<sphere>")),
        kRattlebackStart, 10, 0.5);
    gap.push_back(largestGap(plane, sphere, {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3"}));
  }
  EXPECT_LT(gap[0], 0.5);
  EXPECT_GT(gap[0], 1e-4);       // the curvature shows
  EXPECT_LT(gap[1], gap[0] / 5); // like 1/a
}

TEST(RollingModel, AnyBodyOnACurvedSupportKeepsItsEnergy) {
  // the rattleback in a spherical bowl, and the superellipsoid brick (its contact by Newton's method) on an
  // ellipsoid
  // (the rattleback's semi-axis b1 = 0.6 instead of 2: its radii of curvature, at most b1^2/b3, stay below
  // the bowl's 2, so it touches at one point wherever it rolls)
  const auto inTheBowl = [](const char* contact) {
    json body = rattlebackOn({{"surface", "sphere"}, {"radius", 2}, {"side", "inside"}});
    body["id"] = std::string(contact) + "_rattleback_in_a_bowl";
    body["contact"] = contact;
    return runModel(instance(modelEntryFromJson(body, "<bowl>"), {{"b1", 0.6}}), kInTheBowlStart, 20, 0.5);
  };
  const ExampleRun bowl = inTheBowl("marble");
  json brick = json::parse(std::ifstream(examples("superellipsoid.json", "rolling")));
  brick["id"] = "brick_on_an_ellipsoid";
  brick["support"] = {{"surface", "ellipsoid"}, {"semi_axes", "[3, 2.5, 2]"}};
  const ExampleRun onEllipsoid =
      runModel(instance(modelEntryFromJson(brick, "<brick>")), kBrickStart, 20, 0.5);
  for (const ExampleRun* run : {&bowl, &onEllipsoid}) {
    EXPECT_LT(relativeDrift(along(*run, "E")), 1e-10);
    EXPECT_LT(relativeDrift(along(*run, "orientation")), 1e-12);
    const std::vector<double> x1 = along(*run, "x1");
    EXPECT_GT(*std::max_element(x1.begin(), x1.end()) - *std::min_element(x1.begin(), x1.end()),
              0.05); // moves
  }
  for (double d : along(onEllipsoid, "contact_drift"))
    EXPECT_LT(d, 1e-9);
  // rubber: the rattleback in the bowl keeps its energy and never spins about the normal
  const ExampleRun rubberBowl = inTheBowl("rubber");
  EXPECT_LT(relativeDrift(along(rubberBowl, "E")), 1e-10);
  for (double spin : along(rubberBowl, "spin_normal"))
    EXPECT_LT(std::abs(spin), 1e-13);
}

TEST(RollingModel, AnImplicitSupportRollsAsTheSameSupportInClosedForm) {
  // the support's contact by Newton's method from F alone against the closed-form inverse Gauss maps: a
  // spherical bowl (marble and rubber), a paraboloid bowl and, under the implicit brick (two Newton solves),
  // an ellipsoid from outside; the support's contact completed from the state's normal by damped steps
  struct Case {
    json body, closed, implicit;
    std::map<std::string, double> set, start;
  };
  json rattleback = rattlebackOn(nullptr),
       brick = json::parse(std::ifstream(examples("superellipsoid.json", "rolling")));
  json rubberRattleback = rattleback;
  rubberRattleback["contact"] = "rubber";
  const std::vector<Case> cases{
      {rattleback,
       {{"surface", "sphere"}, {"radius", 2}, {"side", "inside"}},
       {{"surface", "implicit"}, {"F", "4 - x^2 - y^2 - z^2"}, {"size", 2.2}, {"point", "[0, 0, -2]"}},
       {{"b1", 0.6}},
       kRattlebackStart},
      {rubberRattleback,
       {{"surface", "sphere"}, {"radius", 2}, {"side", "inside"}},
       {{"surface", "implicit"}, {"F", "4 - x^2 - y^2 - z^2"}, {"size", 2.2}, {"point", "[0, 0, -2]"}},
       {{"b1", 0.6}},
       kRattlebackStart},
      {rattleback,
       {{"surface", "paraboloid"}, {"p", 3}, {"q", 2}},
       {{"surface", "implicit"}, {"F", "z - x^2/6 - y^2/4"}, {"size", 3}},
       {{"b1", 0.6}},
       kRattlebackStart},
      {rattleback, // an ellipsoid bowl
       {{"surface", "ellipsoid"}, {"semi_axes", "[3, 2.5, 2]"}, {"side", "inside"}},
       {{"surface", "implicit"},
        {"F", "1 - x^2/9 - y^2/6.25 - z^2/4"},
        {"size", 3.5},
        {"point", "[0, 0, -2]"}},
       {{"b1", 0.6}},
       kRattlebackStart},
      {brick,
       {{"surface", "ellipsoid"}, {"semi_axes", "[3, 2.5, 2]"}},
       {{"surface", "implicit"},
        {"F", "x^2/9 + y^2/6.25 + z^2/4 - 1"},
        {"size", 3.5},
        {"point", "[0, 0, 2]"}},
       {},
       kBrickStart}};
  int k = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.closed.dump() + " " + c.body["contact"].dump());
    json closed = c.body, implicit = c.body;
    closed["id"] = "closed_support_" + std::to_string(k);
    closed["support"] = c.closed;
    implicit["id"] = "implicit_support_" + std::to_string(k++);
    implicit["support"] = c.implicit;
    const ExampleRun a = runModel(instance(modelEntryFromJson(closed, "<closed>"), c.set), c.start, 10, 0.5);
    const ExampleRun b =
        runModel(instance(modelEntryFromJson(implicit, "<implicit>"), c.set), c.start, 10, 0.5);
    expectTheSameRun(a, b, {"omega1", "omega2", "omega3", "x1", "x2", "x3", "E", "spin_normal"}, 1e-9, 0.5);
    for (double d : along(b, "support_drift"))
      EXPECT_LT(d, 1e-9);
  }
}

TEST(RollingModel, ABallOnAnImplicitSupportRollsAsTheBallOnItsClosedForm) {
  // a balanced ball's one moment: on an implicit support it rolls in body axes (the general path) and
  // follows the fixed-frame equations of the ball on the same sphere
  json ball = json::parse(R"({"kind": "rolling", "id": "ball_on_a_sphere",
      "body": {"shape": "sphere", "radius": 0.3, "mass": 1, "inertia": "0.4*0.3^2"}, "gravity": 9.81,
      "support": {"surface": "sphere", "radius": 1.5, "side": "inside"}})");
  json onImplicit = ball;
  onImplicit["id"] = "ball_on_an_implicit_sphere";
  onImplicit["support"] = {
      {"surface", "implicit"}, {"F", "2.25 - x^2 - y^2 - z^2"}, {"size", 1.6}, {"point", "[0, 0, -1.5]"}};
  const Eigen::Vector3d gamma = Eigen::Vector3d(0.3, -0.2, 1).normalized();
  const std::map<std::string, double> start{{"M1", 0.02},         {"M2", 0.05},         {"M3", 0.01},
                                            {"gamma1", gamma[0]}, {"gamma2", gamma[1]}, {"gamma3", gamma[2]}};
  std::map<std::string, double> withQ = start;
  withQ.insert({{"q0", 1}, {"q1", 0}, {"q2", 0}, {"q3", 0}});
  const ExampleRun a = runModel(instance(modelEntryFromJson(ball, "<ball>")), start, 10, 0.5);
  const ExampleRun b = runModel(instance(modelEntryFromJson(onImplicit, "<implicit>")), withQ, 10, 0.5);
  expectTheSameRun(a, b, {"x1", "x2", "x3", "E"}, 1e-9, 0.5);
}

TEST(RollingModel, ABodyOnAnImplicitBowlKeepsItsEnergyAndIsDrawnOnIt) {
  // a bowl with no closed form: z = (x^2 + y^2)/4 + (x^4 + y^4)/20, convex everywhere
  json body =
      rattlebackOn({{"surface", "implicit"}, {"F", "z - (x^2 + y^2)/4 - (x^4 + y^4)/20"}, {"size", 2.5}});
  body["id"] = "rattleback_in_a_quartic_bowl";
  const ExampleRun run =
      runModel(instance(modelEntryFromJson(body, "<quartic>"), {{"b1", 0.6}}), kInTheBowlStart, 20, 0.5);
  EXPECT_LT(relativeDrift(along(run, "E")), 1e-10);
  for (double d : along(run, "support_drift"))
    EXPECT_LT(d, 1e-9);
  const std::vector<double> x1 = along(run, "x1");
  EXPECT_GT(*std::max_element(x1.begin(), x1.end()) - *std::min_element(x1.begin(), x1.end()), 0.05);
  // the view: the sampled bowl passes through the contact, where F = 0 and its gradient is the normal
  const auto* drawn = dynamic_cast<const DrawnFromMesh*>(run.model.get());
  ASSERT_NE(drawn, nullptr);
  const auto surface = drawn->supportSurface();
  ASSERT_TRUE(surface);
  for (const Eigen::VectorXd& x : run.states) {
    const auto pose = run.model->pose(x.data());
    ASSERT_TRUE(pose);
    EXPECT_NEAR(surface->F(pose->contact), 0, 1e-9);
  }
  // bad supports are named at their fields
  json noF = body;
  noF["support"].erase("F");
  EXPECT_NE(modelFileError(noF).find("m.json:support: an implicit support needs \"F\""), std::string::npos)
      << modelFileError(noF);
  json sized = body;
  sized["support"] = {{"surface", "sphere"}, {"radius", 2}, {"size", 3}};
  EXPECT_NE(modelFileError(sized).find("m.json:support.size: only an \"implicit\" support has \"size\""),
            std::string::npos)
      << modelFileError(sized);
  json taken = body;
  taken["definitions"]["support_point"] = "[0, 0, 0]";
  EXPECT_NE(modelFileError(taken).find("m.json:definitions.support_point: 'support_point' is a name"),
            std::string::npos)
      << modelFileError(taken);
}

TEST(RollingModel, TheTippeTopTurnsOverOnlyInsideItsInertiaWindowAndKeepsJellettsIntegral) {
  // offset 0.3, I3 = 0.4: inversion needs 0.7 < I1/I3 < 1.3
  const std::map<std::string, double> spun{{"omega1", 0}, {"omega2", 0},
                                           {"omega3", 6}, {"gamma1", std::sin(0.1)},
                                           {"gamma2", 0}, {"gamma3", std::cos(0.1)}};
  for (const double I1 : {0.35, 0.6}) {
    SCOPED_TRACE(I1);
    const ExampleRun top = runExample("tippe_top.json", {{"I1", I1}}, spun, 50, 0.25);
    const std::vector<double> up = along(top, "axis_up"), E = along(top, "E"), N = along(top, "normal_force");
    EXPECT_LT(relativeDrift(along(top, "jellett")), 1e-10);
    EXPECT_GT(up.front(), 0.99);
    for (std::size_t i = 1; i < E.size(); ++i)
      EXPECT_LE(E[i], E[i - 1] + 1e-12); // friction only takes energy
    for (double n : N)
      EXPECT_GT(n, 0); // it never leaves the plane
    const double lowest = *std::min_element(up.begin(), up.end());
    if (I1 / 0.4 < 1.3) {
      EXPECT_LT(lowest, -0.95);
      EXPECT_LT(up.back(), -0.9);
      EXPECT_GT(observable(*top.model, "Z", top.states.back().data()), 1.0); // the centre of mass went up
    } else {
      EXPECT_GT(lowest, -0.8); // tilts over to a steady slant, never onto its stem
    }
  }
}

TEST(RollingModel, ABodySlidingOnACurvedSupportLosesExactlyWhatItsFrictionTakes) {
  // the tippe top in a spherical and in a paraboloid bowl: without friction the normal force does no work
  // (energy to 1e-10); with it dE/dt = -mu |v_slip|^2, integrated by Simpson's rule along the run. (On top
  // of a sphere, frictionless, it slides down and leaves it, as a particle would: the run stops there.)
  const std::map<std::string, double> spun{{"omega1", 0}, {"omega2", 0},
                                           {"omega3", 6}, {"gamma1", std::sin(0.1)},
                                           {"gamma2", 0}, {"gamma3", std::cos(0.1)}};
  int k = 0;
  for (const json& support : {json{{"surface", "sphere"}, {"radius", 5}, {"side", "inside"}},
                              json{{"surface", "paraboloid"}, {"p", 4}, {"q", 6}}}) {
    SCOPED_TRACE(support.dump());
    json top = json::parse(std::ifstream(examples("tippe_top.json", "rolling")));
    top["id"] = "sliding_top_" + std::to_string(k++);
    top["support"] = support;
    const auto entry = modelEntryFromJson(top, "<top>");
    const ExampleRun frictionless = runModel(instance(entry, {{"mu", 0}}), spun, 10, 0.5);
    EXPECT_LT(relativeDrift(along(frictionless, "E")), 1e-10);
    for (double n : along(frictionless, "normal_force"))
      EXPECT_GT(n, 0);
    constexpr double h = 0.01, T = 4;
    const ExampleRun run = runModel(instance(entry), spun, T, h);
    const std::vector<double> E = along(run, "E"), slip = along(run, "slip");
    double dissipated = 0; // Simpson, mu = 1
    for (std::size_t i = 0; i + 2 < slip.size(); i += 2)
      dissipated += h / 3 * (slip[i] * slip[i] + 4 * slip[i + 1] * slip[i + 1] + slip[i + 2] * slip[i + 2]);
    EXPECT_GT(dissipated, 1e-3 * E.front()); // it slips
    EXPECT_NEAR(E.front() - E.back(), dissipated, 1e-7 * E.front());
  }
}

TEST(RollingModel, APotentialOnACurvedSupportActsByItsForceAndCouple) {
  // U(vertical, x) of a body on a curved support: U = k x3 is gravity made stronger by k/m (the force
  // through the centre of mass); a U of both the orientation and the position keeps the energy E + U for
  // marble, rubber and frictionless sliding (a wrong couple or force would do work)
  const auto bowl = [](const char* contact, const char* U, double g) {
    json body = rattlebackOn({{"surface", "sphere"}, {"radius", 2}, {"side", "inside"}});
    body["contact"] = contact;
    if (std::string(contact) == "sliding") body["friction"] = 0;
    if (U[0]) body["potential"] = U;
    body["gravity"] = g;
    body["id"] = std::string("potential_in_a_bowl_") + contact + "_" + std::to_string(U[0] ? 1 : 0) +
                 std::to_string(static_cast<int>(g * 10));
    return body;
  };
  const std::map<std::string, double>& start = kInTheBowlStart;
  std::map<std::string, double> slidingStart{{"omega1", 0.2}, {"omega2", 0.1}, {"omega3", 1}};
  for (const char* g : {"gamma1", "gamma2", "gamma3"})
    slidingStart[g] = start.at(g);
  for (const char* contact : {"marble", "sliding"}) {
    SCOPED_TRACE(contact);
    const auto& from = std::string(contact) == "marble" ? start : slidingStart;
    const ExampleRun heavier =
        runModel(instance(modelEntryFromJson(bowl(contact, "", 1.5), "<g>"), {{"b1", 0.6}}), from, 10, 0.5);
    const ExampleRun pushed = runModel(
        instance(modelEntryFromJson(bowl(contact, "0.5*x[3]", 1), "<U>"), {{"b1", 0.6}}), from, 10, 0.5);
    expectTheSameRun(heavier, pushed, {"x1", "x2", "x3", "gamma1", "gamma2", "gamma3"}, 1e-9, 0.5);
  }
  const char* U = "0.3*vertical[1]^2 + 0.2*x[1]^2 + 0.1*x[2]*vertical[2]";
  for (const char* contact : {"marble", "rubber", "sliding"}) {
    SCOPED_TRACE(contact);
    const ExampleRun run = runModel(instance(modelEntryFromJson(bowl(contact, U, 1), "<U>"), {{"b1", 0.6}}),
                                    std::string(contact) == "sliding" ? slidingStart : start, 20, 0.5);
    EXPECT_LT(relativeDrift(along(run, "E")), 1e-10);
    const std::vector<double> x1 = along(run, "x1");
    EXPECT_GT(*std::max_element(x1.begin(), x1.end()) - *std::min_element(x1.begin(), x1.end()), 0.05);
  }
  EXPECT_NE(modelFileError(bowl("marble", "gamma[1]^2", 1)).find("m.json:potential: on a curved support"),
            std::string::npos)
      << modelFileError(bowl("marble", "gamma[1]^2", 1));
  EXPECT_NE(modelFileError(bowl("marble", "x[3] +", 1)).find("m.json:potential: column"), std::string::npos)
      << modelFileError(bowl("marble", "x[3] +", 1));
}

TEST(RollingModel, ATopSlidingOnASphereOfGrowingRadiusTendsToTheTopOnThePlane) {
  const std::map<std::string, double> spun{{"omega1", 0}, {"omega2", 0},
                                           {"omega3", 6}, {"gamma1", std::sin(0.1)},
                                           {"gamma2", 0}, {"gamma3", std::cos(0.1)}};
  const ExampleRun plane = runExample("tippe_top.json", {}, spun, 10, 0.5);
  std::vector<double> gap;
  for (const double a : {100.0, 1000.0}) {
    json top = json::parse(std::ifstream(examples("tippe_top.json", "rolling")));
    top["id"] = "top_on_a_sphere_" + std::to_string(static_cast<int>(a));
    top["support"] = {{"surface", "sphere"}, {"radius", a}};
    const ExampleRun sphere = runModel(instance(modelEntryFromJson(top, "<top>")), spun, 10, 0.5);
    gap.push_back(largestGap(plane, sphere, {"axis_up", "normal_force", "slip"}));
  }
  EXPECT_LT(gap[0], 0.5);
  EXPECT_GT(gap[0], 1e-5);       // the curvature shows
  EXPECT_LT(gap[1], gap[0] / 5); // like 1/a
}

TEST(RollingModel, AFrictionlessBallSlidingInABowlKeepsItsSpinAndMovesAsASphericalPendulum) {
  // no friction, the normal force through the centre: no torque, so omega stays; the centre is a point
  // on the sphere of radius a - R under gravity (energy and the angular momentum about the vertical)
  json ball = json::parse(R"({"kind": "rolling", "id": "sliding_ball_in_a_bowl",
      "body": {"shape": "sphere", "radius": 0.3, "mass": 1, "inertia": "0.4*0.3^2"}, "gravity": 9.81,
      "contact": "sliding", "friction": 0, "support": {"surface": "sphere", "radius": 1.5, "side": "inside"},
      "observables": {"Lz": "cross(x, rotation*v)[3]"}})");
  const Eigen::Vector3d gamma = Eigen::Vector3d(0.4, -0.1, 1).normalized(),
                        v = 0.8 * gamma.cross(Eigen::Vector3d::UnitX()).normalized();
  const ExampleRun run = runModel(instance(modelEntryFromJson(ball, "<ball>")),
                                  {{"omega1", 1},
                                   {"omega2", 2},
                                   {"omega3", 3},
                                   {"v1", v[0]},
                                   {"v2", v[1]},
                                   {"v3", v[2]},
                                   {"gamma1", gamma[0]},
                                   {"gamma2", gamma[1]},
                                   {"gamma3", gamma[2]},
                                   {"q0", 1},
                                   {"q1", 0},
                                   {"q2", 0},
                                   {"q3", 0}},
                                  10, 0.5);
  EXPECT_LT(relativeDrift(along(run, "E")), 1e-10);
  EXPECT_LT(relativeDrift(along(run, "Lz")), 1e-9);
  for (const char* w : {"omega1", "omega2", "omega3"})
    EXPECT_LT(relativeDrift(along(run, w)), 1e-12) << w;
  for (const Eigen::VectorXd& x : run.states) // the centre on the sphere of radius a - R
    EXPECT_NEAR(Eigen::Vector3d(observable(*run.model, "x1", x.data()),
                                observable(*run.model, "x2", x.data()),
                                observable(*run.model, "x3", x.data()))
                    .norm(),
                1.2, 1e-10);
}

// Jellett's quantity is marked an integral only for a body symmetric about its `axis` (the inertia's axis,
// equal moments across it, the centre of mass on it) for every value of the parameters; otherwise it stays
// an observable -- and then it is not conserved.
TEST(RollingModel, JellettIsAnIntegralOnlyOfABodySymmetricAboutItsAxis) {
  const json top = json::parse(std::ifstream(examples("tippe_top.json", "rolling")));
  int variant = 0;
  const auto jellettIsAnIntegral = [&](const json& doc) {
    json d = doc;
    d["id"] = "jellett_variant_" + std::to_string(variant++);
    const ModelEntry& e = modelEntryFromJson(d, "<jellett>");
    const auto model = instance(e); // the observables live in the model: keep it alive while they are read
    const auto& observables = model->observables();
    EXPECT_TRUE(std::any_of(observables.begin(), observables.end(),
                            [](const Observable& o) { return o.id == "jellett"; })); // always offered
    const auto& integrals = e.info->integralNames;
    return std::find(integrals.begin(), integrals.end(), "jellett") != integrals.end();
  };
  EXPECT_TRUE(jellettIsAnIntegral(top));
  json tilted = top; // the same top with its axis along (1, 1, 0)/sqrt(2): a tensor through principal axes
  tilted["body"]["axis"] = "[1, 1, 0]";
  tilted["body"]["centre"] = "(offset*R/sqrt(2))*[1, 1, 0]";
  tilted["body"]["principal_axes"] = "[[0, 0, 1], [1/sqrt(2), -1/sqrt(2), 0], [1/sqrt(2), 1/sqrt(2), 0]]";
  EXPECT_TRUE(jellettIsAnIntegral(tilted));
  json asymmetric = top; // equal moments at the defaults only: not for every value of the parameters
  asymmetric["parameters"]["I2"] = asymmetric["parameters"]["I1"];
  asymmetric["body"]["inertia"] = json::array({"I1", "I2", "I3"});
  EXPECT_FALSE(jellettIsAnIntegral(asymmetric));
  json offAxis = top;
  offAxis["body"]["centre"] = "[0.05, 0, offset*R]";
  EXPECT_FALSE(jellettIsAnIntegral(offAxis));
  json otherAxis = top;
  otherAxis["body"]["axis"] = "[1, 0, 0]";
  EXPECT_FALSE(jellettIsAnIntegral(otherAxis));
  // File > New rolling body: a sphere declared symmetric about axis 3 says so in its description
  RollingBodyForm form;
  form.shape = "sphere";
  form.sizes = {1, 0, 0};
  form.centre = {0, 0, 0.3};
  form.inertia = {0.35, 0.35, 0.4};
  form.contact = "sliding";
  form.symmetryAxis = true;
  EXPECT_TRUE(jellettIsAnIntegral(json::parse(rollingModelDocument(form).dump())));
  form.inertia = {0.35, 0.3, 0.4};
  EXPECT_FALSE(jellettIsAnIntegral(json::parse(rollingModelDocument(form).dump())));
  // and rightly: with unequal moments across the axis Jellett's quantity drifts
  asymmetric["id"] = "jellett_asymmetric_run";
  const ExampleRun run = runModel(instance(modelEntryFromJson(asymmetric, "<asymmetric>"), {{"I2", 0.3}}),
                                  {{"omega1", 0},
                                   {"omega2", 0},
                                   {"omega3", 6},
                                   {"gamma1", std::sin(0.1)},
                                   {"gamma2", 0},
                                   {"gamma3", std::cos(0.1)}},
                                  50, 0.5);
  EXPECT_GT(relativeDrift(along(run, "jellett")), 1e-4); // the symmetric top keeps it to 1e-10 (above)
}

/// The model File > New rolling body writes for `form` (its id made unique), run from the start it writes.
ExampleRun runForm(RollingBodyForm form, double T) {
  static int made = 0;
  form.id = "form_" + form.shape + "_" + form.support + "_" + std::to_string(made++);
  const ModelEntry& e = modelEntryFromJson(json::parse(rollingModelDocument(form).dump()), "<form>");
  return runModel(instance(e), modelFileInitial(e).at("state").get<std::map<std::string, double>>(), T, 0.5);
}

// File > New rolling body: each shape and each support it offers makes a model that runs from the start the
// form writes -- on a curved support the body on top of the sphere or ellipsoid, at the bottom of the bowl --
// keeps its energy and moves
TEST(RollingModel, EveryShapeAndSupportOfTheNewBodyFormRollsFromItsStartKeepingItsEnergy) {
  struct Case {
    const char *shape, *support;
    bool inside;
    const char* contact;
  };
  for (const Case& c : std::vector<Case>{{"superellipsoid", "plane", false, "marble"},
                                         {"revolution", "plane", false, "rubber"},
                                         {"ellipsoid", "sphere", false, "marble"},
                                         {"ellipsoid", "sphere", true, "rubber"},
                                         {"ellipsoid", "ellipsoid", false, "marble"},
                                         {"ellipsoid", "paraboloid", false, "marble"},
                                         {"superellipsoid", "sphere", false, "marble"},
                                         {"revolution", "paraboloid", false, "rubber"}}) {
    SCOPED_TRACE(std::string(c.shape) + " " + c.support + (c.inside ? " inside " : " ") + c.contact);
    RollingBodyForm form; // the form's defaults but for these
    form.shape = c.shape;
    form.support = c.support;
    form.inside = c.inside;
    form.contact = c.contact;
    const ExampleRun run = runForm(form, 5);
    EXPECT_LT(relativeDrift(along(run, "E")), 1e-10);
    const std::vector<double> g1 = along(run, "gamma1");
    EXPECT_GT(*std::max_element(g1.begin(), g1.end()) - *std::min_element(g1.begin(), g1.end()), 0.05);
    if (std::string(c.contact) == "rubber") {
      for (double spin : along(run, "spin_normal"))
        EXPECT_LT(std::abs(spin), 1e-12);
    }
  }
}

// The form writes each shape's and support's sizes where the rolling model reads them: the same body given
// two ways rolls the same, through the form -- a superellipsoid of exponent 2 (its contact by Newton's
// method) as the closed-form ellipsoid in a spherical bowl, a spheroid by its profile as the closed-form one
// on an ellipsoid, and an ellipsoid of equal semi-axes as the sphere it is
TEST(RollingModel, TheNewBodyFormWritesEachShapeAndSupportItOffers) {
  RollingBodyForm ellipsoid;
  ellipsoid.sizes = {0.6, 0.6, 0.4};
  ellipsoid.support = "sphere";
  ellipsoid.inside = true;
  RollingBodyForm superellipsoid = ellipsoid;
  superellipsoid.shape = "superellipsoid";
  superellipsoid.exponent = 2;
  superellipsoid.bulge = 0;
  expectTheSameRun(runForm(ellipsoid, 5), runForm(superellipsoid, 5),
                   {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "x1", "x2", "x3", "E"}, 1e-9,
                   0.5);
  ellipsoid.support = "ellipsoid";
  ellipsoid.inside = false;
  ellipsoid.supportSizes = {3, 2.5, 2};
  RollingBodyForm spheroid = ellipsoid;
  spheroid.shape = "revolution";
  spheroid.profile = "0.36*(1 - (z/0.4)^2)";
  spheroid.heights = {-0.4, 0.4};
  expectTheSameRun(runForm(ellipsoid, 5), runForm(spheroid, 5),
                   {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "x1", "x2", "x3", "E"}, 1e-9,
                   0.5);
  ellipsoid.supportSizes = {3, 3, 3};
  RollingBodyForm onASphere = ellipsoid;
  onASphere.support = "sphere";
  onASphere.inside = false;
  expectTheSameRun(runForm(ellipsoid, 5), runForm(onASphere, 5),
                   {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "x1", "x2", "x3", "E"}, 1e-12,
                   0.5);
  ellipsoid.inside = onASphere.inside = true; // and inside: an ellipsoid bowl of equal semi-axes
  expectTheSameRun(runForm(ellipsoid, 5), runForm(onASphere, 5),
                   {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "x1", "x2", "x3", "E"}, 1e-12,
                   0.5);
  EXPECT_EQ(rollingModelDocument(ellipsoid)["title"],
            "An ellipsoid rolling in an ellipsoid bowl (File > New rolling body)");
  // an implicit support: the form's default F, the paraboloid bowl of radii 8, is the paraboloid support
  RollingBodyForm inABowl = ellipsoid, onF = ellipsoid;
  inABowl.support = "paraboloid";
  inABowl.supportSizes = {8, 8, 0};
  onF.support = "implicit";
  onF.supportSizes = {8, 0, 0};
  expectTheSameRun(runForm(inABowl, 5), runForm(onF, 5),
                   {"omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3", "x1", "x2", "x3", "E"}, 1e-9,
                   0.5);
  EXPECT_EQ(rollingModelDocument(onF)["title"],
            "An ellipsoid rolling on a support given by its surface (File > New rolling body)");
  // the title names the body and what it rolls on
  EXPECT_EQ(rollingModelDocument(superellipsoid)["title"],
            "A superellipsoid rolling in a spherical bowl (File > New rolling body)");
  EXPECT_EQ(rollingModelDocument(spheroid)["title"],
            "A body of revolution rolling on an ellipsoid (File > New rolling body)");
}

// A sliding body from the form on a curved support: the tippe top (a sphere, its centre of mass off centre)
// in a spherical bowl and the ellipsoid in a paraboloid bowl; without friction they keep their energy, with
// it friction only takes energy, and does take it (the form's mu reaches the model)
TEST(RollingModel, ASlidingBodyFromTheNewBodyFormOnACurvedSupportLosesEnergyOnlyToFriction) {
  RollingBodyForm top;
  top.shape = "sphere";
  top.sizes = {1, 0, 0};
  top.centre = {0, 0, 0.3};
  top.inertia = {0.35, 0.35, 0.4};
  top.symmetryAxis = true;
  top.support = "sphere";
  top.inside = true;
  RollingBodyForm ellipsoid;
  ellipsoid.support = "paraboloid";
  for (RollingBodyForm form : {top, ellipsoid}) {
    SCOPED_TRACE(form.shape);
    form.contact = "sliding";
    form.friction = 0;
    EXPECT_LT(relativeDrift(along(runForm(form, 5), "E")), 1e-10);
    form.friction = 0.3;
    const std::vector<double> E = along(runForm(form, 5), "E");
    for (std::size_t i = 1; i < E.size(); ++i)
      EXPECT_LE(E[i], E[i - 1] + 1e-12);
    EXPECT_LT(E.back(), E.front() - 1e-3);
  }
}

// What the form cannot make is refused before a file is written, naming the form's field: a superellipsoid
// flat along its mid-lines or with edges, a profile upside down, a support it does not offer
TEST(RollingModel, TheNewBodyFormRefusesWhatMakesNoModel) {
  const auto refusal = [](const RollingBodyForm& form) -> std::string {
    try {
      rollingModelDocument(form);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  RollingBodyForm form;
  form.shape = "superellipsoid";
  EXPECT_EQ(refusal(form), ""); // exponent 4, bulge 0.05
  form.bulge = 0;
  EXPECT_NE(refusal(form).find("the form's bulge:"), std::string::npos) << refusal(form);
  form.exponent = 1.5;
  EXPECT_NE(refusal(form).find("the form's exponent:"), std::string::npos) << refusal(form);
  form.shape = "revolution";
  EXPECT_EQ(refusal(form), "");
  form.heights = {0.5, -0.5};
  EXPECT_NE(refusal(form).find("the form's heights:"), std::string::npos) << refusal(form);
  form.shape = "sphere";
  form.support = "torus";
  EXPECT_NE(
      refusal(form).find("the form's support: expected plane, sphere, ellipsoid, paraboloid or implicit"),
      std::string::npos)
      << refusal(form);
}

TEST(RollingModel, ATopThatWouldLeaveThePlaneStopsTheRunSayingSo) {
  // weightless, the spinning top's plane would have to pull (N < 0): the sliding model no longer holds
  const std::map<std::string, double> spun{{"omega1", 0}, {"omega2", 0},
                                           {"omega3", 6}, {"gamma1", std::sin(0.1)},
                                           {"gamma2", 0}, {"gamma3", std::cos(0.1)}};
  try {
    runExample("tippe_top.json", {{"g", 0}}, spun, 5, 1);
    ADD_FAILURE() << "the run went on";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("definitions.leaves_the_plane"), std::string::npos) << e.what();
  }
}

TEST(RollingModel, AMalformedBodyIsNamedAtTheFieldTheUserWrote) {
  const json top = json::parse(R"({"kind": "rolling", "id": "bad_top", "parameters": {"R": {"default": 1}},
      "body": {"shape": "sphere", "radius": "R", "mass": 1, "inertia": [1, 1, 1]}, "contact": "marble"})");
  EXPECT_EQ(modelFileError(top), ""); // the good one loads
  json tensor = top;
  tensor["id"] = "tensor_top";
  tensor["body"]["inertia"] = json::parse(R"([[1, 0, 0], [0, "R", 0], [0, 0, 1]])");
  EXPECT_EQ(modelFileError(tensor), ""); // the full tensor as a JSON matrix
  const auto expect = [&](const json& bad, const std::string& part) {
    const std::string what = modelFileError(bad);
    EXPECT_NE(what.find(part), std::string::npos) << what;
  };
  json bad = top;
  bad["id"] = "bad_top2";
  bad["body"]["radius"] = "Rr";
  expect(bad, "m.json:body.radius: column 1: unknown name 'Rr' (did you mean 'R'?)");
  bad = top;
  bad["body"]["shape"] = "cube";
  expect(bad, "m.json:body.shape: expected \"sphere\"");
  bad = top;
  bad["contact"] = "sliding";
  expect(bad, "missing \"friction\"");
  bad = top;
  bad["parameters"]["omega"] = {{"default", 1}};
  expect(bad, "m.json:parameters.omega: 'omega' is a name the rolling model's derivation uses");
  bad = top;
  bad["parameters"]["gamma1"] = {{"default", 1}};
  expect(bad, "m.json:parameters.gamma1: 'gamma1' is a name the rolling model's derivation uses");
  bad = top;
  bad["support"] = {{"surface", "plane"}, {"centre", "[0, 0, 1]"}};
  expect(bad, "m.json:support");
  bad = top;
  bad["body"] = {{"shape", "implicit"}, {"F", "x^2 + y^2 + w^2 - 1"}, {"mass", 1}, {"inertia", {1, 1, 1}}};
  expect(bad, "m.json:body.F: unknown name 'w'");
  bad["body"]["F"] = "x^2 + (y";
  expect(bad, "m.json:body.F: column");
  bad = top;
  bad["support"] = {{"surface", "cube"}};
  expect(bad, "m.json:support.surface: expected \"plane\", \"sphere\"");
  bad = top;
  bad["support"] = {{"surface", "sphere"}, {"radius", 2}};
  EXPECT_EQ(modelFileError(bad), ""); // three moments: any body on a curved support
  bad["contact"] = "sliding";
  bad["friction"] = 1;
  EXPECT_EQ(modelFileError(bad), ""); // and slides on it
  bad["contact"] = "marble";
  bad.erase("friction");
  bad["potential"] = "gamma1";
  expect(bad,
         "has a potential U of `vertical` (the upward vertical in body axes) and `x` (its centre of mass "
         "in fixed axes); `gamma` is the support's normal there");
  bad.erase("potential");
  bad["support"]["describes"] = "centre";
  expect(bad, "m.json:support.describes: \"centre\" describes the surface a balanced ball's centre moves on");
  bad["support"] = {{"surface", "graph"}, {"height", "x1^2"}, {"describes", "centre"}};
  expect(bad, "m.json:support.surface: a \"graph\" support carries a balanced ball only");
  bad["body"]["inertia"] = 1;
  bad["contact"] = "sliding";
  bad["friction"] = 1;
  expect(bad,
         "m.json:support.surface: a \"graph\" support carries a balanced ball only (it gives the surface "
         "its centre moves on); a body sliding moves on");
  bad = top;
  bad["body"]["semi_axes"] = "[1, 2, 3]";
  expect(bad, "m.json:body.semi_axes: a sphere has no \"semi_axes\"");
  // a value of the wrong size, named at the field that holds it (not where the derivation first uses it)
  bad = top;
  bad["body"]["centre"] = "[0, 0.1]";
  expect(bad, "m.json:body.centre: the shape's centre must be a 3-vector, not a 2-vector");
  bad = top;
  bad["body"]["axis"] = "[0, 1]";
  expect(bad, "m.json:body.axis: the axis must be a 3-vector, not a 2-vector");
  bad = top;
  bad["body"]["inertia"] = json::array({1, "[1, 2, 3]", 1});
  expect(bad, "m.json:body.inertia.1: a principal moment of inertia must be a scalar, not a 3-vector");
  bad = top;
  bad["body"]["inertia"] = "diag(1, 2)";
  expect(bad, "m.json:body.inertia: the inertia tensor must be a 3x3 matrix, not a 2x2 matrix");
  bad = top;
  bad["body"]["radius"] = "[R, R]";
  expect(bad, "m.json:body.radius: the radius must be a scalar, not a 2-vector");
  bad = top;
  bad["body"] = {{"shape", "ellipsoid"}, {"semi_axes", "R"}, {"mass", 1}, {"inertia", {1, 1, 1}}};
  expect(bad, "m.json:body.semi_axes: the semi-axes must be a 3-vector, not a scalar");
  bad = top;
  bad["gravity"] = "[0, 0, 1]";
  expect(bad, "m.json:gravity: the gravity must be a scalar, not a 3-vector");
  const json brick = {{"shape", "superellipsoid"},
                      {"semi_axes", "[1, 0.8, 0.6]"},
                      {"exponent", 4},
                      {"bulge", 0.05},
                      {"mass", 1},
                      {"inertia", {1, 1, 1}}};
  bad = top;
  bad["body"] = brick;
  EXPECT_EQ(modelFileError(bad), "");
  bad["body"]["exponent"] = 1.5;
  expect(bad, "m.json:body.exponent: expected an exponent of at least 2");
  bad["body"]["exponent"] = 4;
  bad["body"].erase("bulge");
  expect(bad, "m.json:body: a superellipsoid with an exponent above 2 is flat along its mid-curves");
  bad["body"]["bulge"] = 0;
  expect(bad, "m.json:body.bulge: a superellipsoid with an exponent above 2 is flat");
  bad["body"] = brick;
  bad["body"]["radius"] = 1;
  expect(bad, "m.json:body.radius: a superellipsoid has no \"radius\"");
  bad["body"] = brick;
  bad["body"]["profile"] = "1 - z^2";
  expect(bad, "m.json:body.profile: only a \"revolution\" body has \"profile\"");
  bad["body"] = {{"shape", "revolution"},
                 {"profile", "sqrt(1 - x^2)"},
                 {"heights", "[-1, 1]"},
                 {"mass", 1},
                 {"inertia", {1, 1, 1}}};
  expect(bad, "m.json:body.profile: unknown name 'x' (this reads z,");
  bad["body"].erase("heights");
  bad["body"]["profile"] = "sqrt(1 - z^2)";
  expect(bad, "m.json:body: a revolution body needs \"heights\"");
  bad["body"]["profile_squared"] = "1 - z^2";
  expect(bad, "m.json:body: a revolution body gives its profile as \"profile\"");
  bad["body"].erase("profile_squared");
  bad["body"]["heights"] = "[1, 2, 3]";
  expect(bad, "m.json:body.heights: the profile's ends on its axis must be a 2-vector, not a 3-vector");
}

} // namespace
} // namespace rv
