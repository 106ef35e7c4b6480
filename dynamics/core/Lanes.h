// Lanes.h -- kLanes doubles computed together, one per SIMD lane, and Jet, a value with its derivative along
// one direction: the scalars a model's templated field is evaluated on to integrate kLanes trajectories at
// once (a sweep's points, issue 40), as heyoka's batch mode does (Biscani & Izzo, MNRAS 504 (2021) 2614).
//
// Lanes is a GCC/Clang vector of 4 doubles: a baseline x86-64 build computes it as two SSE2 pairs; code
// compiled for AVX2 (ModelWithField's lane kernel, chosen at run time on a CPU that has it) as one 256-bit
// register. Each lane does exactly the arithmetic the scalar path does -- no fused multiply-add (the kernel
// is compiled for AVX2 without FMA), the same order of operations (Jet's rules are Eigen::AutoDiffScalar's)
// -- so a lane's result equals the scalar one bit for bit. Functions with no vector form (sqrt, sin, ...)
// are applied lane by lane with the C library's, as the scalar path calls them.
#pragma once
#include "dynamics/core/HeldScalar.h"

#include <Eigen/Core>
#include <cmath>
#include <string>

namespace rv {

/// How many trajectories a lane kernel integrates at once.
inline constexpr int kLanes = 4;

struct Lanes {
  // aligned as a double, not as the vector: Eigen's fixed-size storage aligns its arrays to 16 bytes, which a
  // 32-byte-aligned element would contradict (clang refuses it); loads and stores are unaligned ones
  typedef double V __attribute__((vector_size(kLanes * sizeof(double)), aligned(alignof(double))));
  V v;
  Lanes() : v(V{}) {}
  Lanes(double x) : v(V{} + x) {} // NOLINT(google-explicit-constructor): a constant in every lane
  static Lanes load(const double* p) {
    Lanes r;
    __builtin_memcpy(&r.v, p, sizeof(V));
    return r;
  }
  void store(double* p) const { __builtin_memcpy(p, &v, sizeof(V)); }
  double operator[](int l) const { return v[l]; }
  Lanes& operator+=(const Lanes& o) { return v += o.v, *this; }
  Lanes& operator-=(const Lanes& o) { return v -= o.v, *this; }
  Lanes& operator*=(const Lanes& o) { return v *= o.v, *this; }
  Lanes& operator/=(const Lanes& o) { return v /= o.v, *this; }
};

inline Lanes operator+(const Lanes& a, const Lanes& b) {
  Lanes r;
  r.v = a.v + b.v;
  return r;
}
inline Lanes operator-(const Lanes& a, const Lanes& b) {
  Lanes r;
  r.v = a.v - b.v;
  return r;
}
inline Lanes operator*(const Lanes& a, const Lanes& b) {
  Lanes r;
  r.v = a.v * b.v;
  return r;
}
inline Lanes operator/(const Lanes& a, const Lanes& b) {
  Lanes r;
  r.v = a.v / b.v;
  return r;
}
inline Lanes operator-(const Lanes& a) {
  Lanes r;
  r.v = -a.v;
  return r;
}
inline Lanes operator+(const Lanes& a) {
  return a;
}
template <class F> Lanes eachLane(const Lanes& a, F f) {
  Lanes r;
  for (int l = 0; l < kLanes; ++l)
    r.v[l] = f(a.v[l]);
  return r;
}
inline Lanes sqrt(const Lanes& a) {
  return eachLane(a, [](double x) { return std::sqrt(x); });
}
inline Lanes sin(const Lanes& a) {
  return eachLane(a, [](double x) { return std::sin(x); });
}
inline Lanes cos(const Lanes& a) {
  return eachLane(a, [](double x) { return std::cos(x); });
}
inline Lanes exp(const Lanes& a) {
  return eachLane(a, [](double x) { return std::exp(x); });
}
inline Lanes log(const Lanes& a) {
  return eachLane(a, [](double x) { return std::log(x); });
}

/// A value and its derivative along one direction (forward-mode differentiation), with the rules of
/// Eigen::AutoDiffScalar written out in its order of operations, so that a lane's tangent equals the scalar
/// path's (ModelWithField::tangentRhs) bit for bit.
template <class T> struct Jet {
  T v, d;
  Jet() : v(0.0), d(0.0) {}
  Jet(double x) : v(x), d(0.0) {} // NOLINT(google-explicit-constructor): a constant
  Jet(T value, T derivative) : v(value), d(derivative) {}
  Jet& operator+=(const Jet& o) { return *this = *this + o; }
  Jet& operator-=(const Jet& o) { return *this = *this - o; }
  Jet& operator*=(const Jet& o) { return *this = *this * o; }
  Jet& operator/=(const Jet& o) { return *this = *this / o; }
};

template <class T> Jet<T> operator+(const Jet<T>& a, const Jet<T>& b) {
  return {a.v + b.v, a.d + b.d};
}
template <class T> Jet<T> operator-(const Jet<T>& a, const Jet<T>& b) {
  return {a.v - b.v, a.d - b.d};
}
template <class T> Jet<T> operator*(const Jet<T>& a, const Jet<T>& b) {
  return {a.v * b.v, a.d * b.v + b.d * a.v};
}
template <class T> Jet<T> operator/(const Jet<T>& a, const Jet<T>& b) {
  return {a.v / b.v, (a.d * b.v - b.d * a.v) * (T(1.0) / (b.v * b.v))};
}
template <class T> Jet<T> operator-(const Jet<T>& a) {
  return {-a.v, -a.d};
}
template <class T> Jet<T> operator+(const Jet<T>& a) {
  return a;
}
template <class T> Jet<T> operator+(const Jet<T>& a, double b) {
  return {a.v + b, a.d};
}
template <class T> Jet<T> operator+(double a, const Jet<T>& b) {
  return {a + b.v, b.d};
}
template <class T> Jet<T> operator-(const Jet<T>& a, double b) {
  return {a.v - b, a.d};
}
template <class T> Jet<T> operator-(double a, const Jet<T>& b) {
  return {a - b.v, -b.d};
}
template <class T> Jet<T> operator*(const Jet<T>& a, double b) {
  return {a.v * b, a.d * b};
}
template <class T> Jet<T> operator*(double a, const Jet<T>& b) {
  return {a * b.v, b.d * a};
}
template <class T> Jet<T> operator/(const Jet<T>& a, double b) {
  return {a.v / b, a.d * (1.0 / b)};
}
template <class T> Jet<T> operator/(double a, const Jet<T>& b) {
  return {a / b.v, b.d * (T(-a) / (b.v * b.v))};
}
template <class T> Jet<T> sqrt(const Jet<T>& a) {
  using std::sqrt;
  const T root = sqrt(a.v);
  return {root, a.d * (T(0.5) / root)};
}
template <class T> Jet<T> sin(const Jet<T>& a) {
  using std::cos, std::sin;
  return {sin(a.v), a.d * cos(a.v)};
}
template <class T> Jet<T> cos(const Jet<T>& a) {
  using std::cos, std::sin;
  return {cos(a.v), a.d * -sin(a.v)};
}

/// Whether this CPU runs the AVX2 lane kernels (else they run as SSE2 pairs).
inline bool cpuHasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

/// What `rollviz info` says of the lanes.
inline std::string laneDescription() {
  return std::to_string(kLanes) + " trajectories per batch, " +
         (cpuHasAvx2() ? "one AVX2 register (256 bits) of doubles"
                       : "two SSE2 pairs of doubles (no AVX2 here)");
}

} // namespace rv

namespace Eigen {
template <> struct NumTraits<rv::Lanes> : rv::HeldScalarTraits<rv::Lanes, 1> {};
template <class T> struct NumTraits<rv::Jet<T>> : rv::HeldScalarTraits<rv::Jet<T>, 3> {};
} // namespace Eigen
