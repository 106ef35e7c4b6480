#include "dynamics/models/BallOnSurface.h"

#include <Eigen/Geometry>

namespace rv::ball_on_surface {

Eigen::Matrix3d rotation(const double* q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
}

} // namespace rv::ball_on_surface
