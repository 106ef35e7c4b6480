#include "dynamics/integrators/LaneStages.h"

#include "dynamics/core/Lanes.h"

#include <cstring>

namespace rv::lanes {

namespace {
// lanes g..g+P-1 of every row as one packet of P doubles (AVX-512, AVX2, or SSE2 pairs in the baseline
// build); each element as the scalar tail computes it
template <int P>
[[gnu::always_inline]] inline void stageBody(const double* x, const double* a, const double* c,
                                             const double* const* k, int terms, Eigen::Index rows, int width,
                                             double* out) {
  using V = typename detail::DoubleVector<P>::Type;
  for (int g = 0; g + P <= width; g += P) {
    V factor, s, t;
    std::memcpy(&factor, a + g, sizeof factor);
    for (Eigen::Index r = 0; r < rows; ++r) {
      const Eigen::Index i = r * width + g;
      std::memcpy(&s, k[0] + i, sizeof s);
      s *= c[0];
      for (int j = 1; j < terms; ++j) {
        std::memcpy(&t, k[j] + i, sizeof t);
        s += t * c[j];
      }
      s *= factor;
      if (x != nullptr) {
        std::memcpy(&t, x + i, sizeof t);
        s += t;
      }
      std::memcpy(out + i, &s, sizeof s);
    }
  }
}

void stageEachLane(const double* x, const double* a, const double* c, const double* const* k, int terms,
                   Eigen::Index rows, int width, double* out) {
  for (Eigen::Index i = 0; i < rows * width; ++i) {
    double s = k[0][i] * c[0];
    for (int j = 1; j < terms; ++j)
      s += k[j][i] * c[j];
    s *= a[i % width];
    out[i] = x != nullptr ? x[i] + s : s;
  }
}

#if defined(__x86_64__)
#define RV_TARGET(isa) [[gnu::target(isa)]]
#else
#define RV_TARGET(isa)
#endif
RV_TARGET("avx512f")
void stageAvx512(const double* x, const double* a, const double* c, const double* const* k, int terms,
                 Eigen::Index rows, int width, double* out) {
  if (width % 8 == 0) return stageBody<8>(x, a, c, k, terms, rows, width, out);
  if (width % 4 == 0) return stageBody<4>(x, a, c, k, terms, rows, width, out);
  stageEachLane(x, a, c, k, terms, rows, width, out);
}
RV_TARGET("avx2")
void stageAvx2(const double* x, const double* a, const double* c, const double* const* k, int terms,
               Eigen::Index rows, int width, double* out) {
  if (width % 4 == 0) return stageBody<4>(x, a, c, k, terms, rows, width, out);
  stageEachLane(x, a, c, k, terms, rows, width, out);
}
void stageBaseline(const double* x, const double* a, const double* c, const double* const* k, int terms,
                   Eigen::Index rows, int width, double* out) {
  if (width % 4 == 0) return stageBody<4>(x, a, c, k, terms, rows, width, out);
  stageEachLane(x, a, c, k, terms, rows, width, out);
}
#undef RV_TARGET
} // namespace

void stage(const double* x, const double* a, const double* c, const double* const* k, int terms,
           Eigen::Index rows, int width, double* out, Path path) {
  if (path == Path::widest) path = cpuHasAvx512() ? Path::avx512 : cpuHasAvx2() ? Path::avx2 : Path::baseline;
  const auto run = path == Path::avx512 ? &stageAvx512 : path == Path::avx2 ? &stageAvx2 : &stageBaseline;
  run(x, a, c, k, terms, rows, width, out);
}

} // namespace rv::lanes
