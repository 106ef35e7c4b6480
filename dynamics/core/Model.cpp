#include "dynamics/core/Model.h"

#include "dynamics/core/Errors.h"

#include <cmath>

namespace rv {

Model::Model(const ModelInfo& info, const ParameterValues& params) : info_(&info), params_(params) {}

Eigen::VectorXd Model::integrals(const double*) const {
  return {};
}
double Model::measureDensity(const double*) const {
  return 1.0;
}
std::optional<BodyPose> Model::pose(const double*) const {
  return std::nullopt;
}
std::optional<BodyGeometry> Model::geometry() const {
  return std::nullopt;
}
std::optional<SupportSurface> Model::support() const {
  return std::nullopt;
}

Eigen::VectorXd Model::stateFromNamed(const std::map<std::string, double>& named,
                                      const std::string& context) const {
  for (const auto& n : info_->stateNames)
    if (!named.count(n)) throw InputError(context + ": missing state component '" + n + "'");
  Eigen::VectorXd x = Eigen::VectorXd::Zero(dimension());
  assignNamed(named, context, x);
  return x;
}

Eigen::VectorXd Model::stateFromMap(const std::vector<double>& point, const MapPointSpec&,
                                    const std::string& context) const {
  if (isMap()) { // the point is the state
    if (static_cast<int>(point.size()) != dimension())
      throw InputError(context + ": " + info_->id + " map points have " + std::to_string(dimension()) +
                       " coordinates");
    return Eigen::Map<const Eigen::VectorXd>(point.data(), dimension());
  }
  throw InputError(context + ": " + info_->id + " has no map coordinates; give \"state\" instead");
}

void Model::coreJacobian(const double* x, double* jac) const {
  const int n = dimension(), m = info_->coreDimension;
  std::vector<double> full(static_cast<std::size_t>(n) * n);
  jacobian(x, full.data());
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      jac[i * m + j] = full[i * n + j];
}

void Model::recordField(taylor::Tape&, const double*) const {
  throw InputError(info_->id + ": the taylor integrator cannot expand this system (it expands a model's own "
                               "right-hand side, not the tangent vectors of Lyapunov exponents or MEGNO); "
                               "choose another integrator.method, e.g. everhart");
}

bool Model::tangentRk4(double*, double*, int, double, long) const {
  return false;
}

void Model::tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const {
  const int m = info_->coreDimension;
  rhs(x, dx);
  std::vector<double> J(static_cast<std::size_t>(m) * m);
  coreJacobian(x, J.data());
  for (int c = 0; c < k; ++c)
    for (int i = 0; i < m; ++i) {
      double sum = 0;
      for (int l = 0; l < m; ++l)
        sum += J[i * m + l] * V[c * m + l];
      dV[c * m + i] = sum;
    }
}

int Model::sheetOf(const Eigen::VectorXd&, const MapPointSpec&) const {
  return 1;
}

int Model::findObservable(const std::string& id) const {
  for (std::size_t i = 0; i < observables_.size(); ++i)
    if (observables_[i].id == id) return static_cast<int>(i);
  return -1;
}

void Model::addObservable(std::string id, std::string description,
                          std::function<double(double, const double*)> f) {
  observables_.push_back({std::move(id), std::move(description), std::move(f)});
}

void Model::addObservables(std::vector<Observable> list) {
  for (auto& o : list)
    observables_.push_back(std::move(o));
}

void Model::addStandardObservables() {
  addObservable("t", "time", [](double t, const double*) { return t; });
  for (std::size_t i = 0; i < info_->stateNames.size(); ++i)
    addObservable(info_->stateNames[i], "state component", [i](double, const double* x) { return x[i]; });
  for (std::size_t k = 0; k < info_->integralNames.size(); ++k)
    if (findObservable(info_->integralNames[k]) < 0)
      addObservable(info_->integralNames[k], "first integral", [this, k](double, const double* x) {
        return integrals(x)[static_cast<Eigen::Index>(k)];
      });
}

void Model::assignNamed(const std::map<std::string, double>& named, const std::string& context,
                        Eigen::VectorXd& x) const {
  for (const auto& [name, value] : named) {
    const auto& names = info_->stateNames;
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw InputError(context + "." + name + ": unknown state component of " + info_->id);
    if (!std::isfinite(value)) throw InputError(context + "." + name + ": must be a finite number");
    x[it - names.begin()] = value;
  }
}

} // namespace rv
