#include "dynamics/tools/Bordered.h"

#include "dynamics/core/Errors.h"

#include <Eigen/LU>

namespace rv {

namespace {
Eigen::MatrixXd bordered(const Eigen::MatrixXd& J, const Eigen::VectorXd& row) {
  Eigen::MatrixXd M(J.rows() + 1, J.cols());
  M.topRows(J.rows()) = J;
  M.row(J.rows()) = row.transpose();
  return M;
}
} // namespace

Eigen::VectorXd curveTangent(const Eigen::MatrixXd& J, const Eigen::VectorXd& along, const char* why) {
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(bordered(J, along));
  if (!lu.isInvertible()) throw ComputationError(why);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(J.cols());
  rhs[J.rows()] = 1;
  const Eigen::VectorXd t = lu.solve(rhs).normalized();
  return t.dot(along) < 0 ? (-t).eval() : t;
}

Eigen::VectorXd correctorStep(const Eigen::MatrixXd& J, const Eigen::VectorXd& normal,
                              const Eigen::VectorXd& F, double g, double maxDistance) {
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(bordered(J, normal));
  if (!lu.isInvertible()) throw ComputationError("the corrector's bordered system is singular");
  Eigen::VectorXd rhs(J.cols());
  rhs.head(J.rows()) = -F;
  rhs[J.rows()] = -g;
  Eigen::VectorXd d = lu.solve(rhs);
  if (d.norm() > maxDistance) d *= maxDistance / d.norm();
  return d;
}

} // namespace rv
