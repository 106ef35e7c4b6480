#include "dynamics/models/BodyParameters.h"

#include "dynamics/core/Errors.h"

#include <Eigen/Eigenvalues>
#include <sstream>

namespace rv::rigid_body {

std::vector<ParameterSpec> massParameters(double I1, double I2, double I3) {
  return {
      {.id = "energy",
       .label = "Energy",
       .defaultValue = 1.0,
       .description = "total energy H of (3) at which a map point is completed into a state"},
      {.id = "I1",
       .label = "I1",
       .defaultValue = I1,
       .min = 0,
       .description = "principal central moment of inertia"},
      {.id = "I2",
       .label = "I2",
       .defaultValue = I2,
       .min = 0,
       .description = "principal central moment of inertia"},
      {.id = "I3",
       .label = "I3",
       .defaultValue = I3,
       .min = 0,
       .description = "principal central moment of inertia"},
      {.id = "m", .label = "m", .defaultValue = 1.0, .min = 0, .description = "mass of the body"},
      {.id = "g", .label = "g", .defaultValue = 1.0, .min = 0, .description = "acceleration of gravity"},
  };
}

std::vector<ParameterSpec> fieldParameters() {
  std::vector<ParameterSpec> specs;
  for (const char* id : {"B11", "B12", "B13", "B22", "B23", "B33"})
    specs.push_back(
        {.id = id,
         .label = id,
         .defaultValue = 0.0,
         .description = "extra field U = (gamma, B gamma)/2, symmetric positive semi-definite B"});
  return specs;
}

Eigen::Vector3d principalMoments(const ParameterValues& p) {
  Eigen::Vector3d I(p["I1"], p["I2"], p["I3"]);
  for (int i = 0; i < 3; ++i)
    if (!(I[i] > 0)) throw InputError("I" + std::to_string(i + 1) + ": a moment of inertia must be positive");
  for (int i = 0; i < 3; ++i)
    if (I[i] > I[(i + 1) % 3] + I[(i + 2) % 3]) {
      std::ostringstream os;
      os << "I" << i + 1 << " = " << I[i] << " exceeds I" << (i + 1) % 3 + 1 << " + I" << (i + 2) % 3 + 1
         << ": moments of inertia of a body satisfy the triangle inequality";
      throw InputError(os.str());
    }
  if (!(p["m"] > 0)) throw InputError("m: the mass must be positive");
  return I;
}

Eigen::Matrix3d fieldMatrix(const ParameterValues& p) {
  Eigen::Matrix3d B;
  B << p["B11"], p["B12"], p["B13"], p["B12"], p["B22"], p["B23"], p["B13"], p["B23"], p["B33"];
  const double least = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(B).eigenvalues().minCoeff();
  if (least < -1e-14 * std::max(1.0, B.norm())) {
    std::ostringstream os;
    os << "B11..B33: the field matrix B must be positive semi-definite (its least eigenvalue is " << least
       << ")";
    throw InputError(os.str());
  }
  return B;
}

} // namespace rv::rigid_body
