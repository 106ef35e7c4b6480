// FixedPointJson.h -- a fixed point's numbers as the front ends write them (JSON of `--json`, CSV rows, the
// runners' fields): one spelling for the CLI, the Python module and the registry tools.
#pragma once
#include <Eigen/Core>
#include <complex>
#include <nlohmann/json.hpp>
#include <vector>

namespace rv {

/// The coordinates as a plain vector (a JSON array, a CSV row).
inline std::vector<double> toVector(const Eigen::VectorXd& x) {
  return {x.data(), x.data() + x.size()};
}

/// Multipliers as [[re, im], ...].
inline nlohmann::json multipliersJson(const std::vector<std::complex<double>>& m) {
  nlohmann::json j = nlohmann::json::array();
  for (auto z : m)
    j.push_back({z.real(), z.imag()});
  return j;
}

} // namespace rv
