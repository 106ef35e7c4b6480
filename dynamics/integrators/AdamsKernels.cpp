#include "dynamics/integrators/AdamsKernels.h"

#include <cstring>
#include <type_traits>

namespace rv::adams {

namespace {
// the portable path: a block of W components in fixed-size arrays (packed SSE2 arithmetic held in registers;
// scalar arrays of 8 were spilled to the stack)
template <int W>
void predictBlock(const double* D, Eigen::Index n, int k, const double* gamma, double h, const double* x,
                  Eigen::Index i0, double* increment, double* sum, double* predicted) {
  using Block = Eigen::Array<double, W, 1>;
  Block a = Block::Zero(), s = Block::Zero();
  for (int j = 0; j < k; ++j) {
    const Eigen::Map<const Block> d(D + j * n + i0);
    a += gamma[j] * d;
    s += d;
  }
  a *= h;
  Eigen::Map<Block>(increment + i0) = a;
  Eigen::Map<Block>(sum + i0) = s;
  Eigen::Map<Block>(predicted + i0) = Eigen::Map<const Block>(x + i0) + a;
}

template <int W> void shiftBlock(double* D, Eigen::Index n, int k, const double* f, Eigen::Index i0) {
  using Block = Eigen::Array<double, W, 1>;
  Block c = Eigen::Map<const Block>(f + i0);
  for (int j = 0; j < k; ++j) {
    Eigen::Map<Block> d(D + j * n + i0);
    const Block old = d;
    d = c;
    c -= old;
  }
}

// calls block(width, i0) over [0, n) from `from` on: blocks of 8, then 4, then single components
template <class Block> void inBlocks(Eigen::Index from, Eigen::Index n, Block&& block) {
  Eigen::Index i0 = from;
  for (; i0 + 8 <= n; i0 += 8)
    block(std::integral_constant<int, 8>{}, i0);
  for (; i0 + 4 <= n; i0 += 4)
    block(std::integral_constant<int, 4>{}, i0);
  for (; i0 < n; ++i0)
    block(std::integral_constant<int, 1>{}, i0);
}

void predictPortable(const double* D, Eigen::Index n, int k, const double* gamma, double h, const double* x,
                     Eigen::Index from, double* increment, double* sum, double* predicted) {
  inBlocks(from, n, [&](auto width, Eigen::Index i0) {
    predictBlock<decltype(width)::value>(D, n, k, gamma, h, x, i0, increment, sum, predicted);
  });
}

void shiftPortable(double* D, Eigen::Index n, int k, const double* f, Eigen::Index from) {
  inBlocks(from, n, [&](auto width, Eigen::Index i0) { shiftBlock<decltype(width)::value>(D, n, k, f, i0); });
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RV_ADAMS_AVX2 1
// four doubles in one AVX register (GCC/Clang vector extension: compiled for AVX2 only inside the functions
// below, which run only where avx2Available())
using Packet = double __attribute__((vector_size(32)));

#define RV_AVX2 __attribute__((target("avx2")))
RV_AVX2 inline Packet load(const double* p) {
  Packet v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
RV_AVX2 inline void store(double* p, Packet v) {
  std::memcpy(p, &v, sizeof v);
}

// P on the block of P packets at i0 (4P components): P independent sums per quantity, so that the adder's
// latency overlaps across packets (one packet's sum over k differences is a chain of k additions)
template <int P>
RV_AVX2 inline void predictPackets(const double* D, Eigen::Index n, int k, const double* gamma, double h,
                                   const double* x, Eigen::Index i0, double* increment, double* sum,
                                   double* predicted) {
  Packet a[P] = {}, s[P] = {};
  for (int j = 0; j < k; ++j) {
    const double* d = D + j * n + i0;
    for (int p = 0; p < P; ++p) {
      const Packet dp = load(d + 4 * p);
      a[p] += gamma[j] * dp;
      s[p] += dp;
    }
  }
  for (int p = 0; p < P; ++p) {
    a[p] *= h;
    store(increment + i0 + 4 * p, a[p]);
    store(sum + i0 + 4 * p, s[p]);
    store(predicted + i0 + 4 * p, load(x + i0 + 4 * p) + a[p]);
  }
}

template <int P>
RV_AVX2 inline void shiftPackets(double* D, Eigen::Index n, int k, const double* f, Eigen::Index i0) {
  Packet c[P];
  for (int p = 0; p < P; ++p)
    c[p] = load(f + i0 + 4 * p);
  for (int j = 0; j < k; ++j) {
    double* d = D + j * n + i0;
    for (int p = 0; p < P; ++p) {
      const Packet old = load(d + 4 * p);
      store(d + 4 * p, c[p]);
      c[p] -= old;
    }
  }
}

// P and the shift over blocks of 16 components, then 8, then 4; each returns where it stopped
RV_AVX2 Eigen::Index predictAvx2(const double* D, Eigen::Index n, int k, const double* gamma, double h,
                                 const double* x, double* increment, double* sum, double* predicted) {
  Eigen::Index i0 = 0;
  for (; i0 + 16 <= n; i0 += 16)
    predictPackets<4>(D, n, k, gamma, h, x, i0, increment, sum, predicted);
  for (; i0 + 8 <= n; i0 += 8)
    predictPackets<2>(D, n, k, gamma, h, x, i0, increment, sum, predicted);
  for (; i0 + 4 <= n; i0 += 4)
    predictPackets<1>(D, n, k, gamma, h, x, i0, increment, sum, predicted);
  return i0;
}

RV_AVX2 Eigen::Index shiftAvx2(double* D, Eigen::Index n, int k, const double* f) {
  Eigen::Index i0 = 0;
  for (; i0 + 16 <= n; i0 += 16)
    shiftPackets<4>(D, n, k, f, i0);
  for (; i0 + 8 <= n; i0 += 8)
    shiftPackets<2>(D, n, k, f, i0);
  for (; i0 + 4 <= n; i0 += 4)
    shiftPackets<1>(D, n, k, f, i0);
  return i0;
}
#undef RV_AVX2
#endif
} // namespace

bool avx2Available() {
#ifdef RV_ADAMS_AVX2
  static const bool available = __builtin_cpu_supports("avx2") != 0;
  return available;
#else
  return false;
#endif
}

void predict(const double* D, Eigen::Index n, int k, const double* gamma, double h, const double* x,
             double* increment, double* sum, double* predicted, bool avx2) {
  Eigen::Index from = 0;
#ifdef RV_ADAMS_AVX2
  if (avx2) from = predictAvx2(D, n, k, gamma, h, x, increment, sum, predicted);
#endif
  predictPortable(D, n, k, gamma, h, x, from, increment, sum, predicted);
}

void shift(double* D, Eigen::Index n, int k, const double* f, bool avx2) {
  Eigen::Index from = 0;
#ifdef RV_ADAMS_AVX2
  if (avx2) from = shiftAvx2(D, n, k, f);
#endif
  shiftPortable(D, n, k, f, from);
}

} // namespace rv::adams
