// Bordered.h -- the linear algebra of pseudo-arclength continuation, shared by the families of fixed points
// (Continuation.h) and the bifurcation curves (BifurcationCurve.h): a system of m equations in m + 1
// unknowns, its derivative J (m x (m + 1)) bordered by one more row (Keller, Numerical solution of
// bifurcation and nonlinear eigenvalue problems (1977); Allgower & Georg, Introduction to Numerical
// Continuation Methods (1990) §2.1-2.2).
#pragma once
#include <Eigen/Core>

namespace rv {

/// The unit tangent of the solution curve: the null vector of J, oriented along `along` (the bordered system
/// [J; along^T] t = (0, 1)). ComputationError `why` where that system is singular (J of rank below m, a
/// branch point, or `along` orthogonal to the curve).
Eigen::VectorXd curveTangent(const Eigen::MatrixXd& J, const Eigen::VectorXd& along, const char* why);

/// One Newton step of the corrector on [F(v) = 0, normal . (v - base) = sigma]: the solution d of
/// [J; normal^T] d = -(F, g), g the constraint's residual, shortened to `maxDistance`. ComputationError when
/// the bordered matrix is singular.
Eigen::VectorXd correctorStep(const Eigen::MatrixXd& J, const Eigen::VectorXd& normal,
                              const Eigen::VectorXd& F, double g, double maxDistance);

} // namespace rv
