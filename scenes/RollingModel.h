// RollingModel.h -- a rolling body described by its geometry (a model file of "kind": "rolling",
// docs/rolling.md): its surface, centre of mass, mass, inertia tensor, an optional gyrostat and potential,
// the support and the contact (marble, rubber, sliding). rollviz derives the equations of motion from it and
// writes them as an ordinary equation model (docs/models.md), so the expression graph, its exact derivatives,
// native compilation, every tool and the 3D view work on it as on a model written by hand: a new body is
// data, not another translation unit.
//
// The derivation (written out in docs/rolling.md). Body axes; gamma is the upward vertical, so the body's
// outward normal at the contact is -gamma and the contact point s(gamma) is the inverse Gauss map of the
// surface (closed form for the named shapes); r = s + centre is the contact relative to the centre of mass
// and r' = (dr/dgamma) gamma' its rate, taken exactly by derivative() (expr/Derivative.h). A surface with no
// closed form -- implicit F(x, y, z) = 0, a superellipsoid (A. H. Barr, Superquadrics and angle-preserving
// transformations, IEEE Computer Graphics and Applications 1 (1981) 11-23) made strictly convex by a bulge,
// a body of revolution by its profile rho(z) -- carries its contact in the state and takes one Newton step
// per evaluation onto F = 0 with the normal turned to -gamma through the shape operator.
//  - marble (no slip): M = A omega, A = I + m (|r|^2 E - r r^T) (the angular momentum about the contact),
//    M' = (M + k) x omega + m r' x (omega x r) + m g r x gamma + gamma x dU/dgamma, gamma' = gamma x omega
//    (A. V. Borisov, I. S. Mamaev, Rolling of a rigid body on a plane and sphere. Hierarchy of dynamics,
//    Regul. Chaotic Dyn. 7 (2002) 177-200, eq. (2.1)-(2.5)); the five built-in rolling problems are cases.
//  - rubber (no slip, no spin about the normal): the same with the reaction couple lambda gamma, lambda from
//    d/dt (omega, gamma) = 0 and omega kept normal to gamma by construction (A. V. Borisov, I. S. Mamaev,
//    I. A. Bizyaev, The hierarchy of dynamics of a rigid body rolling without slipping and spinning on a
//    plane and a sphere, Nelin. Dinam. 9 (2013) 141-202, section 2).
//  - sliding with viscous friction F = -mu v_P (the contact's velocity along the plane): Newton-Euler for
//    omega and the centre of mass's velocity v in body axes, the normal force N from d/dt (v_P, gamma) = 0
//    (the contact stays on the plane): the classical smooth tippe top (N. M. Bou-Rabee, J. E. Marsden,
//    L. A. Romero, Tippe top inversion as a dissipation-induced instability, SIAM J. Appl. Dyn. Syst. 3
//    (2004) 352-377; S. Rauch-Wojciechowski, N. Rutstam, SIGMA 10 (2014) 017).
//  - on a curved support: a balanced ball in the fixed frame (the manual's section 3.3); any other body in
//    body axes, marble or rubber: gamma the support's normal at the contact (into the body), q the
//    orientation, the plane's M' with the vertical e = Q^T e3 (its derivation uses only that the contact is
//    at rest), and the contact's motion from the relative curvature, (Sigma - S) N' = S (gamma x omega) with
//    S, Sigma the inverse shape operators of body and support (D. J. Montana, The kinematics of contact and
//    grasp, Int. J. Robotics Research 7(3) (1988) 17-32; Ju. I. Neimark, N. A. Fufaev, Dynamics of
//    Nonholonomic Systems (1972) ch. III).
#pragma once
#include "dynamics/models/EquationModel.h"

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace rv {

/// Whether a model document describes a rolling body ("kind": "rolling").
bool isRollingModel(const nlohmann::json& doc);

/// The equation model of a rolling body, and where each expression it copied from the description came
/// from: {generated JSON path, the description's JSON path}, so that an error in a user's expression is
/// reported at the field the user wrote.
struct RollingEquations {
  std::string model; ///< the equation model's JSON text, keys in the order written (parameters, observables)
  std::vector<std::pair<std::string, std::string>> origins;
  /// The shape each definition holding a user's expression must have (EquationModelSpec::definitionShapes):
  /// a centre given as a 2-vector is named at body.centre, not where the derivation first uses it.
  std::map<std::string, RequiredShape> shapes;
};

/// Derives the equations of the rolling body `doc` (with its key order from `ordered` when given). Throws
/// InputError "SOURCE:path: what is wrong" for a malformed description.
RollingEquations rollingEquations(const nlohmann::json& doc, const nlohmann::ordered_json* ordered,
                                  const std::string& source);

/// What File > New rolling body asks of a body and what it rolls on. Every number becomes a parameter of the
/// model written (so the GUI's fields, --set, sweeps and continuation reach it).
struct RollingBodyForm {
  std::string id = "my_body", title;
  /// sphere, ellipsoid, paraboloid, disk, superellipsoid, revolution or implicit
  std::string shape = "ellipsoid";
  /// sphere, disk: the radius first; ellipsoid, superellipsoid: the semi-axes; paraboloid: p, q
  std::array<double, 3> sizes{1, 0.6, 0.4};
  double exponent = 4, bulge = 0.05; ///< superellipsoid: p >= 2, and the bulge (> 0 when p > 2)
  /// revolution: the radius rho(z) about body axis 3 at the height z (rho(z)^2 when profileSquared), an
  /// expression of z and the parameters (z_bottom, z_top among them); by default a lens wider above its
  /// middle
  std::string profile = "(z - z_bottom)*(z_top - z)*(1.6 + 0.4*z)";
  bool profileSquared = true;
  std::array<double, 2> heights{-0.5, 0.5}; ///< revolution: the profile's ends on the axis, bottom and top
  std::string surface;                      ///< implicit: F(x, y, z), F < 0 inside
  double size = 1;                          ///< implicit: a length that bounds the surface
  std::array<double, 3> centre{0, 0, 0};    ///< the shape's origin seen from the centre of mass
  double mass = 1;
  std::array<double, 3> inertia{0.2, 0.3, 0.4}; ///< central principal moments along the body axes
  std::string contact = "marble";               ///< marble, rubber or sliding
  double friction = 0.3, gravity = 1;
  bool symmetryAxis = false;     ///< body axis 3 is an axis of symmetry (axis_up, Jellett)
  std::string support = "plane"; ///< plane, sphere, ellipsoid, paraboloid (a bowl) or implicit
  bool inside = false;           ///< sphere, ellipsoid: the body rolls inside it (a bowl), not on it
  /// sphere: its radius first; ellipsoid: its semi-axes; paraboloid: p, q, its radii of curvature at the
  /// bottom. The defaults are flatter than each shape's default body (but the superellipsoid's brick, whose
  /// faces are flatter than any bowl), so that it touches a bowl at one point.
  std::array<double, 3> supportSizes{8, 6, 4};
  /// implicit: the support's F(x, y, z) in fixed axes, F < 0 in it (supportSizes[0] the size drawn); by
  /// default a paraboloid bowl of radius 8 at its bottom, through the origin where the contact is sought
  std::string supportSurface = "z - (x^2 + y^2)/16";
};

/// The rolling model file of a form, with a start that suits its shape (tilted from rest, spinning; on a
/// curved support on top of the sphere or ellipsoid, at the bottom of a bowl). Throws InputError naming the
/// field for a form that makes no model (a superellipsoid's exponent below 2 or without bulge above 2, a
/// profile's bottom not below its top).
nlohmann::ordered_json rollingModelDocument(const RollingBodyForm& form);

} // namespace rv
