#include "dynamics/models/HenonHeiles.h"

#include "dynamics/core/Errors.h"

#include <cmath>
#include <sstream>

namespace rv {

const ModelInfo& HenonHeiles::staticInfo() {
  static const ModelInfo info{
      .id = "henon_heiles",
      .title = "Henon-Heiles system (reference Hamiltonian flow)",
      .reference = "M. Henon, C. Heiles, Astron. J. 69 (1964) 73",
      .parameters = {{.id = "energy",
                      .label = "Energy",
                      .defaultValue = 0.125,
                      .min = 0,
                      .max = 1.0 / 6.0,
                      .description =
                          "energy at which a map point (y, py) is completed (bounded motion below 1/6)"}},
      .stateNames = {"x", "y", "px", "py"},
      .coreDimension = 4,
      .integralNames = {"E"},
      .hasMeasure = true,
      .mapCoordinates = {"y", "py"},
      .section = "x",
  };
  return info;
}

HenonHeiles::HenonHeiles(const ParameterValues& p) : ModelWithField(staticInfo(), p) {
  addStandardObservables();
}

double HenonHeiles::hamiltonian(const double* s) {
  const double x = s[0], y = s[1];
  return 0.5 * (s[2] * s[2] + s[3] * s[3]) + 0.5 * (x * x + y * y) + x * x * y - y * y * y / 3;
}

Eigen::VectorXd HenonHeiles::integrals(const double* s) const {
  Eigen::VectorXd v(1);
  v << hamiltonian(s);
  return v;
}

Eigen::VectorXd HenonHeiles::stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                                          const std::string& context) const {
  if (point.size() != 2) throw InputError(context + ": henon_heiles map points are (y, py)");
  if (spec.sectionValue != 0) throw InputError(context + ": the henon_heiles section is x = 0");
  const double y = point[0], py = point[1], E = params_["energy"];
  const double px2 = 2 * E - py * py - y * y + 2 * y * y * y / 3;
  if (!(px2 >= 0)) {
    std::ostringstream os;
    os << context << ": no state at (y, py) = (" << y << ", " << py << ") with energy " << E
       << " (the point lies outside the region of allowed motion)";
    throw InputError(os.str());
  }
  Eigen::VectorXd s(4);
  s << 0, y, std::sqrt(px2), py;
  return s;
}

template class ModelWithField<HenonHeiles, 4>;

} // namespace rv
