// BodyParameters.h -- parameter declarations and checks shared by the rigid bodies (mass, inertia, extra
// field).
#pragma once
#include "dynamics/core/ParameterTable.h"

#include <Eigen/Core>
#include <vector>

namespace rv {

namespace rigid_body {
/// energy, I1..I3, m, g (in this order).
std::vector<ParameterSpec> massParameters(double I1, double I2, double I3);
/// B11 B12 B13 B22 B23 B33.
std::vector<ParameterSpec> fieldParameters();
/// Checks I > 0 with the triangle inequality, m > 0; returns diag(I1, I2, I3).
Eigen::Vector3d principalMoments(const ParameterValues& p);
/// The symmetric B from B11..B33; InputError when it has a negative eigenvalue.
Eigen::Matrix3d fieldMatrix(const ParameterValues& p);
} // namespace rigid_body

} // namespace rv
