// BodyState.h -- the state layout and observables shared by every body rolling on the plane (Chaplygin ball,
// paraboloid, ellipsoid): M, gamma, alpha, beta in the body frame, the position on the plane, trace lengths.
#pragma once
#include "dynamics/core/Model.h"

#include <Eigen/Dense>
#include <functional>
#include <map>

namespace rv::body_state {

// indices into the state
constexpr int kM = 0, kGamma = 3, kAlpha = 6, kBeta = 9, kX = 12, kY = 13, kTracePlane = 14, kTraceBody = 15,
              kSize = 16;

/// M1..M3 gamma1..3 alpha1..3 beta1..3 x y s_plane s_body
std::vector<std::string> names();

/// A state with M and the unit vertical gamma (normalised), alpha and beta completing a right-handed fixed
/// frame (alpha x beta = gamma), the body at the origin of the plane, traces empty.
Eigen::VectorXd fromMomentumAndVertical(const Eigen::Vector3d& M, const Eigen::Vector3d& gamma);

/// M1..M3 and gamma1..gamma3 from named values; InputError naming `context` when one is missing or gamma is
/// zero.
std::pair<Eigen::Vector3d, Eigen::Vector3d> momentumAndVertical(const std::map<std::string, double>& named,
                                                                const std::string& context);

/// The rotation body -> world: rows alpha, beta, gamma.
Eigen::Matrix3d rotation(const double* x);

using VectorOf = std::function<Eigen::Vector3d(const double* x)>;

/// omega1..3; Andoyer-Deprit G, L, l, g, L/G, H/G of `momentum` (M, or M + K with a gyrostat); Euler angles
/// theta, phi, psi; RabsX, RabsY; Vx, Vy (from `velocity`, the centre's velocity in the body frame);
/// Lplane, Lbody, Ldiff.
std::vector<Observable> kinematicObservables(const VectorOf& omega, const VectorOf& momentum,
                                             const VectorOf& velocity);

} // namespace rv::body_state
