// Snapshot.h -- the numbers a resumable computation saves (checkpoints): appended in order, read back in the
// same order. Doubles keep every bit; counts and flags are stored as doubles (exact below 2^53).
#pragma once
#include "dynamics/core/Errors.h"

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace rv {

struct Snapshot {
  std::vector<double> values;
  std::size_t position = 0; ///< the next value get() reads

  void put(double v) { values.push_back(v); }
  /// a vector or matrix with its shape
  template <class Derived> void put(const Eigen::PlainObjectBase<Derived>& m) {
    put(static_cast<double>(m.rows())), put(static_cast<double>(m.cols()));
    values.insert(values.end(), m.data(), m.data() + m.size());
  }
  double get() {
    if (position >= values.size()) throw InputError("checkpoint: fewer numbers than the computation saved");
    return values[position++];
  }
  long getLong() { return static_cast<long>(get()); }
  template <class Derived> void get(Eigen::PlainObjectBase<Derived>& m) {
    const auto rows = static_cast<Eigen::Index>(get()), cols = static_cast<Eigen::Index>(get());
    if (rows < 0 || cols < 0 || position + static_cast<std::size_t>(rows * cols) > values.size())
      throw InputError("checkpoint: a saved array does not fit");
    m.resize(rows, cols);
    for (Eigen::Index i = 0; i < rows * cols; ++i)
      m.data()[i] = values[position++];
  }
};

} // namespace rv
