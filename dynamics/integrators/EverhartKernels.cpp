#include "dynamics/integrators/EverhartKernels.h"

#include "dynamics/core/Lanes.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace rv::everhart {

namespace {
// The bodies are written once over packets of P doubles and inlined into one function per target below:
// P = 8 in AVX-512 registers, P = 4 in AVX2 ones or, in the baseline build, as SSE2 pairs. A component's
// arithmetic is the same in a packet as in the scalar tail.
template <int P> using Packet = typename detail::DoubleVector<P>::Type;
template <int P> struct MaskVector; // (a dependent vector_size is not one)
template <> struct MaskVector<4> {
  typedef std::int64_t Type __attribute__((vector_size(4 * sizeof(double)), aligned(alignof(double))));
};
template <> struct MaskVector<8> {
  typedef std::int64_t Type __attribute__((vector_size(8 * sizeof(double)), aligned(alignof(double))));
};
template <int P> using Mask = typename MaskVector<P>::Type;

// B packets at component i: B independent sums, so that the adder's latency overlaps across packets (each
// packet's sum over the n columns is a chain of n additions)
template <int P, int B>
[[gnu::always_inline]] inline void combinePackets(const double* F, Eigen::Index d, int n, const double* c,
                                                  const double* x, double* out, Eigen::Index i) {
  using V = Packet<P>;
  V s[B], term;
#pragma GCC unroll 8
  for (int p = 0; p < B; ++p) {
    std::memcpy(&s[p], F + i + p * P, sizeof term);
    s[p] *= c[0];
  }
  for (int l = 1; l < n; ++l)
#pragma GCC unroll 8
    for (int p = 0; p < B; ++p) {
      std::memcpy(&term, F + l * d + i + p * P, sizeof term);
      s[p] += term * c[l];
    }
#pragma GCC unroll 8
  for (int p = 0; p < B; ++p) {
    if (x != nullptr) {
      std::memcpy(&term, x + i + p * P, sizeof term);
      s[p] += term;
    }
    std::memcpy(out + i + p * P, &s[p], sizeof term);
  }
}

template <int P>
[[gnu::always_inline]] inline void combineBody(const double* F, Eigen::Index d, int n, const double* c,
                                               const double* x, double* out) {
  Eigen::Index i = 0;
  for (; i + 4 * P <= d; i += 4 * P)
    combinePackets<P, 4>(F, d, n, c, x, out, i);
  for (; i + P <= d; i += P)
    combinePackets<P, 1>(F, d, n, c, x, out, i);
  for (; i < d; ++i) {
    double s = F[i] * c[0];
    for (int l = 1; l < n; ++l)
      s += F[l * d + i] * c[l];
    if (x != nullptr) s += x[i];
    out[i] = s;
  }
}

template <int P>
[[gnu::always_inline]] inline void incrementBody(const double* F, Eigen::Index d, int n, const double* b,
                                                 double h, double* out) {
  using V = Packet<P>;
  Eigen::Index i = 0;
  for (; i + P <= d; i += P) {
    V first, s, term;
    std::memcpy(&first, F + i, sizeof first);
    s = first;
    for (int j = 1; j < n; ++j) {
      std::memcpy(&term, F + j * d + i, sizeof term);
      s += b[j] * (term - first);
    }
    s *= h;
    std::memcpy(out + i, &s, sizeof s);
  }
  for (; i < d; ++i) {
    double s = F[i];
    for (int j = 1; j < n; ++j)
      s += b[j] * (F[j * d + i] - F[i]);
    out[i] = s * h;
  }
}

// the lanes in groups of P (width a multiple of P); max and abs as std::max and std::abs do them (the larger
// of a and b is b where a < b, else a; abs clears the sign bit), selected bit by bit
template <int P>
[[gnu::always_inline]] inline void scanBody(const double* f, double* Fj, Eigen::Index components,
                                            Eigen::Index controlled, int width, const std::int64_t* open,
                                            double* change, double* scale) {
  using V = Packet<P>;
  using M = Mask<P>;
  const M noSign = M{} + 0x7fffffffffffffff;
  for (int o = 0; o < width; o += P) {
    V largestChange, largestValue, value, old;
    M keep;
    std::memcpy(&largestChange, change + o, sizeof largestChange);
    std::memcpy(&largestValue, scale + o, sizeof largestValue);
    std::memcpy(&keep, open + o, sizeof keep);
    for (Eigen::Index c = 0; c < components; ++c) {
      const Eigen::Index r = c * width + o;
      std::memcpy(&value, f + r, sizeof value);
      std::memcpy(&old, Fj + r, sizeof old);
      if (c < controlled) {
        const V delta = __builtin_bit_cast(V, __builtin_bit_cast(M, value - old) & noSign),
                magnitude = __builtin_bit_cast(V, __builtin_bit_cast(M, value) & noSign);
        const M moreChange = largestChange < delta, moreValue = largestValue < magnitude;
        largestChange = __builtin_bit_cast(V, (__builtin_bit_cast(M, delta) & moreChange) |
                                                  (__builtin_bit_cast(M, largestChange) & ~moreChange));
        largestValue = __builtin_bit_cast(V, (__builtin_bit_cast(M, magnitude) & moreValue) |
                                                 (__builtin_bit_cast(M, largestValue) & ~moreValue));
      }
      const V updated =
          __builtin_bit_cast(V, (__builtin_bit_cast(M, value) & keep) | (__builtin_bit_cast(M, old) & ~keep));
      std::memcpy(Fj + r, &updated, sizeof updated);
    }
    std::memcpy(change + o, &largestChange, sizeof largestChange);
    std::memcpy(scale + o, &largestValue, sizeof largestValue);
  }
}

void scanEachLane(const double* f, double* Fj, Eigen::Index components, Eigen::Index controlled, int width,
                  const std::int64_t* open, double* change, double* scale) {
  for (Eigen::Index c = 0; c < components; ++c)
    for (int l = 0; l < width; ++l) {
      if (open[l] == 0) continue;
      const Eigen::Index r = c * width + l;
      if (c < controlled) {
        change[l] = std::max(change[l], std::abs(f[r] - Fj[r]));
        scale[l] = std::max(scale[l], std::abs(f[r]));
      }
      Fj[r] = f[r];
    }
}

#if defined(__x86_64__)
#define RV_TARGET(isa) [[gnu::target(isa)]]
#else
#define RV_TARGET(isa) // elsewhere the portable code under these names (available() never chooses them)
#endif
RV_TARGET("avx512f")
void combineAvx512(const double* F, Eigen::Index d, int n, const double* c, const double* x, double* out) {
  combineBody<8>(F, d, n, c, x, out);
}
RV_TARGET("avx2")
void combineAvx2(const double* F, Eigen::Index d, int n, const double* c, const double* x, double* out) {
  combineBody<4>(F, d, n, c, x, out);
}
void combineBaseline(const double* F, Eigen::Index d, int n, const double* c, const double* x, double* out) {
  combineBody<4>(F, d, n, c, x, out);
}
RV_TARGET("avx512f")
void incrementAvx512(const double* F, Eigen::Index d, int n, const double* b, double h, double* out) {
  incrementBody<8>(F, d, n, b, h, out);
}
RV_TARGET("avx2")
void incrementAvx2(const double* F, Eigen::Index d, int n, const double* b, double h, double* out) {
  incrementBody<4>(F, d, n, b, h, out);
}
void incrementBaseline(const double* F, Eigen::Index d, int n, const double* b, double h, double* out) {
  incrementBody<4>(F, d, n, b, h, out);
}
// lanes in groups of 8 or 4 (or one by one when the width is neither's multiple)
RV_TARGET("avx512f")
void scanAvx512(const double* f, double* Fj, Eigen::Index components, Eigen::Index controlled, int width,
                const std::int64_t* open, double* change, double* scale) {
  if (width % 8 == 0) return scanBody<8>(f, Fj, components, controlled, width, open, change, scale);
  if (width % 4 == 0) return scanBody<4>(f, Fj, components, controlled, width, open, change, scale);
  scanEachLane(f, Fj, components, controlled, width, open, change, scale);
}
RV_TARGET("avx2")
void scanAvx2(const double* f, double* Fj, Eigen::Index components, Eigen::Index controlled, int width,
              const std::int64_t* open, double* change, double* scale) {
  if (width % 4 == 0) return scanBody<4>(f, Fj, components, controlled, width, open, change, scale);
  scanEachLane(f, Fj, components, controlled, width, open, change, scale);
}
void scanBaseline(const double* f, double* Fj, Eigen::Index components, Eigen::Index controlled, int width,
                  const std::int64_t* open, double* change, double* scale) {
  if (width % 4 == 0) return scanBody<4>(f, Fj, components, controlled, width, open, change, scale);
  scanEachLane(f, Fj, components, controlled, width, open, change, scale);
}
#undef RV_TARGET

// the function of `path` (of the widest this CPU runs, for Path::widest)
template <class Function> Function onPath(Path path, Function avx512, Function avx2, Function baseline) {
  if (path == Path::widest)
    path = available(Path::avx512) ? Path::avx512 : available(Path::avx2) ? Path::avx2 : Path::baseline;
  return path == Path::avx512 ? avx512 : path == Path::avx2 ? avx2 : baseline;
}
} // namespace

bool available(Path path) {
#if defined(__x86_64__)
  if (path == Path::avx512) return cpuHasAvx512();
  if (path == Path::avx2) return cpuHasAvx2();
#else
  if (path == Path::avx512 || path == Path::avx2) return false;
#endif
  return true;
}

void combine(const double* F, Eigen::Index d, int n, const double* c, const double* x, double* out,
             Path path) {
  onPath(path, &combineAvx512, &combineAvx2, &combineBaseline)(F, d, n, c, x, out);
}

void increment(const double* F, Eigen::Index d, int n, const double* b, double h, double* out, Path path) {
  onPath(path, &incrementAvx512, &incrementAvx2, &incrementBaseline)(F, d, n, b, h, out);
}

void scanLanes(const double* f, double* Fj, Eigen::Index components, Eigen::Index controlled, int width,
               const std::int64_t* open, double* change, double* scale, Path path) {
  onPath(path, &scanAvx512, &scanAvx2, &scanBaseline)(f, Fj, components, controlled, width, open, change,
                                                      scale);
}

} // namespace rv::everhart
