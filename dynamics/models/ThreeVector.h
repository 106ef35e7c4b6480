// ThreeVector.h -- a 3-vector of a field's scalar with the few operations the rigid bodies' equations use,
// each written out and always inlined. The lane kernels (dynamics/core/LaneField.h) compile a field whole
// for AVX2/AVX-512 only where every call in it is inlined: GCC leaves Eigen's expression machinery over
// large scalars (Jet<LaneVector<8>, 6> is 448 bytes) out of line, compiled for baseline x86-64 (measured:
// the rattleback's lanes ran slower than one orbit at a time). One definition of the arithmetic's order for
// the scalar path and the lanes, so each lane rounds as the scalar run does.
#pragma once
#include <Eigen/Core>
#include <array>
#include <cmath>

namespace rv {

template <class S> struct ThreeVector {
  std::array<S, 3> c;

  [[gnu::always_inline]] const S& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
  /// From and to an Eigen vector (for the callers outside the equations).
  static ThreeVector from(const Eigen::Matrix<S, 3, 1>& v) { return {{v[0], v[1], v[2]}}; }
  Eigen::Matrix<S, 3, 1> eigen() const { return Eigen::Matrix<S, 3, 1>(c[0], c[1], c[2]); }
  /// The components of a vector of coefficients T (double, or one value per lane) as S.
  template <class T> [[gnu::always_inline]] static ThreeVector of(const std::array<T, 3>& v) {
    return {{S(v[0]), S(v[1]), S(v[2])}};
  }

  [[gnu::always_inline]] friend ThreeVector operator+(const ThreeVector& a, const ThreeVector& b) {
    return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
  }
  [[gnu::always_inline]] friend ThreeVector operator-(const ThreeVector& a, const ThreeVector& b) {
    return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
  }
  [[gnu::always_inline]] friend ThreeVector operator-(const ThreeVector& a) {
    return {{-a[0], -a[1], -a[2]}};
  }
  /// A scalar (S, or a coefficient) times the vector.
  template <class C> [[gnu::always_inline]] friend ThreeVector operator*(const C& s, const ThreeVector& a) {
    return {{s * a[0], s * a[1], s * a[2]}};
  }
  /// Divided by a scalar (S, or a coefficient).
  template <class C> [[gnu::always_inline]] friend ThreeVector operator/(const ThreeVector& a, const C& s) {
    return {{a[0] / s, a[1] / s, a[2] / s}};
  }
  /// Component by component, with coefficients T.
  template <class T>
  [[gnu::always_inline]] friend ThreeVector times(const std::array<T, 3>& k, const ThreeVector& a) {
    return {{k[0] * a[0], k[1] * a[1], k[2] * a[2]}};
  }
  [[gnu::always_inline]] friend S dot(const ThreeVector& a, const ThreeVector& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  [[gnu::always_inline]] friend ThreeVector cross(const ThreeVector& a, const ThreeVector& b) {
    return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
  }
};

/// A 3x3 matrix of S, row-major, with the solve the equations need.
template <class S> struct ThreeMatrix {
  std::array<S, 9> m;

  [[gnu::always_inline]] S& operator()(int i, int j) {
    return m[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j)];
  }
  [[gnu::always_inline]] const S& operator()(int i, int j) const {
    return m[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(j)];
  }
  /// A matrix of coefficients T stored column-major (Eigen's order) as S.
  template <class T> [[gnu::always_inline]] static ThreeMatrix of(const std::array<T, 9>& columnMajor) {
    const auto& c = columnMajor;
    return {{S(c[0]), S(c[3]), S(c[6]), S(c[1]), S(c[4]), S(c[7]), S(c[2]), S(c[5]), S(c[8])}};
  }
  [[gnu::always_inline]] ThreeVector<S> operator*(const ThreeVector<S>& v) const {
    const ThreeMatrix& a = *this;
    return {{a(0, 0) * v[0] + a(0, 1) * v[1] + a(0, 2) * v[2],
             a(1, 0) * v[0] + a(1, 1) * v[1] + a(1, 2) * v[2],
             a(2, 0) * v[0] + a(2, 1) * v[1] + a(2, 2) * v[2]}};
  }
  /// A^-1 v by the cofactors (Cramer's rule): what a 3x3 inverse costs, without forming it.
  [[gnu::always_inline]] ThreeVector<S> solve(const ThreeVector<S>& v) const {
    const ThreeMatrix& a = *this;
    const S c00 = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1), c01 = a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2),
            c02 = a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0);
    const S c10 = a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2), c11 = a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0),
            c12 = a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1);
    const S c20 = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1), c21 = a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2),
            c22 = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
    const S det = a(0, 0) * c00 + a(0, 1) * c01 + a(0, 2) * c02;
    // (A^-1)_ij = C_ji / det
    return {{(c00 * v[0] + c10 * v[1] + c20 * v[2]) / det, (c01 * v[0] + c11 * v[1] + c21 * v[2]) / det,
             (c02 * v[0] + c12 * v[1] + c22 * v[2]) / det}};
  }
};

} // namespace rv
