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
#include <type_traits>

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

/// A value and its derivatives along K directions (forward-mode differentiation), with the rules of
/// Eigen::AutoDiffScalar written out in its order of operations, derivative by derivative, so that a lane's
/// tangents equal the scalar path's (ModelWithField::tangentRhs, its K-vector AutoDiff pass) bit for bit.
/// A constant is a double, or one value per lane (a coefficient that differs between lanes).
template <class T, int K = 1> struct Jet {
  T v;
  T d[K];
  Jet() : v(0.0) { fill(T(0.0)); }
  Jet(double x) : v(x) { fill(T(0.0)); } // NOLINT(google-explicit-constructor): a constant
  Jet(T value, T derivative) : v(value) { fill(derivative); }
  Jet& operator+=(const Jet& o) { return *this = *this + o; }
  Jet& operator-=(const Jet& o) { return *this = *this - o; }
  Jet& operator*=(const Jet& o) { return *this = *this * o; }
  Jet& operator/=(const Jet& o) { return *this = *this / o; }
  /// The jet with value `value` and derivatives d[c] = f(c).
  template <class F> [[gnu::always_inline]] static Jet with(T value, F f) {
    Jet r;
    r.v = value;
    for (int c = 0; c < K; ++c)
      r.d[c] = f(c);
    return r;
  }

private:
  void fill(const T& x) {
    for (int c = 0; c < K; ++c)
      d[c] = x;
  }
};

/// A constant of a Jet<T, K>: a number, or a T (one value per lane: a coefficient that differs between
/// lanes).
template <class C, class T>
concept JetConstant = std::is_arithmetic_v<C> || std::is_same_v<C, T>;

/// A Jet's constant as a T: a number in every lane.
template <class T, class C> T constantAs(const C& c) {
  if constexpr (std::is_same_v<C, T>)
    return c;
  else
    return T(static_cast<double>(c));
}

template <class T, int K>
[[gnu::always_inline]] inline Jet<T, K> operator+(const Jet<T, K>& a, const Jet<T, K>& b) {
  return Jet<T, K>::with(a.v + b.v, [&](int c) { return a.d[c] + b.d[c]; });
}
template <class T, int K>
[[gnu::always_inline]] inline Jet<T, K> operator-(const Jet<T, K>& a, const Jet<T, K>& b) {
  return Jet<T, K>::with(a.v - b.v, [&](int c) { return a.d[c] - b.d[c]; });
}
template <class T, int K>
[[gnu::always_inline]] inline Jet<T, K> operator*(const Jet<T, K>& a, const Jet<T, K>& b) {
  return Jet<T, K>::with(a.v * b.v, [&](int c) { return a.d[c] * b.v + b.d[c] * a.v; });
}
template <class T, int K>
[[gnu::always_inline]] inline Jet<T, K> operator/(const Jet<T, K>& a, const Jet<T, K>& b) {
  const T scale = T(1.0) / (b.v * b.v);
  return Jet<T, K>::with(a.v / b.v, [&](int c) { return (a.d[c] * b.v - b.d[c] * a.v) * scale; });
}
template <class T, int K> [[gnu::always_inline]] inline Jet<T, K> operator-(const Jet<T, K>& a) {
  return Jet<T, K>::with(-a.v, [&](int c) { return -a.d[c]; });
}
template <class T, int K> [[gnu::always_inline]] inline Jet<T, K> operator+(const Jet<T, K>& a) {
  return a;
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator+(const Jet<T, K>& a, const C& constant) {
  const T b = constantAs<T>(constant);
  return Jet<T, K>::with(a.v + b, [&](int c) { return a.d[c]; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator+(const C& constant, const Jet<T, K>& b) {
  const T a = constantAs<T>(constant);
  return Jet<T, K>::with(a + b.v, [&](int c) { return b.d[c]; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator-(const Jet<T, K>& a, const C& constant) {
  const T b = constantAs<T>(constant);
  return Jet<T, K>::with(a.v - b, [&](int c) { return a.d[c]; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator-(const C& constant, const Jet<T, K>& b) {
  const T a = constantAs<T>(constant);
  return Jet<T, K>::with(a - b.v, [&](int c) { return -b.d[c]; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator*(const Jet<T, K>& a, const C& constant) {
  const T b = constantAs<T>(constant);
  return Jet<T, K>::with(a.v * b, [&](int c) { return a.d[c] * b; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator*(const C& constant, const Jet<T, K>& b) {
  const T a = constantAs<T>(constant);
  return Jet<T, K>::with(a * b.v, [&](int c) { return b.d[c] * a; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator/(const Jet<T, K>& a, const C& constant) {
  const T b = constantAs<T>(constant);
  const T inverse = T(1.0) / b;
  return Jet<T, K>::with(a.v / b, [&](int c) { return a.d[c] * inverse; });
}
template <class T, int K, JetConstant<T> C>
[[gnu::always_inline]] inline Jet<T, K> operator/(const C& constant, const Jet<T, K>& b) {
  const T a = constantAs<T>(constant);
  const T scale = -a / (b.v * b.v);
  return Jet<T, K>::with(a / b.v, [&](int c) { return b.d[c] * scale; });
}
template <class T, int K> [[gnu::always_inline]] inline Jet<T, K> sqrt(const Jet<T, K>& a) {
  using std::sqrt;
  const T root = sqrt(a.v);
  const T scale = T(0.5) / root;
  return Jet<T, K>::with(root, [&](int c) { return a.d[c] * scale; });
}
template <class T, int K> [[gnu::always_inline]] inline Jet<T, K> sin(const Jet<T, K>& a) {
  using std::cos, std::sin;
  const T slope = cos(a.v);
  return Jet<T, K>::with(sin(a.v), [&](int c) { return a.d[c] * slope; });
}
template <class T, int K> [[gnu::always_inline]] inline Jet<T, K> cos(const Jet<T, K>& a) {
  using std::cos, std::sin;
  const T slope = -sin(a.v);
  return Jet<T, K>::with(cos(a.v), [&](int c) { return a.d[c] * slope; });
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
template <class T, int K> struct NumTraits<rv::Jet<T, K>> : rv::HeldScalarTraits<rv::Jet<T, K>, 3> {};
} // namespace Eigen
