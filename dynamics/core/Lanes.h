// Lanes.h -- W doubles computed together, one per SIMD lane, and Jet, a value with its derivatives along K
// directions: the scalars a model's templated field is evaluated on to integrate W trajectories at once (a
// sweep's points, issue 40), as heyoka's batch mode does (Biscani & Izzo, MNRAS 504 (2021) 2614).
//
// LaneVector<W> is a GCC/Clang vector of W = 4 or 8 doubles: a baseline x86-64 build computes it in SSE2
// pairs; code compiled for AVX2 or AVX-512 (the lane kernels of ModelWithField, chosen at run time on a CPU
// that has them) in 256- or 512-bit registers. Each lane does exactly the arithmetic the scalar path does --
// no fused multiply-add (the project compiles with -ffp-contract=off, and AVX2 code without FMA), the same
// order of operations (Jet's rules are Eigen::AutoDiffScalar's) -- so a lane's result equals the scalar one
// bit for bit. Functions with no vector form (sqrt, sin, ...) are applied lane by lane with the C library's,
// as the scalar path calls them.
#pragma once
#include "dynamics/core/HeldScalar.h"

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rv {

/// The most trajectories a lane kernel integrates at once (AVX-512).
inline constexpr int kMaxLanes = 8;

namespace detail {
// the vector types (a dependent vector_size is not one); aligned as a double, not as the vector: Eigen's
// fixed-size storage aligns its arrays to 16 bytes, which a 32-byte-aligned element would contradict (clang
// refuses it); loads and stores are unaligned ones
template <int W> struct DoubleVector;
template <> struct DoubleVector<4> {
  typedef double Type __attribute__((vector_size(4 * sizeof(double)), aligned(alignof(double))));
};
template <> struct DoubleVector<8> {
  typedef double Type __attribute__((vector_size(8 * sizeof(double)), aligned(alignof(double))));
};
} // namespace detail

/// W doubles, one per lane.
template <int W> struct LaneVector {
  static constexpr int kWidth = W;
  using V = typename detail::DoubleVector<W>::Type;
  V v;
  LaneVector() = default; // uninitialised, as a double: jets are built lane values first (Jet::with)
  LaneVector(double x) : v(V{} + x) {} // NOLINT(google-explicit-constructor): a constant in every lane
  static LaneVector load(const double* p) {
    LaneVector r;
    __builtin_memcpy(&r.v, p, sizeof(V));
    return r;
  }
  void store(double* p) const { __builtin_memcpy(p, &v, sizeof(V)); }
  double operator[](int l) const { return v[l]; }
  LaneVector& operator+=(const LaneVector& o) { return v += o.v, *this; }
  LaneVector& operator-=(const LaneVector& o) { return v -= o.v, *this; }
  LaneVector& operator*=(const LaneVector& o) { return v *= o.v, *this; }
  LaneVector& operator/=(const LaneVector& o) { return v /= o.v, *this; }
};

/// Four lanes: one AVX2 register.
using Lanes = LaneVector<4>;

template <int W> LaneVector<W> operator+(const LaneVector<W>& a, const LaneVector<W>& b) {
  LaneVector<W> r;
  r.v = a.v + b.v;
  return r;
}
template <int W> LaneVector<W> operator-(const LaneVector<W>& a, const LaneVector<W>& b) {
  LaneVector<W> r;
  r.v = a.v - b.v;
  return r;
}
template <int W> LaneVector<W> operator*(const LaneVector<W>& a, const LaneVector<W>& b) {
  LaneVector<W> r;
  r.v = a.v * b.v;
  return r;
}
template <int W> LaneVector<W> operator/(const LaneVector<W>& a, const LaneVector<W>& b) {
  LaneVector<W> r;
  r.v = a.v / b.v;
  return r;
}
/// A number and lanes: the number in every lane (a field's coefficients, one per lane, with a constant).
template <int W> LaneVector<W> operator+(double a, const LaneVector<W>& b) {
  return LaneVector<W>(a) + b;
}
template <int W> LaneVector<W> operator+(const LaneVector<W>& a, double b) {
  return a + LaneVector<W>(b);
}
template <int W> LaneVector<W> operator-(double a, const LaneVector<W>& b) {
  return LaneVector<W>(a) - b;
}
template <int W> LaneVector<W> operator-(const LaneVector<W>& a, double b) {
  return a - LaneVector<W>(b);
}
template <int W> LaneVector<W> operator*(double a, const LaneVector<W>& b) {
  return LaneVector<W>(a) * b;
}
template <int W> LaneVector<W> operator*(const LaneVector<W>& a, double b) {
  return a * LaneVector<W>(b);
}
template <int W> LaneVector<W> operator/(double a, const LaneVector<W>& b) {
  return LaneVector<W>(a) / b;
}
template <int W> LaneVector<W> operator/(const LaneVector<W>& a, double b) {
  return a / LaneVector<W>(b);
}
template <int W> LaneVector<W> operator-(const LaneVector<W>& a) {
  LaneVector<W> r;
  r.v = -a.v;
  return r;
}
template <int W> LaneVector<W> operator+(const LaneVector<W>& a) {
  return a;
}
template <int W, class F> LaneVector<W> eachLane(const LaneVector<W>& a, F f) {
  LaneVector<W> r;
  for (int l = 0; l < W; ++l)
    r.v[l] = f(a.v[l]);
  return r;
}
/// A square root is correctly rounded (IEEE 754), so SSE2's packed one gives std::sqrt's bits: two lanes at a
/// time (a vector sqrt of the target's width has no portable spelling; lane by lane, each call also checked
/// for errno, and the rattleback's kernel spent 6 % there).
template <int W> LaneVector<W> sqrt(const LaneVector<W>& a) {
#if defined(__SSE2__)
  LaneVector<W> r;
  for (int l = 0; l < W; l += 2) {
    __m128d pair;
    __builtin_memcpy(&pair, reinterpret_cast<const double*>(&a.v) + l, sizeof pair);
    pair = _mm_sqrt_pd(pair);
    __builtin_memcpy(reinterpret_cast<double*>(&r.v) + l, &pair, sizeof pair);
  }
  return r;
#else
  return eachLane(a, [](double x) { return std::sqrt(x); });
#endif
}
template <int W> LaneVector<W> sin(const LaneVector<W>& a) {
  return eachLane(a, [](double x) { return std::sin(x); });
}
template <int W> LaneVector<W> cos(const LaneVector<W>& a) {
  return eachLane(a, [](double x) { return std::cos(x); });
}
template <int W> LaneVector<W> exp(const LaneVector<W>& a) {
  return eachLane(a, [](double x) { return std::exp(x); });
}
template <int W> LaneVector<W> log(const LaneVector<W>& a) {
  return eachLane(a, [](double x) { return std::log(x); });
}

/// A value and its derivatives along K directions (forward-mode differentiation), with the rules of
/// Eigen::AutoDiffScalar written out in its order of operations, derivative by derivative, so that a lane's
/// tangents equal the scalar path's (ModelWithField::tangentRhs, its K-vector AutoDiff pass) bit for bit.
/// A constant is a double, or one value per lane (a coefficient that differs between lanes).
template <class T, int K = 1> struct Jet {
  T v;
  std::array<T, K> d; ///< none for K = 0: the value alone (a plain field on lanes)
  /// Uninitialised, as AutoDiffScalar: a jet of 8 lanes and 6 directions is 448 bytes, which a field's
  /// temporaries would otherwise zero each time before their values are written.
  Jet() = default;
  Jet(double x) : v(x) { fill(T(0.0)); } // NOLINT(google-explicit-constructor): a constant
  /// A constant of one value per lane (a coefficient that differs between lanes).
  template <class C>
  requires(std::is_same_v<C, T> && !std::is_arithmetic_v<C>) explicit Jet(const C& value) : v(value) {
    fill(T(0.0));
  }
  Jet& operator+=(const Jet& o) { return *this = *this + o; }
  Jet& operator-=(const Jet& o) { return *this = *this - o; }
  Jet& operator*=(const Jet& o) { return *this = *this * o; }
  Jet& operator/=(const Jet& o) { return *this = *this / o; }
  /// The jet with value `value` and derivatives d[c] = f(c).
  template <class F> [[gnu::always_inline]] static Jet with(T value, F f) {
    Jet r;
    r.v = value;
#pragma GCC unroll 16 // GCC -O2 leaves a loop of K rolled, and the jet in memory (bench README)
    for (int c = 0; c < K; ++c)
      r.d[c] = f(c);
    return r;
  }

private:
  void fill(const T& x) {
#pragma GCC unroll 16
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

/// r where `coefficient` is not 0, else 0 with no derivatives, lane by lane: a term c f(x) that vanishes with
/// its coefficient c although f is not finite everywhere (BallOnSurface.h's vanishingWith).
template <class T, int K> Jet<T, K> keptWhereNonzero(const T& coefficient, Jet<T, K> r) {
  if constexpr (std::is_arithmetic_v<T>) {
    return coefficient != 0.0 ? r : Jet<T, K>(0.0);
  } else {
    using V = typename T::V;
    const auto kept = coefficient.v != V{}; // all ones where the coefficient is not 0
    const auto only = [&](T& x) { x.v = kept ? x.v : V{}; };
    only(r.v);
    for (T& d : r.d)
      only(d);
    return r;
  }
}

/// Whether this CPU runs the AVX2 lane kernels (else they run as SSE2 pairs).
inline bool cpuHasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

/// Whether this CPU runs the AVX-512 lane kernels of eight lanes.
inline bool cpuHasAvx512() {
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  return avx512;
}

/// How many trajectories a batch takes on this CPU: 8 with AVX-512, else 4.
inline int laneWidth() {
  return cpuHasAvx512() ? 8 : 4;
}

/// What `rollviz info` says of the lanes.
inline std::string laneDescription() {
  if (cpuHasAvx512()) return "8 trajectories per batch, one AVX-512 register (512 bits) of doubles";
  return "4 trajectories per batch, " + std::string(cpuHasAvx2()
                                                        ? "one AVX2 register (256 bits) of doubles"
                                                        : "two SSE2 pairs of doubles (no AVX2 here)");
}

} // namespace rv

namespace Eigen {
template <int W> struct NumTraits<rv::LaneVector<W>> : rv::HeldScalarTraits<rv::LaneVector<W>, 1> {};
template <class T, int K> struct NumTraits<rv::Jet<T, K>> : rv::HeldScalarTraits<rv::Jet<T, K>, 3> {};
// a vector of jets times a coefficient of one value per lane (as a vector of AutoDiffScalar times a double)
template <int W, int K, typename BinaryOp>
struct ScalarBinaryOpTraits<rv::LaneVector<W>, rv::Jet<rv::LaneVector<W>, K>, BinaryOp> {
  using ReturnType = rv::Jet<rv::LaneVector<W>, K>;
};
template <int W, int K, typename BinaryOp>
struct ScalarBinaryOpTraits<rv::Jet<rv::LaneVector<W>, K>, rv::LaneVector<W>, BinaryOp> {
  using ReturnType = rv::Jet<rv::LaneVector<W>, K>;
};
} // namespace Eigen
