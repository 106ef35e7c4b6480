#include "scenes/RollingModel.h"

#include "dynamics/core/Errors.h"
#include "dynamics/expr/Expression.h"
#include "dynamics/expr/Graph.h"
#include "dynamics/expr/Lowering.h"
#include "scenes/JsonFields.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <optional>
#include <set>

namespace rv {

using nlohmann::json;
using nlohmann::ordered_json;

bool isRollingModel(const json& doc) {
  return doc.is_object() && doc.contains("kind") && doc["kind"] == "rolling";
}

namespace {

enum class Contact { Marble, Rubber, Sliding };

/// The rotation of the unit quaternion q0..q3 (body to fixed axes).
constexpr const char* kRotation = "[[q0^2 + q1^2 - q2^2 - q3^2, 2*(q1*q2 - q0*q3), 2*(q1*q3 + q0*q2)], "
                                  "[2*(q1*q2 + q0*q3), q0^2 - q1^2 + q2^2 - q3^2, 2*(q2*q3 - q0*q1)], "
                                  "[2*(q1*q3 - q0*q2), 2*(q2*q3 + q0*q1), q0^2 - q1^2 - q2^2 + q3^2]]";

/// A sliding body's energy (v the centre of mass's velocity, body axes).
constexpr const char* kSlidingEnergy = "body_mass*dot(v, v)/2 + dot(omega, body_inertia*omega)/2 + potential";

constexpr const char* kShapes =
    "\"sphere\", \"ellipsoid\", \"paraboloid\", \"disk\", \"superellipsoid\", \"revolution\" or \"implicit\"";

class Generator {
public:
  Generator(const json& doc, const ordered_json* ordered, std::string source)
      : doc_(doc), ordered_(ordered), root_{std::move(source), ""} {}

  RollingEquations run() {
    requireObject(doc_, root_);
    onlyKeys(doc_, root_,
             {"id",      "title",   "reference", "description", "kind",    "parameters", "definitions",
              "body",    "support", "contact",   "friction",    "gravity", "potential",  "observables",
              "section", "map",     "complete",  "initial",     "view",    "measure"});
    for (const char* key :
         {"id", "title", "reference", "description", "parameters", "section", "map", "initial", "measure"})
      if (doc_.contains(key)) out_[key] = source(key);
    out_["kind"] = "flow";
    if (!doc_.contains("section")) out_["section"] = "gamma1"; // graph supports: set in ballOnSupport()
    readContact();
    readSupport();
    readBody();
    userDefinitions();
    if (!support_.empty() && balancedBall_)
      ballOnSupport();
    else if (!support_.empty())
      bodyOnSupport();
    else if (contact_ == Contact::Sliding)
      sliding();
    else
      rolling();
    observables();
    view();
    RollingEquations r;
    r.model = out_.dump();
    r.origins = std::move(origins_);
    r.shapes = std::move(shapes_);
    return r;
  }

private:
  /// The description's value at `key` (from the root), with its own key order when known.
  ordered_json source(const std::string& key) const {
    if (ordered_ && ordered_->contains(key)) return (*ordered_)[key];
    return ordered_json::parse(doc_[key].dump());
  }

  static RequiredShape scalar(std::string what) { return {1, 1, std::move(what)}; }
  static RequiredShape vector3(std::string what) { return {3, 1, std::move(what)}; }
  static RequiredShape matrix3(std::string what) { return {3, 3, std::move(what)}; }
  /// What a size of a shape is, and its shape (the semi-axes a 3-vector, the others scalars).
  static RequiredShape sizeShape(const std::string& key) {
    if (key == "semi_axes") return vector3("the semi-axes");
    if (key == "p" || key == "q") return scalar("a radius of curvature");
    if (key == "heights") return {2, 1, "the profile's ends on its axis"};
    return scalar("the " + key);
  }

  /// An expression the user wrote (a string, or a number), under a generated definition `name`, which must
  /// have `shape` (a wrong one is named at the user's field).
  void userExpression(const std::string& name, const json& j, const Where& w, RequiredShape shape) {
    std::string e;
    if (j.is_number())
      e = j.dump();
    else if (j.is_string())
      e = j.get<std::string>();
    else
      w.fail("expected an expression (a string or a number)");
    define(name, e);
    origins_.emplace_back("definitions." + name, w.path);
    shapes_[name] = std::move(shape);
  }

  void define(const std::string& name, const std::string& expression) {
    // a user's parameter or definition of a name the derivation takes later would be overwritten silently
    if (const auto user = userNamed_.find(name); user != userNamed_.end())
      user->second.fail("'" + name + "' is a name the rolling model's derivation uses: choose another");
    out_["definitions"][name] = expression;
    generated_.insert(name);
  }

  void readContact() {
    const std::string c = doc_.contains("contact") ? text(doc_["contact"], root_ / "contact") : "marble";
    if (c == "marble")
      contact_ = Contact::Marble;
    else if (c == "rubber")
      contact_ = Contact::Rubber;
    else if (c == "sliding")
      contact_ = Contact::Sliding;
    else
      (root_ / "contact")
          .fail("expected \"marble\" (rolling without slipping), \"rubber\" (without slipping and without "
                "spinning about the normal) or \"sliding\" (viscous friction at the contact)");
    if (contact_ == Contact::Sliding) {
      if (!doc_.contains("friction"))
        root_.fail("missing \"friction\": a sliding contact needs its viscous friction coefficient mu "
                   "(the force -mu v at the contact point)");
      userExpression("friction_mu", doc_["friction"], root_ / "friction", scalar("the friction coefficient"));
    } else if (doc_.contains("friction")) {
      (root_ / "friction").fail("only a \"sliding\" contact has friction (a rolling one does no work)");
    }
    userExpression("gravity_g", doc_.contains("gravity") ? doc_["gravity"] : json(0), root_ / "gravity",
                   scalar("the gravity"));
    if (doc_.contains("potential")) {
      userExpression("potential_U", doc_["potential"], root_ / "potential", scalar("the potential"));
      potential_ = true;
    }
  }

  /// The support: the plane, or a fixed surface a balanced ball rolls on -- given by its inverse Gauss map
  /// (sphere, ellipsoid, paraboloid: the point whose normal towards the ball is gamma) or, for the surface
  /// the ball's centre moves on, as a height over the plane ("graph"). "describes": "centre" gives the sizes
  /// of the surface the centre moves on (the manual's way) instead of the support's own.
  void readSupport() {
    if (!doc_.contains("support")) return;
    const Where w = root_ / "support";
    const json& s = doc_["support"];
    if (s.is_string()) {
      if (text(s, w) == "plane") return;
      w.fail("a curved support is an object: {\"surface\": \"sphere\", \"radius\": ...}");
    }
    requireObject(s, w);
    onlyKeys(
        s, w,
        {"surface", "radius", "semi_axes", "p", "q", "side", "height", "describes", "F", "size", "point"});
    if (!s.contains("surface"))
      w.fail("missing \"surface\" (plane, sphere, ellipsoid, paraboloid, implicit or graph)");
    support_ = text(s["surface"], w / "surface");
    if (support_ == "plane") {
      if (s.size() > 1) w.fail("the plane has no sizes");
      support_.clear();
      return;
    }
    const auto need = [&](const char* key, const std::string& name) {
      if (!s.contains(key)) w.fail("a " + support_ + " support needs \"" + key + "\"");
      userExpression(name, s[key], w / key, sizeShape(key));
    };
    const std::string describes = s.contains("describes") ? text(s["describes"], w / "describes") : "support";
    if (describes != "support" && describes != "centre")
      (w / "describes")
          .fail("expected \"support\" (the sizes are the support's) or \"centre\" (the sizes are of the "
                "surface the ball's centre moves on)");
    centreSurface_ = describes == "centre";
    const std::string side = s.contains("side") ? text(s["side"], w / "side") : "";
    if (!side.empty() && side != "outside" && side != "inside")
      (w / "side")
          .fail("expected \"outside\" (the body rolls on the " + support_ + ") or \"inside\" (in it)");
    inside_ = side == "inside";
    if (support_ == "sphere") {
      need("radius", "support_radius");
      supportContact_ = inside_ ? "-support_radius*gamma" : "support_radius*gamma";
      supportView_ = {{"surface", "sphere"}, {"radius", "support_radius"}};
    } else if (support_ == "ellipsoid") {
      need("semi_axes", "support_semi_axes");
      define("support_axes_squared", "diag(support_semi_axes)*diag(support_semi_axes)");
      // the point whose outward normal is gamma (outside) or -gamma (inside: a bowl)
      supportContact_ = std::string(inside_ ? "-" : "") +
                        "(support_axes_squared*gamma)/sqrt(dot(gamma, support_axes_squared*gamma))";
      supportView_ = {{"surface", "ellipsoid"}, {"semi_axes", "support_semi_axes"}};
    } else if (support_ == "paraboloid") { // a bowl z = x^2/(2p) + y^2/(2q); gamma its upward normal
      need("p", "support_p");
      need("q", "support_q");
      inside_ = true;
      supportContact_ = "[-support_p*gamma[1]/gamma[3], -support_q*gamma[2]/gamma[3], "
                        "(support_p*gamma[1]^2 + support_q*gamma[2]^2)/(2*gamma[3]^2)]";
      supportView_ = {{"surface", "paraboloid"}, {"p", "support_p"}, {"q", "support_q"}};
    } else if (support_ == "implicit") { // F(x, y, z) = 0 in fixed axes, F < 0 in the support's solid
      if (!s.contains("F"))
        w.fail("an implicit support needs \"F\": its surface F(x, y, z) = 0 in fixed axes, F < 0 inside the "
               "support (the body rolls on the side where F > 0)");
      const std::string F = userFunction(s["F"], w / "F", {"x", "y", "z"}).text;
      supportImplicit_ = expr::parse(F);
      if (!s.contains("size"))
        w.fail("an implicit support needs \"size\": a length that bounds the part of it drawn around the "
               "origin and the first contact's search");
      userExpression("support_size", s["size"], w / "size", scalar("the support's size"));
      if (s.contains("point"))
        userExpression("support_start", s["point"], w / "point", vector3("a point of the support"));
      else
        define("support_start", "[0, 0, 0]");
      supportView_ = {{"surface", "implicit"}, {"F", F}, {"size", "support_size"}};
    } else if (support_ == "graph") { // the centre's height over the plane, z = height(x1, x2)
      need("height", "support_height");
      if (!centreSurface_)
        (w / "describes")
            .fail("a graph gives the height of the surface the centre moves on: \"describes\": \"centre\"");
    } else {
      (w / "surface")
          .fail("expected \"plane\", \"sphere\", \"ellipsoid\", \"paraboloid\", \"implicit\" or \"graph\"");
    }
    if (!supportImplicit_)
      for (const char* key : {"F", "size", "point"})
        if (s.contains(key)) (w / key).fail(std::string("only an \"implicit\" support has \"") + key + "\"");
    for (const char* key : {"radius", "semi_axes", "p", "q", "height"})
      if (s.contains(key) && !out_["definitions"].contains(std::string("support_") + key))
        (w / key).fail("a " + support_ + " support has no \"" + key + "\"");
    if (s.contains("side") && support_ != "sphere" && support_ != "ellipsoid")
      (w / "side").fail("only a sphere or an ellipsoid has a side");
  }

  /// A user's expression of some of x, y, z (an implicit surface's F, a profile's radius of z): parsed
  /// here, so that an error is named at its field, and its names checked (those point coordinates, the
  /// parameters, the user's definitions).
  expr::Expression userFunction(const json& j, const Where& w, const std::vector<std::string>& point) const {
    std::string of;
    for (const std::string& c : point)
      of += (of.empty() ? "" : ", ") + c;
    if (!j.is_string()) w.fail("expected an expression of " + of + " (a string)");
    std::optional<expr::Expression> e;
    try {
      e = expr::parse(j.get<std::string>());
    } catch (const expr::ExprError& error) {
      w.fail(error.what());
    }
    std::vector<std::string> known = point;
    known.push_back("pi");
    for (const char* section : {"parameters", "definitions"})
      if (doc_.contains(section) && doc_[section].is_object())
        for (const auto& [name, value] : doc_[section].items())
          known.push_back(name);
    for (const std::string& name : expr::namesUsed(*e))
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        const std::string near = expr::nearestName(name, known);
        w.fail("unknown name '" + name + "' (this reads " + of + ", the parameters and your definitions" +
               (near.empty() ? ")" : "; did you mean '" + near + "'?)"));
      }
    return *e;
  }

  /// The body's surface as F(x, y, z) = 0 (F < 0 inside), rolled by the implicit machinery; `start`, when
  /// given, is an F with the same zeros near the body that is defined everywhere (the contact's first
  /// Newton steps begin far from it) and is also the one the 3D view samples.
  void implicitSurface(const std::string& F, const std::string& start = "") {
    implicit_ = expr::parse(F);
    implicitStart_ = expr::parse(start.empty() ? F : start);
    shapeView_ = {{"body", "implicit"}, {"F", start.empty() ? F : start}, {"size", "body_size"}};
    shapeContact_ = "contact_newton";
  }

  /// F at the point named `p` (a 3-vector expression).
  static std::string implicitAt(const expr::Expression& F, const std::string& p) {
    return expr::renamed(F, {{"x", p + "[1]"}, {"y", p + "[2]"}, {"z", p + "[3]"}});
  }

  /// A size of the shape the user may give: theirs, or `otherwise`.
  void sizeOr(const json& b, const Where& w, const char* key, const std::string& name,
              const std::string& otherwise) {
    if (b.contains(key))
      userExpression(name, b[key], w / key, sizeShape(key));
    else
      define(name, otherwise);
  }

  /// A definition that is 0 where `ok` (an expression) is positive and not finite elsewhere: added to the
  /// contact, it stops the run where the model stops holding, naming `name` (as `turns_over` does).
  void guard(const std::string& name, const std::string& ok) {
    define(name, "(1 - max(0, sign(" + ok + ")))/max(0, sign(" + ok + "))");
  }

  /// |x/a1|^p + |y/a2|^p + |z/a3|^p + bulge ((x/a1)^2 + (y/a2)^2 + (z/a3)^2 - 1) = 1 (A. H. Barr,
  /// Superquadrics and angle-preserving transformations, IEEE Computer Graphics and Applications 1 (1981)
  /// 11-23, with one exponent). For p > 2 the pure superellipsoid is flat (zero normal curvature) along its
  /// three mid-curves x_i = 0 -- the face centres among them -- so there the shape operator is singular and
  /// the contact's rate infinite: the bulge, a multiple of the ellipsoid through the same vertices, keeps the
  /// Hessian of F positive definite, hence the surface strictly convex with the semi-axes unchanged. Below
  /// p = 2 the curvature is infinite along the mid-curves (edges towards an octahedron): not offered.
  /// |u|^p is written (u^2 + 1e-100)^(p/2): the same number to rounding for |u| > 1e-42, with derivatives
  /// of every order the Newton step and the Jacobian take finite at u = 0 (|u|^p's are 0 * inf there for a
  /// p given as a parameter).
  void superellipsoid(const json& b, const Where& w) {
    for (const char* key : {"semi_axes", "exponent"})
      if (!b.contains(key)) w.fail(std::string("a superellipsoid needs \"") + key + "\"");
    userExpression("body_semi_axes", b["semi_axes"], w / "semi_axes", sizeShape("semi_axes"));
    userExpression("body_exponent", b["exponent"], w / "exponent", sizeShape("exponent"));
    sizeOr(b, w, "bulge", "body_bulge", "0");
    sizeOr(b, w, "size", "body_size", "norm(body_semi_axes)");
    // numbers are checked now (exit 2), expressions of parameters when the model runs (the guard)
    const json& p = b["exponent"];
    if (p.is_number() && p.get<double>() < 2)
      (w / "exponent")
          .fail("expected an exponent of at least 2 (2: the ellipsoid; above 2 the faces flatten towards a "
                "box's); below 2 the surface has edges of infinite curvature along its mid-curves");
    const bool flat = p.is_number() && p.get<double>() > 2;
    if (flat && (!b.contains("bulge") || (b["bulge"].is_number() && b["bulge"].get<double>() <= 0)))
      (b.contains("bulge") ? w / "bulge" : w)
          .fail("a superellipsoid with an exponent above 2 is flat along its mid-curves x_i = 0 (the face "
                "centres among them): there the contact's rate is infinite. Give \"bulge\" > 0 (e.g. 0.05), "
                "the weight of the ellipsoid through the same vertices that keeps it strictly convex");
    guard("not_strictly_convex", "(1 - abs(sign(body_exponent - 2))) + "
                                 "max(0, sign(body_exponent - 2))*max(0, sign(body_bulge)) - 1/2");
    std::string F, quadric;
    for (int i = 0; i < 3; ++i) {
      const std::string u = std::string("(") + "xyz"[i] + "/body_semi_axes[" + std::to_string(i + 1) + "])^2";
      F += "(" + u + " + 1e-100)^(body_exponent/2) + ";
      quadric += (i ? " + " : "") + u;
    }
    implicitSurface(F + "body_bulge*(" + quadric + " - 1) - 1");
    // the first contact's steps begin at the contact without the bulge, in closed form: s = -grad h(gamma),
    // h(gamma) = (sum |a_i gamma_i|^q)^(1/q), q = p/(p - 1), the support function (the dual norm); Newton
    // from a point far off diverges on flat faces
    define("superellipsoid_q", "body_exponent/(body_exponent - 1)");
    std::string guess, sum;
    for (int i = 1; i <= 3; ++i) {
      const std::string a = "body_semi_axes[" + std::to_string(i) + "]",
                        g = "gamma[" + std::to_string(i) + "]";
      guess += (i > 1 ? ", " : "") + a + "*sign(" + g + ")*abs(" + a + "*" + g + ")^(superellipsoid_q - 1)";
      sum += (i > 1 ? " + " : "") + std::string("abs(") + a + "*" + g + ")^superellipsoid_q";
    }
    contactGuess_ = "-[" + guess + "]/(" + sum + ")^(1/body_exponent)";
    shapeContact_ += " + [0, 0, not_strictly_convex]";
  }

  /// A body of revolution about body axis 3: its radius rho(z) at the height z (or rho(z)^2), from the
  /// bottom to the top of the profile: F = x^2 + y^2 - rho(z)^2. Newton's first steps and the 3D view take
  /// the profile's radius at z clamped to just inside the ends and close it beyond them; where the radius
  /// does not fall to zero at an end the body has an edge or a flat cap there, and a contact that reaches it
  /// stops the run (the guard `leaves_the_profile`).
  void revolution(const json& b, const Where& w) {
    if (b.contains("profile") == b.contains("profile_squared"))
      w.fail("a revolution body gives its profile as \"profile\" (the radius rho(z) at the height z along "
             "body axis 3) or as \"profile_squared\" (rho(z)^2), one of them");
    const bool squared = b.contains("profile_squared");
    const char* key = squared ? "profile_squared" : "profile";
    const expr::Expression profile = userFunction(b[key], w / key, {"z"});
    if (!b.contains("heights"))
      w.fail("a revolution body needs \"heights\": \"[bottom, top]\", the profile's ends on its axis");
    userExpression("body_heights", b["heights"], w / "heights", sizeShape("heights"));
    const auto radius2 = [&](const std::string& z) {
      const std::string r = expr::renamed(profile, {{"z", z}});
      return squared ? "(" + r + ")" : "(" + r + ")^2";
    };
    // clamped a millionth of the length inside the ends: at an end rho' may be infinite (a pole, rho(z)^2
    // smooth there), and 0 * inf is not 0
    const std::string inset = "1e-6*(body_heights[2] - body_heights[1])";
    const std::string clamped =
        "min(max(z, body_heights[1] + " + inset + "), body_heights[2] - " + inset + ")";
    std::string widest = "max(abs(body_heights[1]), abs(body_heights[2]))";
    constexpr int kSamples = 16; // the widest radius, sampled, for the default size
    for (int k = 1; k < kSamples; ++k)
      widest = "max(" + widest + ", sqrt(max(0, " +
               radius2("body_heights[1] + " + std::to_string(k) + "/" + std::to_string(kSamples) +
                       "*(body_heights[2] - body_heights[1])") +
               ")))";
    sizeOr(b, w, "size", "body_size", "1.1*" + widest);
    implicitSurface("x^2 + y^2 - " + radius2("z"),
                    "x^2 + y^2 - " + radius2(clamped) +
                        " + max(0, (z - body_heights[1])*(z - body_heights[2]))");
    guard("leaves_the_profile", "(contact_newton[3] - body_heights[1])*(body_heights[2] - contact_newton[3])"
                                "/(body_heights[2] - body_heights[1])^2 + 1e-9");
    shapeContact_ += " + [0, 0, leaves_the_profile]";
  }

  /// One Newton step `to` from the point `from` towards the contact: onto F = 0 along the gradient, then
  /// along the surface so that the unit gradient (the outward normal) turns to `normal` (the shape
  /// operator's inverse, from the Hessian, as the closed forms' contact rate uses it). Quadratic from a
  /// point near the contact; a damped step moves at most 0.3 `size` along the surface.
  void newtonStep(const expr::Expression& F, const std::string& from, const std::string& to, bool damped,
                  const std::string& normal = "-gamma", const std::string& size = "body_size") {
    define(to + "_F0", implicitAt(F, from));
    define(to + "_g0", "gradient(" + to + "_F0, " + from + ")");
    define(to + "_on", from + " - (" + to + "_F0/dot(" + to + "_g0, " + to + "_g0))*" + to + "_g0");
    define(to + "_F", implicitAt(F, to + "_on"));
    define(to + "_g", "gradient(" + to + "_F, " + to + "_on)");
    define(to + "_n", "normalize(" + to + "_g)");
    define(to + "_P", "identity() - outer(" + to + "_n, " + to + "_n)");
    define(to + "_K", to + "_P*jacobian(" + to + "_g, " + to + "_on)*" + to + "_P/norm(" + to +
                          "_g) + outer(" + to + "_n, " + to + "_n)");
    if (!damped) {
      define(to, to + "_on + inverse(" + to + "_K)*(" + to + "_P*(" + normal + "))");
      return;
    }
    // far from the contact, where the curvature of a flat-faced body changes fast, a full step overshoots:
    // at most 0.3 size along the surface (then full steps, quadratic, once near)
    define(to + "_step", "inverse(" + to + "_K)*(" + to + "_P*(" + normal + "))");
    define(to, to + "_on + min(1, 0.3*" + size + "/norm(" + to + "_step))*" + to + "_step");
  }

  /// The implicit body's contact: one Newton step from the one carried in the state, which follows the
  /// contact's rate (so it is off by the integration's error, squared by the step), and a start for it from
  /// gamma alone.
  void implicitContact() {
    newtonStep(*implicit_, "contact", "contact_newton", false);
    define("contact_start_0", contactGuess_);
    constexpr int kStartSteps = 16;
    for (int k = 1; k <= kStartSteps; ++k)
      newtonStep(*implicitStart_, "contact_start_" + std::to_string(k - 1),
                 "contact_start_" + std::to_string(k), true);
    for (int i = 1; i <= 3; ++i)
      out_["complete"]["contact" + std::to_string(i)] =
          "contact_start_" + std::to_string(kStartSteps) + "[" + std::to_string(i) + "]";
    out_["equations"]["contact"] = "derivative(contact_s, gamma, dgamma)";
  }

  /// An implicit support's contact, in fixed axes: one Newton step from the one carried in the state onto
  /// F = 0 with the unit gradient (out of the support, into the body) turned to N, as an implicit body's.
  void implicitSupportContact() {
    newtonStep(*supportImplicit_, "support_contact", "support_point", false, "N", "support_size");
  }

  /// Its start: damped Newton steps from the support's "point" (the origin by default) towards the normal
  /// N of the state being completed (its q completed first when left out).
  void completeSupportContact() {
    // (nudged along the normal: a start that is a constant has no derivative for the steps to take)
    define("support_start_0", "support_start + 1e-3*support_size*rotation*normalize(gamma)");
    constexpr int kStartSteps = 24;
    for (int k = 1; k <= kStartSteps; ++k)
      newtonStep(*supportImplicit_, "support_start_" + std::to_string(k - 1),
                 "support_start_" + std::to_string(k), true, "rotation*normalize(gamma)", "support_size");
    for (int i = 1; i <= 3; ++i)
      out_["complete"]["support_contact" + std::to_string(i)] =
          "support_start_" + std::to_string(kStartSteps) + "[" + std::to_string(i) + "]";
  }

  void readBody() {
    const Where w = root_ / "body";
    if (!doc_.contains("body")) root_.fail("missing \"body\" (its shape, sizes, mass and inertia)");
    const json& b = requireObject(doc_["body"], w);
    onlyKeys(b, w,
             {"shape", "radius", "semi_axes", "p", "q", "height", "F", "size", "exponent", "bulge", "profile",
              "profile_squared", "heights", "centre", "mass", "inertia", "principal_axes", "gyrostat",
              "axis"});
    if (!b.contains("shape")) w.fail("missing \"shape\" (" + std::string(kShapes) + ")");
    shape_ = text(b["shape"], w / "shape");
    const auto need = [&](const char* key, const std::string& name) {
      if (!b.contains(key)) w.fail("a " + shape_ + " needs \"" + key + "\"");
      userExpression(name, b[key], w / key, sizeShape(key));
    };
    // the contact point s(gamma) relative to the shape's own origin, where the body's outward normal is
    // -gamma (the inverse Gauss map), and how the 3D view draws the shape
    if (shape_ == "sphere") {
      need("radius", "body_radius");
      shapeContact_ = "-body_radius*gamma";
      shapeView_ = {{"body", "ball"}, {"radius", "body_radius"}};
    } else if (shape_ == "ellipsoid") {
      need("semi_axes", "body_semi_axes");
      define("body_axes_squared", "diag(body_semi_axes)*diag(body_semi_axes)");
      shapeContact_ = "-(body_axes_squared*gamma)/sqrt(dot(gamma, body_axes_squared*gamma))";
      shapeView_ = {{"body", "ellipsoid"}, {"semi_axes", "body_semi_axes"}};
    } else if (shape_ ==
               "paraboloid") { // z = x^2/(2p) + y^2/(2q), the vertex at the origin, opening along +3
      need("p", "body_p");
      need("q", "body_q");
      shapeContact_ = "[-body_p*gamma[1]/gamma[3], -body_q*gamma[2]/gamma[3], "
                      "(body_p*gamma[1]^2 + body_q*gamma[2]^2)/(2*gamma[3]^2)]";
      // it touches with its vertex side only (gamma3 > 0): past that the run stops, named after this
      // definition
      define("turns_over", "(1 - max(0, sign(gamma[3])))/max(0, sign(gamma[3]))");
      shapeContact_ += " + [0, 0, turns_over]";
      shapeView_ = {{"body", "paraboloid"}, {"p", "body_p"}, {"q", "body_q"}};
      if (b.contains("height")) {
        userExpression("body_height", b["height"], w / "height", sizeShape("height"));
        shapeView_["height"] = "body_height";
      } else {
        shapeView_["height"] = "2*max(body_p, body_q)";
      }
    } else if (shape_ == "disk") { // a thin disk in the plane of axes 1, 2, touching with its edge
      need("radius", "body_radius");
      shapeContact_ = "-(body_radius/sqrt(gamma[1]^2 + gamma[2]^2))*[gamma[1], gamma[2], 0]";
      shapeView_ = {{"body", "ellipsoid"}, {"semi_axes", "[body_radius, body_radius, body_radius/40]"}};
    } else if (shape_ == "implicit") { // F(x, y, z) = 0, F < 0 inside: the contact found by Newton's method
      if (!b.contains("F")) w.fail("an implicit body needs \"F\": its surface F(x, y, z) = 0, F < 0 inside");
      implicitSurface(userFunction(b["F"], w / "F", {"x", "y", "z"}).text);
      if (b.contains("size"))
        userExpression("body_size", b["size"], w / "size", sizeShape("size"));
      else
        define("body_size", "1");
    } else if (shape_ == "superellipsoid") {
      superellipsoid(b, w);
    } else if (shape_ == "revolution") {
      revolution(b, w);
    } else {
      (w / "shape").fail("expected " + std::string(kShapes));
    }
    for (const char* key : {"radius", "semi_axes", "p", "q", "height", "exponent", "bulge", "heights"})
      if (b.contains(key) && !out_["definitions"].contains(std::string("body_") + key))
        (w / key).fail("a " + shape_ + " has no \"" + key + "\"");
    if (b.contains("size") && !implicit_) (w / "size").fail("a " + shape_ + " has no \"size\"");
    if (b.contains("F") && shape_ != "implicit") (w / "F").fail("only an \"implicit\" body has \"F\"");
    for (const char* key : {"profile", "profile_squared"})
      if (b.contains(key) && shape_ != "revolution")
        (w / key).fail(std::string("only a \"revolution\" body has \"") + key + "\"");
    centred_ = b.contains("centre");
    if (centred_)
      userExpression("body_centre", b["centre"], w / "centre", vector3("the shape's centre"));
    else
      define("body_centre", "[0, 0, 0]");
    if (!b.contains("mass")) w.fail("missing \"mass\"");
    userExpression("body_mass", b["mass"], w / "mass", scalar("the mass"));
    if (!b.contains("inertia"))
      w.fail("missing \"inertia\" (the central principal moments [I1, I2, I3], or the tensor as a matrix)");
    const json& I = b["inertia"];
    if (I.is_array() && !I.empty() && I[0].is_array()) { // the full tensor as a JSON matrix
      if (I.size() != 3) (w / "inertia").fail("expected three rows of three expressions");
      std::string matrix = "[";
      for (std::size_t i = 0; i < 3; ++i) {
        const Where row = w / "inertia" / std::to_string(i);
        if (!I[i].is_array() || I[i].size() != 3) row.fail("expected a row of three expressions");
        matrix += i ? ", [" : "[";
        for (std::size_t j = 0; j < 3; ++j) {
          const json& e = I[i][j];
          if (!e.is_string() && !e.is_number()) (row / std::to_string(j)).fail("expected an expression");
          matrix += (j ? ", " : "") + (e.is_string() ? "(" + e.get<std::string>() + ")" : e.dump());
        }
        matrix += "]";
      }
      if (b.contains("principal_axes"))
        (w / "principal_axes").fail("principal axes go with three principal moments, not a full tensor");
      userExpression("body_inertia", json(matrix + "]"), w / "inertia", matrix3("the inertia tensor"));
    } else if (I.is_array()) { // principal moments, along the body axes or along the rows of principal_axes
      if (I.size() != 3) (w / "inertia").fail("expected three principal moments");
      std::string moments;
      for (std::size_t i = 0; i < 3; ++i) {
        const std::string name = "body_I" + std::to_string(i + 1);
        userExpression(name, I[i], w / "inertia" / std::to_string(i),
                       scalar("a principal moment of inertia"));
        moments += (i ? ", " : "") + name;
      }
      if (b.contains("principal_axes")) {
        userExpression("body_principal_axes", b["principal_axes"], w / "principal_axes",
                       matrix3("the principal axes (rows)"));
        define("body_inertia", "transpose(body_principal_axes)*diag(" + moments + ")*body_principal_axes");
      } else {
        define("body_inertia", "diag(" + moments + ")");
      }
    } else {
      if (b.contains("principal_axes"))
        (w / "principal_axes").fail("principal axes go with three principal moments, not a full tensor");
      if (!support_.empty() && (supportImplicit_ || contact_ == Contact::Sliding)) {
        // a ball's one central moment: it moves in body axes like any other body
        userExpression("body_moment", I, w / "inertia", scalar("the ball's central moment of inertia"));
        define("body_inertia", "body_moment*identity()");
      } else {
        userExpression("body_inertia", I, w / "inertia",
                       support_.empty() ? matrix3("the inertia tensor")
                                        : scalar("the ball's central moment of inertia"));
      }
    }
    if (b.contains("gyrostat")) {
      userExpression("body_gyrostat", b["gyrostat"], w / "gyrostat", vector3("the gyrostat"));
      gyrostat_ = true;
    }
    if (b.contains("axis")) {
      userExpression("body_axis", b["axis"], w / "axis", vector3("the axis"));
      axis_ = true;
    }
    // a balanced ball (a sphere with no centre, gyrostat or principal axes, one central moment) rolling on a
    // closed-form curved support moves in the fixed frame; any other body, and any body sliding or on an
    // implicit support, in body axes
    balancedBall_ = shape_ == "sphere" && !b.contains("centre") && !b.contains("gyrostat") &&
                    !b.contains("principal_axes") && !I.is_array() && !supportImplicit_ &&
                    contact_ != Contact::Sliding;
    if (support_.empty() || balancedBall_) return;
    const std::string which =
        supportImplicit_ || contact_ == Contact::Sliding
            ? std::string("a body ") + (supportImplicit_ ? "on an implicit support" : "sliding")
            : "a body other than a balanced ball (a \"sphere\" with no \"centre\", "
              "gyrostat or principal axes and one central moment of inertia)";
    if (support_ == "graph")
      (root_ / "support" / "surface")
          .fail("a \"graph\" support carries a balanced ball only (it gives the surface its centre moves "
                "on); " +
                which + " moves on a \"sphere\", \"ellipsoid\", \"paraboloid\" or \"implicit\" support");
    if (centreSurface_)
      (root_ / "support" / "describes")
          .fail("\"centre\" describes the surface a balanced ball's centre moves on; for " + which +
                " give the support's own sizes (\"describes\": \"support\")");
    if (potential_ && doc_["potential"].is_string()) { // U(vertical, x): body axes' vertical, fixed axes' x
      std::vector<std::string> used;
      try {
        used = expr::namesUsed(expr::parse(doc_["potential"].get<std::string>()));
      } catch (const expr::ExprError&) { // said at the field when the model is checked
      }
      if (std::any_of(used.begin(), used.end(),
                      [](const std::string& n) { return n.rfind("gamma", 0) == 0; }))
        (root_ / "potential")
            .fail(
                "on a curved support " + which +
                " has a potential U of `vertical` (the upward vertical in body axes) and `x` (its centre of "
                "mass in fixed axes); `gamma` is the support's normal there");
    }
  }

  /// The user's definitions, after checking none takes a name the derivation uses.
  void userDefinitions() {
    static const std::set<std::string> names{"M",
                                             "gamma",
                                             "alpha",
                                             "beta",
                                             "omega",
                                             "v",
                                             "x",
                                             "y",
                                             "r",
                                             "dr",
                                             "dgamma",
                                             "A",
                                             "A_gamma",
                                             "omega_free",
                                             "contact_s",
                                             "potential",
                                             "dM_free",
                                             "dA_omega",
                                             "spin_couple",
                                             "v_contact",
                                             "v_slip",
                                             "friction_force",
                                             "L",
                                             "I_inverse",
                                             "v_free",
                                             "omega_per_N",
                                             "normal_force",
                                             "first",
                                             "seed",
                                             "alpha0"};
    const auto component = [](const std::string& name) { // M1, gamma2, ..., x, y, s_plane, s_body
      for (const char* v : {"M", "gamma", "alpha", "beta", "omega", "v", "contact"})
        for (const char* i : {"1", "2", "3"})
          if (name == std::string(v) + i) return true;
      for (const char* i : {"1", "2", "3"})
        if (name == std::string("support_contact") + i) return true;
      return name == "s_plane" || name == "s_body" || name == "q0" || name == "q1" || name == "q2" ||
             name == "q3";
    };
    const auto taken = [&](const std::string& name) {
      return names.count(name) || generated_.count(name) || component(name);
    };
    if (doc_.contains("parameters") && doc_["parameters"].is_object())
      for (const auto& [name, value] : doc_["parameters"].items()) {
        if (taken(name))
          (root_ / "parameters" / name)
              .fail("'" + name + "' is a name the rolling model's derivation uses: choose another");
        userNamed_.emplace(name, root_ / "parameters" / name);
      }
    if (!doc_.contains("definitions")) return;
    const ordered_json defs = source("definitions");
    if (!defs.is_object()) (root_ / "definitions").fail("expected an object of named expressions");
    for (const auto& [name, value] : defs.items()) {
      if (taken(name))
        (root_ / "definitions" / name)
            .fail("'" + name + "' is a name the rolling model's derivation uses: choose another");
      out_["definitions"][name] = value;
      userNamed_.emplace(name, root_ / "definitions" / name);
    }
  }

  std::string gyrostat() const { return gyrostat_ ? " + body_gyrostat" : ""; }

  /// The torque of the user's potential U(gamma): gamma x dU/dgamma (the contact's rate is tangent, so a
  /// potential of the orientation alone has no other).
  std::string potentialTorque() const {
    return potential_ ? " + cross(gamma, gradient(potential_U, gamma))" : "";
  }

  /// State vectors v1, v2, v3 for each name, in order.
  static void addVectors(ordered_json& state, ordered_json& vectors, const std::vector<const char*>& names) {
    for (const char* v : names) {
      ordered_json components = ordered_json::array();
      for (int i = 1; i <= 3; ++i) {
        const std::string n = std::string(v) + std::to_string(i);
        state.push_back(n);
        components.push_back(n);
      }
      vectors[v] = components;
    }
  }

  /// The space frame seen from the body turns against omega; the centre of mass moves with v.
  static void frameEquations(ordered_json& eq) {
    eq["gamma"] = "dgamma";
    eq["alpha"] = "cross(alpha, omega)";
    eq["beta"] = "cross(beta, omega)";
    eq["x"] = "dot(v, alpha)";
    eq["y"] = "dot(v, beta)";
  }

  void common() {
    if (implicit_) implicitContact();
    define("contact_s", shapeContact_);
    define("r", "contact_s + body_centre");
    define("dgamma", "cross(gamma, omega)");
    define("dr", "derivative(r, gamma, dgamma)");
    define("potential",
           "-body_mass*gravity_g*dot(r, gamma)" + std::string(potential_ ? " + potential_U" : ""));
    // a frame completing gamma: alpha normal to it, beta = gamma x alpha
    define("first", "(1 + sign(0.9 - abs(gamma1)))/2");
    define("seed", "[first, 1 - first, 0]");
    define("alpha0", "normalize(seed - dot(seed, gamma)*gamma)");
    ordered_json& c = out_["complete"];
    for (int i = 1; i <= 3; ++i) {
      c["alpha" + std::to_string(i)] = "alpha0[" + std::to_string(i) + "]";
      c["beta" + std::to_string(i)] = "cross(gamma, alpha0)[" + std::to_string(i) + "]";
    }
    c["x"] = "0";
    c["y"] = "0";
  }

  void rolling() {
    ordered_json state = ordered_json::array(), vectors;
    if (implicit_)
      addVectors(state, vectors, {"M", "gamma", "contact", "alpha", "beta"});
    else
      addVectors(state, vectors, {"M", "gamma", "alpha", "beta"});
    for (const char* n : {"x", "y", "s_plane", "s_body"})
      state.push_back(n);
    out_["state"] = state;
    out_["vectors"] = vectors;
    common();
    define("A", "body_inertia + body_mass*(dot(r, r)*identity() - outer(r, r))");
    const std::string forces =
        "body_mass*cross(dr, cross(omega, r)) + body_mass*gravity_g*cross(r, gamma)" + potentialTorque();
    ordered_json& eq = out_["equations"];
    if (contact_ == Contact::Marble) {
      define("omega", "inverse(A)*M");
      eq["M"] = "cross(M" + gyrostat() + ", omega) + " + forces;
    } else {
      rubber(forces, false);
      // a balanced ball: (J omega)' = J omega x omega + lambda gamma with J = I + m R^2 E (Veselova's
      // system), whose invariant measure in (M, gamma) has the density (gamma, J^-1 gamma)^(-1/2)
      // (docs/rolling.md)
      if (shape_ == "sphere" && !centred_ && !gyrostat_ && !potential_ && !doc_.contains("measure"))
        out_["measure"] = "dot(gamma, inverse(body_inertia + body_mass*body_radius^2*dot(gamma, gamma)*"
                          "identity())*gamma)^(-1/2)";
    }
    define("v", "-cross(omega, r)");
    frameEquations(eq);
    eq["s_plane"] = "sqrt(dot(alpha, dr)^2 + dot(beta, dr)^2)";
    eq["s_body"] = "norm(dr)";
    out_["complete"]["s_plane"] = "0";
    out_["complete"]["s_body"] = "0";
    energy_ =
        contact_ == Contact::Marble ? "dot(M, omega)/2 + potential" : "dot(omega, A*omega)/2 + potential";
  }

  /// Rubber rolling about the contact: omega normal to gamma by construction, the couple lambda gamma keeps
  /// M = A omega (Borisov, Mamaev & Bizyaev 2013), lambda from d/dt (omega, gamma) = 0. On the plane
  /// (omega, gamma') = (omega, gamma x omega) = 0; on a curved support gamma' turns with the support too
  /// (`curved`), and that term stays.
  void rubber(const std::string& forces, bool curved) {
    define("omega_free", "inverse(A)*M");
    define("A_gamma", "inverse(A)*gamma");
    define("omega", "omega_free - (dot(gamma, omega_free)/dot(gamma, A_gamma))*A_gamma");
    define("dM_free", "cross(A*omega" + gyrostat() + ", omega) + " + forces);
    define("dA_omega", "body_mass*(2*dot(r, dr)*omega - dot(r, omega)*dr - dot(dr, omega)*r)");
    define("spin_couple", "-(dot(A_gamma, dM_free - dA_omega)" +
                              std::string(curved ? " + dot(omega, dgamma)" : "") + ")/dot(gamma, A_gamma)");
    // A omega = M - spin_gauge*gamma: the part of M along gamma that the projection removes turns with gamma
    define("spin_gauge", "dot(gamma, omega_free)/dot(gamma, A_gamma)");
    out_["equations"]["M"] = "dM_free + spin_couple*gamma + spin_gauge*dgamma";
  }

  void sliding() {
    ordered_json state = ordered_json::array(), vectors;
    if (implicit_)
      addVectors(state, vectors, {"omega", "v", "gamma", "contact", "alpha", "beta"});
    else
      addVectors(state, vectors, {"omega", "v", "gamma", "alpha", "beta"});
    for (const char* n : {"x", "y"})
      state.push_back(n);
    out_["state"] = state;
    out_["vectors"] = vectors;
    common();
    slipVelocity();
    slidingForces("gamma", "leaves_the_plane");
    frameEquations(out_["equations"]);
    energy_ = kSlidingEnergy;
  }

  /// The velocity of the body's point at the contact (v the centre of mass's, body axes) and its part
  /// along the support (the normal part is kept zero by the normal force); a start that gives no velocity
  /// rolls: the contact at rest.
  void slipVelocity() {
    define("v_contact", "v + cross(omega, r)");
    define("v_slip", "v_contact - dot(v_contact, gamma)*gamma");
    for (int i = 1; i <= 3; ++i)
      out_["complete"]["v" + std::to_string(i)] = "-cross(omega, r)[" + std::to_string(i) + "]";
  }

  /// Newton-Euler for a body sliding with viscous friction F = -mu v_slip at the contact, under gravity
  /// along -`vertical` (body axes): the normal force N gamma from d/dt (v_contact, gamma) = 0 with the
  /// contact's rates dr and dgamma (the support's turning is in them); where N would turn negative the
  /// body leaves the support and the run stops, naming `leaves`.
  void slidingForces(const std::string& vertical, const std::string& leaves) {
    const bool curved = vertical != "gamma"; // on a curved support U(vertical, x) has a force too
    define("friction_force", "-friction_mu*v_slip");
    define("L", "body_inertia*omega" + gyrostat());
    define("I_inverse", "inverse(body_inertia)");
    define("omega_free",
           "I_inverse*(cross(r, friction_force) - cross(omega, L)" +
               (curved ? std::string(potential_ ? " + potential_couple" : "") : potentialTorque()) + ")");
    define("v_free", "friction_force/body_mass - gravity_g*" + vertical + " - cross(omega, v)" +
                         (curved && potential_ ? " + potential_force/body_mass" : ""));
    define("omega_per_N", "I_inverse*cross(r, gamma)");
    define("normal_force", "-(dot(v_free + cross(omega_free, r) + cross(omega, dr), gamma) + "
                           "dot(v_contact, dgamma))/(1/body_mass + dot(omega_per_N, cross(r, gamma)))");
    ordered_json& eq = out_["equations"];
    eq["omega"] = "omega_free + normal_force*omega_per_N";
    // where the support would have to pull (N < 0) the body leaves it: the model no longer holds, so the
    // run stops there (a non-finite rate, named after this definition)
    define(leaves, "(1 - max(0, sign(normal_force)))/max(0, sign(normal_force))");
    eq["v"] = "v_free + (normal_force/body_mass + " + leaves + ")*gamma";
  }

  /// A balanced ball (central moment mu, D = m R^2) rolling without slipping on a fixed surface, in the
  /// fixed frame (Borisov & Mamaev 2002; manual section 3.3, (11)-(14)): gamma the unit normal at the contact
  /// towards the centre, x the centre on the surface parallel to the support, M = mu w + D g x (w x g),
  /// x' = R w x g, M' = D g' x (w x g) + R g x F (F the force on the centre), q' = (0, w) q / 2; g' from x'
  /// through the centre surface's Gauss map, inverse(dx/dgamma + gamma gamma^T) x' (exact, by jacobian()).
  void ballOnSupport() {
    const bool graph = support_ == "graph";
    if (graph && !doc_.contains("section")) out_["section"] = "x1";
    ordered_json state = ordered_json::array(), vectors;
    addVectors(state, vectors, {"M"});
    if (graph) {
      state.push_back("x1");
      state.push_back("x2");
    } else {
      addVectors(state, vectors, {"gamma"});
    }
    for (const char* n : {"q0", "q1", "q2", "q3", "s_surface", "s_ball"})
      state.push_back(n);
    out_["state"] = state;
    out_["vectors"] = vectors;
    define("ball_D", "body_mass*body_radius^2");
    if (graph) {
      define("height_slope", "gradient(support_height, [x1, x2])");
      define("gamma", "normalize([-height_slope[1], -height_slope[2], 1])");
      define("x", "[x1, x2, support_height]");
    } else {
      define("centre_surface", // the centre lies R along the normal from the contact, on either side
             centreSurface_ ? supportContact_ : supportContact_ + " + body_radius*gamma");
      define("x", "centre_surface");
    }
    const std::string omegaOfM = "(M + (ball_D/body_inertia)*dot(gamma, M)*gamma)/(body_inertia + ball_D)";
    if (contact_ == Contact::Rubber) { // omega normal to gamma (A^-1 gamma = gamma/mu): as on the plane
      define("omega_free", omegaOfM);
      define("omega", "omega_free - dot(gamma, omega_free)*gamma");
      define("spin_gauge", "body_inertia*dot(gamma, omega_free)");
    } else {
      define("omega", omegaOfM);
    }
    define("dx", "body_radius*cross(omega, gamma)");
    define("dgamma", graph ? "derivative(gamma, [x1, x2], [dx[1], dx[2]])"
                           : "inverse(jacobian(centre_surface, gamma) + outer(gamma, gamma))*dx");
    define("force", "-body_mass*gravity_g*[0, 0, 1]" +
                        std::string(potential_ ? " - gradient(potential_U, [x[1], x[2], x[3]])" : ""));
    define("potential", "body_mass*gravity_g*x[3]" + std::string(potential_ ? " + potential_U" : ""));
    define("rotation", kRotation);
    ordered_json& eq = out_["equations"];
    const std::string rolling =
        "ball_D*cross(dgamma, cross(omega, gamma)) + body_radius*cross(gamma, force)"; // M' of a marble ball
    if (contact_ == Contact::Rubber) { // the couple lambda gamma keeps (omega, gamma) = 0
      define("dM_free", rolling);
      define("spin_couple", "-dot(gamma, dM_free) - (ball_D + body_inertia)*dot(dgamma, omega)");
      eq["M"] = "dM_free + spin_couple*gamma + spin_gauge*dgamma";
    } else {
      eq["M"] = rolling;
    }
    if (graph) {
      eq["x1"] = "dx[1]";
      eq["x2"] = "dx[2]";
    } else {
      eq["gamma"] = "dgamma";
    }
    eq["q0"] = "-(omega[1]*q1 + omega[2]*q2 + omega[3]*q3)/2";
    eq["q1"] = "(omega[1]*q0 + omega[2]*q3 - omega[3]*q2)/2";
    eq["q2"] = "(omega[2]*q0 + omega[3]*q1 - omega[1]*q3)/2";
    eq["q3"] = "(omega[3]*q0 + omega[1]*q2 - omega[2]*q1)/2";
    eq["s_surface"] = "norm(dx - body_radius*dgamma)";
    eq["s_ball"] = "body_radius*norm(dgamma - cross(omega, gamma))";
    ordered_json& c = out_["complete"];
    c["q0"] = "1";
    for (const char* n : {"q1", "q2", "q3", "s_surface", "s_ball"})
      c[n] = "0";
    energy_ = "dot(M, omega)/2 + potential";
  }

  /// The value of a generated definition at the parameter values `p`, when it depends on parameters and
  /// definitions only (nothing otherwise: a name of the state, an error).
  std::optional<Eigen::MatrixXd> valueAt(const std::string& name,
                                         const std::map<std::string, double>& p) const {
    expr::Graph graph;
    std::set<std::string> open; // the definitions being lowered (a circle is an error, reported elsewhere)
    std::function<std::optional<expr::Value>(const std::string&, int)> resolve =
        [&](const std::string& n, int) -> std::optional<expr::Value> {
      if (const auto it = p.find(n); it != p.end()) return expr::Value::of(graph.constant(it->second));
      const json& defs = out_["definitions"];
      if (!defs.contains(n) || !defs[n].is_string() || !open.insert(n).second) return std::nullopt;
      const expr::Expression e = expr::parse(defs[n].get<std::string>());
      const expr::Value v = expr::Lowering(graph, resolve, {}).lower(e);
      open.erase(n);
      return v;
    };
    try {
      const std::optional<expr::Value> v = resolve(name, 1);
      if (!v) return std::nullopt;
      const expr::Program program(graph, v->n);
      Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> out(v->rows, v->cols);
      const double none = 0;
      program.evaluate(&none, out.data());
      return out;
    } catch (const InputError&) {
      return std::nullopt;
    }
  }

  /// Whether the body is symmetric about its `axis` as Jellett's integral needs: its inertia tensor (about
  /// the centre of mass) has the axis as a principal axis and equal moments across it, and the centre of mass
  /// lies on the axis (the sphere is a body of revolution about any axis through its centre) -- for every
  /// value of the parameters, so checked at the defaults and at two generic perturbations of them.
  bool symmetricAboutTheAxis() const {
    std::map<std::string, double> defaults;
    if (doc_.contains("parameters") && doc_["parameters"].is_object())
      for (const auto& [name, value] : doc_["parameters"].items()) {
        if (value.is_number())
          defaults[name] = value.get<double>();
        else if (value.is_object() && value.contains("default") && value["default"].is_number())
          defaults[name] = value["default"].get<double>();
      }
    for (int sample = 0; sample < 3; ++sample) {
      std::map<std::string, double> p = defaults;
      double k = 0;
      for (auto& [name, value] : p) { // generic values: each moved by its own irrational factor
        value = value * (1 + 0.1 * sample * std::sqrt(2 + k)) + 0.01 * sample * std::sqrt(5 + k);
        ++k;
      }
      const auto I = valueAt("body_inertia", p), axis = valueAt("body_axis", p),
                 centre = valueAt("body_centre", p);
      if (!I || !axis || !centre || I->rows() != 3 || I->cols() != 3 || axis->size() != 3 ||
          centre->size() != 3 || !(axis->norm() > 0))
        return false;
      const Eigen::Vector3d a = Eigen::Map<const Eigen::Vector3d>(axis->data()).normalized(),
                            c = Eigen::Map<const Eigen::Vector3d>(centre->data());
      const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - a * a.transpose(), PIP = P * *I * P;
      const double tolerance = 1e-12 * (1 + I->norm());
      if ((P * *I * a).norm() > tolerance || (PIP - (PIP.trace() / 2) * P).norm() > tolerance ||
          (P * c).norm() > 1e-12 * (1 + c.norm()))
        return false;
    }
    return true;
  }

  /// Any body rolling without slipping (marble, or rubber: rubber() with the support's turning of gamma) on
  /// a fixed curved support, in body axes (docs/rolling.md, "A body on
  /// a curved support"). gamma is the support's unit normal at the contact, pointing into the body, in body
  /// axes, so the body's contact point is its s(gamma) as on the plane; q0..q3 the body's orientation, N =
  /// rotation gamma the normal in fixed axes and sigma(N) the support's point there. The contact is at rest:
  /// v = -omega x r, and the angular momentum about it, M = A omega, obeys the plane's equation (its
  /// derivation uses v = -omega x r alone, not how r changes): M' = (M + k) x omega + m r' x (omega x r) +
  /// m g r x e, e the upward vertical in body axes. The contact moves on both surfaces alike, sigma'(N) N' =
  /// rotation r' (no slip), so with S = ds/dgamma and Sigma = rotation^T sigma'(N) rotation (the inverse
  /// shape operators; their sum is the relative curvature's inverse) and gamma' = N'_body + gamma x omega:
  /// (Sigma - S) N'_body = S (gamma x omega) on the tangent plane (D. J. Montana, The kinematics of contact
  /// and grasp, Int. J. Robotics Research 7(3) (1988) 17-32; Ju. I. Neimark, N. A. Fufaev, Dynamics of
  /// Nonholonomic Systems (1972) ch. III). A balanced ball is the fixed-frame ballOnSupport(), which this
  /// reproduces; a support of radius a -> infinity gives the plane.
  void bodyOnSupport() {
    const bool sliding = contact_ == Contact::Sliding;
    ordered_json state = ordered_json::array(), vectors;
    std::vector<const char*> vectorStates =
        sliding ? std::vector<const char*>{"omega", "v", "gamma"} : std::vector<const char*>{"M", "gamma"};
    if (implicit_) vectorStates.push_back("contact");
    addVectors(state, vectors, vectorStates);
    for (const char* n : {"q0", "q1", "q2", "q3"})
      state.push_back(n);
    if (supportImplicit_) addVectors(state, vectors, {"support_contact"});
    out_["state"] = state;
    out_["vectors"] = vectors;
    if (implicit_) implicitContact();
    define("contact_s", shapeContact_);
    define("r", "contact_s + body_centre");
    define("rotation", kRotation);
    define("N", "rotation*gamma");
    // with a potential U(vertical, x), vertical gets nodes of its own (normalized: the same value to
    // rounding), so that U's partial derivatives in vertical and in x are taken apart (the derivatives are
    // partial through the graph's nodes, and x = sigma(N) - rotation r holds rotation's third row, which
    // transpose(rotation)*[0, 0, 1] is)
    define("vertical",
           potential_ ? "normalize(transpose(rotation)*[0, 0, 1])" : "transpose(rotation)*[0, 0, 1]");
    if (supportImplicit_)
      implicitSupportContact();
    else
      define("support_point", expr::renamed(expr::parse(supportContact_), {{"gamma", "N"}}));
    if (!sliding) define("A", "body_inertia + body_mass*(dot(r, r)*identity() - outer(r, r))");
    if (contact_ == Contact::Marble) define("omega", "inverse(A)*M");
    define("tangent", "identity() - outer(gamma, gamma)");
    define("body_turning", "tangent*jacobian(r, gamma)*tangent");                                    // S
    define("support_turning", "tangent*transpose(rotation)*jacobian(support_point, gamma)*tangent"); // Sigma
    define("relative_turning", "support_turning - body_turning + outer(gamma, gamma)");
    // sliding, the contact moves on the support by the slip too: (Sigma - S) N' = S (gamma x omega) + v_slip
    if (sliding) slipVelocity();
    define("dN", "inverse(relative_turning)*(body_turning*cross(gamma, omega)" +
                     std::string(sliding ? " + v_slip" : "") + ")");
    // the body touches at one point while the relative curvature is definite there (on a convex support
    // always; in a bowl while the body is more curved than the bowl both ways): det > 0 on the tangent
    // plane. Towards det = 0 it comes to touch along a curve (the contact's rate grows without bound) and
    // past it would cut into the bowl: the run stops once one principal value is 1e-4 of the other
    // (det < 1e-4 trace^2 on the tangent plane), naming this
    guard("flatter_than_the_support", "det(relative_turning) - 1e-4*(trace(relative_turning) - 1)^2");
    define("dgamma", "dN + cross(gamma, omega) + [0, 0, flatter_than_the_support]");
    define("dr", "derivative(r, gamma, dgamma)");
    define("x", "support_point - rotation*r"); // the centre of mass, fixed axes
    define("potential", "body_mass*gravity_g*x[3]" + std::string(potential_ ? " + potential_U" : ""));
    ordered_json& eq = out_["equations"];
    // an extra potential U(vertical, x): its force -dU/dx at the centre of mass, its couple
    // vertical x dU/dvertical (the plane's gamma x dU/dgamma); about the contact, -r x force
    if (potential_) {
      define("potential_force", "-transpose(rotation)*gradient(potential_U, x)");
      define("potential_couple", "cross(vertical, gradient(potential_U, vertical))");
    }
    const std::string forces =
        "body_mass*cross(dr, cross(omega, r)) + body_mass*gravity_g*cross(r, vertical)" +
        std::string(potential_ ? " - cross(r, potential_force) + potential_couple" : "");
    if (contact_ == Contact::Marble)
      eq["M"] = "cross(M" + gyrostat() + ", omega) + " + forces;
    else if (contact_ == Contact::Rubber)
      rubber(forces, true);
    else
      slidingForces("vertical", "leaves_the_support");
    eq["gamma"] = "dgamma";
    // the support's contact moves by its inverse shape operator: sigma'(N) N', N' = rotation dN
    if (supportImplicit_) eq["support_contact"] = "jacobian(support_point, gamma)*dN";
    eq["q0"] = "-(q1*omega[1] + q2*omega[2] + q3*omega[3])/2"; // q' = q (0, omega)/2, omega in body axes
    eq["q1"] = "(q0*omega[1] + q2*omega[3] - q3*omega[2])/2";
    eq["q2"] = "(q0*omega[2] + q3*omega[1] - q1*omega[3])/2";
    eq["q3"] = "(q0*omega[3] + q1*omega[2] - q2*omega[1])/2";
    // a start that gives no orientation turns gamma to the fixed vertical: the body on top of a sphere or
    // ellipsoid, at the bottom of a bowl
    define("q_start", "normalize([1 + normalize(gamma)[3], normalize(gamma)[2], -normalize(gamma)[1], 0])");
    for (int i = 0; i < 4; ++i)
      out_["complete"]["q" + std::to_string(i)] = "q_start[" + std::to_string(i + 1) + "]";
    if (supportImplicit_) completeSupportContact();
    energy_ = contact_ == Contact::Marble   ? "dot(M, omega)/2 + potential"
              : contact_ == Contact::Rubber ? "dot(omega, A*omega)/2 + potential"
                                            : kSlidingEnergy;
  }

  /// The spin about the normal gamma (an integral in rubber rolling), an implicit body's contact drift and
  /// the body's axis against the upward vertical (`vertical` in body axes), where there is one.
  void contactObservables(ordered_json& o, const std::string& vertical) const {
    o["spin_normal"] = {{"value", "dot(omega, gamma)"},
                        {"description", "spin about the normal at the contact (zero in rubber rolling)"}};
    if (contact_ == Contact::Rubber) o["spin_normal"]["integral"] = true;
    if (implicit_)
      o["contact_drift"] = {{"value", "norm(contact - contact_s)"},
                            {"description",
                             "how far the contact carried in the state is from the one solved for "
                             "(Newton's method corrects it at every step)"}};
    if (axis_)
      o["axis_up"] = {{"value", "dot(" + vertical + ", normalize(body_axis))"},
                      {"description", "cosine between the body's axis and the upward vertical"}};
  }

  void planeObservables(ordered_json& o) const {
    const bool conservative = contact_ != Contact::Sliding;
    o["E"] = {{"value", energy_},
              {"description", conservative ? "energy" : "energy (friction at the contact dissipates it)"}};
    if (conservative) o["E"]["integral"] = true;
    o["geometric"] = {
        {"value", "dot(gamma, gamma)"}, {"description", "geometric integral"}, {"integral", true}};
    if (contact_ != Contact::Sliding)
      for (int i = 1; i <= 3; ++i)
        o["omega" + std::to_string(i)] = {
            {"value", "omega[" + std::to_string(i) + "]"},
            {"description", "angular velocity, body axis " + std::to_string(i)}};
    o["Z"] = {{"value", "-dot(r, gamma)"}, {"description", "height of the centre of mass above the plane"}};
    contactObservables(o, "gamma");
    if (shape_ == "sphere") { // Jellett (1872): (L, r) for a sphere whose centre of mass is on its axis
      o["jellett"] = {{"value", "dot(body_inertia*omega" + gyrostat() + ", r)"},
                      {"description",
                       "Jellett's quantity (L, r): L about the centre of mass, r to the contact; "
                       "an integral for an axisymmetric body with its centre of mass on the axis"}};
      // an integral only where its proof holds: otherwise it stays an observable to watch
      if (axis_ && !gyrostat_ && !potential_ && contact_ != Contact::Rubber && symmetricAboutTheAxis())
        o["jellett"]["integral"] = true;
    }
    if (contact_ == Contact::Sliding) slidingObservables(o, "the plane's normal reaction");
  }

  static void slidingObservables(ordered_json& o, const std::string& reaction) {
    o["normal_force"] = {{"value", "normal_force"}, {"description", reaction}};
    o["slip"] = {{"value", "norm(v_slip)"}, {"description", "speed of the contact point along the support"}};
  }

  void observables() {
    ordered_json o;
    if (!support_.empty() && !balancedBall_) { // any other body on a curved support
      const bool sliding = contact_ == Contact::Sliding;
      o["E"] = {{"value", energy_},
                {"description", sliding ? "energy (friction at the contact dissipates it)" : "energy"}};
      if (!sliding) o["E"]["integral"] = true;
      o["geometric"] = {
          {"value", "dot(gamma, gamma)"}, {"description", "geometric integral"}, {"integral", true}};
      for (int i = 1; i <= 3; ++i) {
        const std::string k = std::to_string(i);
        if (!sliding) // sliding, omega is the state
          o["omega" + k] = {{"value", "omega[" + k + "]"},
                            {"description", "angular velocity, body axis " + k}};
        o["x" + k] = {{"value", "x[" + k + "]"}, {"description", "centre of mass, fixed axis " + k}};
      }
      if (sliding) slidingObservables(o, "the support's normal reaction");
      o["orientation"] = {{"value", "q0^2 + q1^2 + q2^2 + q3^2"},
                          {"description", "the orientation quaternion's squared norm"},
                          {"integral", true}};
      contactObservables(o, "vertical");
      if (supportImplicit_)
        o["support_drift"] = {{"value", "norm(support_contact - support_point)"},
                              {"description",
                               "how far the support's contact carried in the state is from the one solved "
                               "for (Newton's method corrects it at every step)"}};
    } else if (!support_.empty()) { // a ball on a curved support
      o["E"] = {{"value", energy_}, {"description", "energy"}, {"integral", true}};
      if (support_ != "graph")
        o["geometric"] = {
            {"value", "dot(gamma, gamma)"}, {"description", "geometric integral"}, {"integral", true}};
      for (int i = 1; i <= 3; ++i) {
        const std::string k = std::to_string(i);
        o["omega" + k] = {{"value", "omega[" + k + "]"},
                          {"description", "angular velocity, fixed axis " + k}};
        if (support_ != "graph" || i == 3)
          o["x" + k] = {{"value", "x[" + k + "]"}, {"description", "centre of the ball, fixed axis " + k}};
      }
      o["spin_normal"] = {{"value", "dot(omega, gamma)"},
                          {"description", "spin about the normal at the contact"}};
      if (contact_ == Contact::Rubber) o["spin_normal"]["integral"] = true;
    } else {
      planeObservables(o);
    }
    if (doc_.contains("observables")) {
      const ordered_json user = source("observables");
      if (!user.is_object()) (root_ / "observables").fail("expected an object of observables");
      for (const auto& [name, value] : user.items())
        o[name] = value; // a user's observable of a generated name replaces it
    }
    out_["observables"] = o;
    if (doc_.contains("complete")) {
      const ordered_json user = source("complete");
      if (!user.is_object()) (root_ / "complete").fail("expected an object of expressions");
      for (const auto& [name, value] : user.items())
        out_["complete"][name] = value;
    }
  }

  void view() {
    ordered_json v = shapeView_;
    v["centre"] = "body_centre";
    if (support_.empty()) {
      v["rotation"] = "rows(alpha, beta, gamma)";
      v["position"] = "[x, y, -dot(r, gamma)]";
      v["contact"] = "[x, y, -dot(r, gamma)] + rows(alpha, beta, gamma)*r";
    } else if (!balancedBall_) {
      v["rotation"] = "rotation";
      v["position"] = "x";
      v["contact"] = "support_point";
      if (!supportView_.is_null()) v["support"] = supportView_;
      if (supportImplicit_) v["normal"] = "N"; // the trace lifted off it: no shape to take its normal from
    } else {
      v["rotation"] = "rotation";
      v["position"] = "x";
      v["contact"] = "x - body_radius*gamma";
      if (!supportView_
               .is_null()) { // the support itself; sizes of the centre's surface drawn less the radius
        ordered_json s = supportView_;
        if (centreSurface_ && support_ == "sphere")
          s["radius"] = inside_ ? "support_radius + body_radius" : "support_radius - body_radius";
        if (centreSurface_ && support_ == "ellipsoid")
          s["semi_axes"] =
              std::string("support_semi_axes ") + (inside_ ? "+" : "-") + " body_radius*[1, 1, 1]";
        v["support"] = s;
      }
    }
    if (doc_.contains("view")) {
      const ordered_json user = source("view");
      if (!user.is_object()) (root_ / "view").fail("expected an object");
      for (const auto& [name, value] : user.items())
        v[name] = value;
    }
    out_["view"] = v;
  }

  const json& doc_;
  const ordered_json* ordered_;
  Where root_;
  ordered_json out_;
  std::vector<std::pair<std::string, std::string>> origins_;
  std::map<std::string, RequiredShape> shapes_;
  std::set<std::string> generated_;
  std::map<std::string, Where> userNamed_; ///< the user's parameters and definitions, where each is given
  Contact contact_ = Contact::Marble;
  std::string shape_, shapeContact_, energy_;
  ordered_json shapeView_;
  bool potential_ = false, gyrostat_ = false, axis_ = false;
  bool centred_ =
      false; ///< the body gives its shape's centre (else the centre of mass is the shape's origin)
  std::optional<expr::Expression> implicit_;        ///< an implicit body's F
  std::optional<expr::Expression> implicitStart_;   ///< F for the first contact's Newton steps and the view
  std::optional<expr::Expression> supportImplicit_; ///< an implicit support's F (fixed axes)
  std::string contactGuess_ = "-body_size*normalize(gamma)"; ///< where the first contact's steps begin
  std::string support_, supportContact_; ///< a curved support ("" for the plane), its inverse Gauss map
  ordered_json supportView_;
  bool centreSurface_ = false, inside_ = false;
  bool balancedBall_ = false; ///< a sphere with no centre, gyrostat or principal axes and one moment
};

} // namespace

RollingEquations rollingEquations(const json& doc, const ordered_json* ordered, const std::string& source) {
  return Generator(doc, ordered, source).run();
}

namespace {
/// What a form describes, for its title: "a superellipsoid rolling in a spherical bowl".
std::string formTitle(const RollingBodyForm& f) {
  const std::string body = f.shape == "revolution" ? "body of revolution"
                           : f.shape == "implicit" ? "body given by its surface"
                                                   : f.shape;
  const std::string on = f.support == "sphere"       ? (f.inside ? "in a spherical bowl" : "on a sphere")
                         : f.support == "ellipsoid"  ? (f.inside ? "in an ellipsoid bowl" : "on an ellipsoid")
                         : f.support == "paraboloid" ? "in a paraboloid bowl"
                         : f.support == "implicit"   ? "on a support given by its surface"
                                                     : "on a plane";
  const bool vowel = std::string("aeiou").find(body.front()) != std::string::npos;
  return (vowel ? "An " : "A ") + body + " rolling " + on + " (File > New rolling body)";
}

/// A form that makes no model, refused before it is written, naming the form's field.
void checkForm(const RollingBodyForm& f) {
  const auto fail = [](const std::string& field, const std::string& what) {
    throw InputError("the form's " + field + ": " + what);
  };
  if (f.support != "plane" && f.support != "sphere" && f.support != "ellipsoid" &&
      f.support != "paraboloid" && f.support != "implicit")
    fail("support", "expected plane, sphere, ellipsoid, paraboloid or implicit, not \"" + f.support + "\"");
  if (f.shape == "superellipsoid" && f.exponent < 2)
    fail("exponent", "a superellipsoid's exponent is at least 2 (below 2 it has edges of infinite "
                     "curvature)");
  if (f.shape == "superellipsoid" && f.exponent > 2 && f.bulge <= 0)
    fail("bulge", "a superellipsoid with an exponent above 2 needs a bulge > 0 (e.g. 0.05): without it its "
                  "faces are flat along their mid-lines, where it cannot roll");
  if (f.shape == "revolution" && !(f.heights[0] < f.heights[1]))
    fail("heights", "the profile's bottom must lie below its top");
}
} // namespace

ordered_json rollingModelDocument(const RollingBodyForm& f) {
  checkForm(f);
  ordered_json doc;
  doc["kind"] = "rolling";
  doc["id"] = f.id;
  doc["title"] = f.title.empty() ? formTitle(f) : f.title;
  doc["parameters"] =
      ordered_json::object(); // filled last: a reference into doc would not outlive its growth
  ordered_json p;
  const auto parameter = [&](const std::string& id, double value, const std::string& what, bool positive) {
    p[id] = {{"default", value}, {"description", what}};
    if (positive) p[id]["min"] = 0;
    return id;
  };
  // "[NAME1, NAME2, NAME3]", three parameters, each described as `what` and its index
  const auto triple = [&](const std::string& name, const std::array<double, 3>& values,
                          const std::string& what) {
    std::string v;
    for (int i = 0; i < 3; ++i)
      v += (i ? ", " : "") + parameter(name + std::to_string(i + 1), values[static_cast<std::size_t>(i)],
                                       what + " " + std::to_string(i + 1), true);
    return "[" + v + "]";
  };
  ordered_json body;
  body["shape"] = f.shape;
  if (f.shape == "sphere" || f.shape == "disk") {
    body["radius"] = parameter("R", f.sizes[0], "radius", true);
  } else if (f.shape == "ellipsoid" || f.shape == "superellipsoid") {
    body["semi_axes"] = triple("b", f.sizes, "semi-axis along body axis");
    if (f.shape == "superellipsoid") {
      body["exponent"] = parameter(
          "p", f.exponent, "exponent: 2 is the ellipsoid, larger flattens the faces towards a box's", true);
      p["p"]["min"] = 2;
      body["bulge"] = parameter(
          "bulge", f.bulge,
          "weight of the ellipsoid through the same vertices that keeps the faces curved (> 0 when p > 2)",
          true);
    }
  } else if (f.shape == "paraboloid") {
    body["p"] = parameter("p", f.sizes[0], "radius of curvature at the vertex along body axis 1", true);
    body["q"] = parameter("q", f.sizes[1], "radius of curvature at the vertex along body axis 2", true);
  } else if (f.shape == "revolution") {
    body[f.profileSquared ? "profile_squared" : "profile"] = f.profile;
    body["heights"] =
        "[" + parameter("z_bottom", f.heights[0], "the profile's bottom on body axis 3", false) + ", " +
        parameter("z_top", f.heights[1], "the profile's top on body axis 3", false) + "]";
  } else if (f.shape == "implicit") {
    body["F"] = f.surface;
    body["size"] = f.size;
  }
  // a body symmetric about axis 3 says so in its description (one moment across the axis, the centre on
  // it), so that it stays symmetric whatever the parameters -- what Jellett's integral needs
  const bool onTheAxis = f.symmetryAxis && f.centre[0] == 0 && f.centre[1] == 0;
  const bool equalMoments = f.symmetryAxis && f.inertia[0] == f.inertia[1];
  std::string centre;
  for (int i = 0; i < 3; ++i)
    centre +=
        (i ? ", " : "") + (onTheAxis && i < 2
                               ? std::string("0")
                               : parameter("c" + std::to_string(i + 1), f.centre[static_cast<std::size_t>(i)],
                                           "the shape's centre seen from the centre of mass, body axis " +
                                               std::to_string(i + 1),
                                           false));
  body["centre"] = "[" + centre + "]";
  body["mass"] = parameter("m", f.mass, "mass", true);
  body["inertia"] = ordered_json::array();
  for (int i = 0; i < 3; ++i)
    body["inertia"].push_back(
        equalMoments && i == 1
            ? std::string("I1")
            : parameter("I" + std::to_string(i + 1), f.inertia[static_cast<std::size_t>(i)],
                        equalMoments && i == 0
                            ? std::string("central moment of inertia across the axis (body "
                                          "axes 1 and 2)")
                            : "central principal moment of inertia, body axis " + std::to_string(i + 1),
                        true));
  if (f.symmetryAxis) body["axis"] = "[0, 0, 1]";
  doc["body"] = body;
  if (f.support != "plane") { // fixed, so its sizes are along the fixed axes
    ordered_json support{{"surface", f.support}};
    if (f.support == "sphere") {
      support["radius"] = parameter("a", f.supportSizes[0],
                                    f.inside ? "radius of the spherical bowl" : "radius of the sphere", true);
      support["side"] = f.inside ? "inside" : "outside";
    } else if (f.support == "ellipsoid") {
      support["semi_axes"] = triple("a", f.supportSizes, "semi-axis of the ellipsoid along fixed axis");
      support["side"] = f.inside ? "inside" : "outside";
    } else if (f.support == "implicit") {
      support["F"] = f.supportSurface;
      support["size"] =
          parameter("extent", f.supportSizes[0],
                    "a length that bounds the part of the support drawn about the origin", true);
    } else {
      support["p"] = parameter("bowl_p", f.supportSizes[0],
                               "the bowl's radius of curvature at its bottom along fixed axis 1", true);
      support["q"] = parameter("bowl_q", f.supportSizes[1],
                               "the bowl's radius of curvature at its bottom along fixed axis 2", true);
    }
    doc["support"] = support;
  }
  doc["gravity"] = parameter("g", f.gravity, "acceleration of gravity", true);
  doc["contact"] = f.contact;
  if (f.contact == "sliding")
    doc["friction"] = parameter("mu", f.friction, "viscous friction at the contact", true);
  // a start tilted from rest, spinning about body axis 3 (a disk stands on its edge); on a curved support
  // the orientation is completed from gamma (bodyOnSupport's q_start): on top of the sphere or ellipsoid, at
  // the bottom of the bowl. A sliding sphere spins fast, as a tippe top must to turn over; any other sliding
  // body at 2 (faster, a long body's contact sweeps round so fast that the plane would have to pull it)
  const double tilt = 0.2;
  const std::array<double, 3> gamma = f.shape == "disk"
                                          ? std::array<double, 3>{0, std::cos(tilt), std::sin(tilt)}
                                          : std::array<double, 3>{std::sin(tilt), 0, std::cos(tilt)};
  ordered_json start;
  const char* spin = f.contact == "sliding" ? "omega" : "M";
  const double spinValue = f.contact != "sliding" ? 2.0 * f.inertia[2] : f.shape == "sphere" ? 5.0 : 2.0;
  for (int i = 0; i < 3; ++i)
    start[spin + std::to_string(i + 1)] = i == 2 ? spinValue : 0.0;
  for (int i = 0; i < 3; ++i)
    start["gamma" + std::to_string(i + 1)] = gamma[static_cast<std::size_t>(i)];
  doc["initial"] = {{"state", start}};
  doc["parameters"] = p;
  return doc;
}

} // namespace rv
