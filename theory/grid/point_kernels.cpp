#include "theory/grid/point_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "theory/numerics/vector_clones.hpp"

namespace granmix::theory {

GRANMIX_VECTOR_CLONES void laguerre_rows(const double* x, std::size_t count, std::size_t modes, double* L) {
  for (std::size_t p = 0; p < count; ++p) L[p] = 1.0;
  if (modes > 1)
    for (std::size_t p = 0; p < count; ++p) L[count + p] = 2.5 - x[p];
  for (std::size_t n = 1; n + 1 < modes; ++n) {
    const double a = 2.0 * double(n) + 2.5, b = double(n) + 1.5, inv = 1.0 / double(n + 1);
    const double *Ln = L + n * count, *Lm = L + (n - 1) * count;
    double* Lp = L + (n + 1) * count;
    for (std::size_t p = 0; p < count; ++p) Lp[p] = ((a - x[p]) * Ln[p] - b * Lm[p]) * inv;
  }
}

GRANMIX_VECTOR_CLONES void weight_rows(const double* x, std::size_t count, double x0, std::size_t first, std::size_t rows, double* B) {
  thread_local std::vector<double> r;  // reused: a fresh one costs page faults at every call
  r.resize(count);
  for (std::size_t p = 0; p < count; ++p) r[p] = 1.0 / std::sqrt(x[p] + x0);
  for (std::size_t m = first; m < rows; ++m)
    for (std::size_t p = 0; p < count; ++p) B[m * count + p] *= r[p];
}

namespace {

// Where weighted_laguerre_chunk's rows go: stored (Store), or taken at once into the loss rows (Loss).
struct Store {
  double* B;
  [[gnu::always_inline]] void operator()(std::size_t at, std::size_t, double v) const { B[at] = v; }
};
struct Loss {
  const double *B, *wx, *wcc;  // wx, wcc from the chunk's first point
  double* loss;
  [[gnu::always_inline]] void operator()(std::size_t at, std::size_t j, double v) const { loss[at] = B[at] * wx[j] - v * wcc[j]; }
};

// One chunk of weighted_laguerre_rows: n points from x, row m's value of point j handed to the sink at m·count + j
// (pointers from the chunk's first point). Inlined with n the full chunk's compile-time 32 (the loops unrolled into
// whole vectors) and with the last chunk's run-time n.
template <class Count, class Sink>
[[gnu::always_inline]] inline void weighted_laguerre_chunk(const double* xs, Count n, std::size_t count, double x0, std::size_t modes, Sink sink) {
  constexpr std::size_t chunk = 32;
  double r[chunk], prev[chunk], cur[chunk];
  for (std::size_t j = 0; j < n; ++j) r[j] = 1.0 / std::sqrt(xs[j] + x0);
  for (std::size_t j = 0; j < n; ++j) prev[j] = 1.0, sink(j, j, 1.0 * r[j]);
  if (modes > 1)
    for (std::size_t j = 0; j < n; ++j) cur[j] = 2.5 - xs[j], sink(count + j, j, cur[j] * r[j]);
  for (std::size_t m = 1; m + 1 < modes; ++m) {
    const double a = 2.0 * double(m) + 2.5, b = double(m) + 1.5, inv = 1.0 / double(m + 1);
    const std::size_t row = (m + 1) * count;
    for (std::size_t j = 0; j < n; ++j) {
      const double next = ((a - xs[j]) * cur[j] - b * prev[j]) * inv;
      prev[j] = cur[j], cur[j] = next, sink(row + j, j, next * r[j]);
    }
  }
}

// weighted_laguerre_chunk over all points in chunks of 32 (their recurrence and weights stay in registers and L1).
template <class MakeSink>
[[gnu::always_inline]] inline void weighted_laguerre_chunks(const double* x, std::size_t count, double x0, std::size_t modes, MakeSink make) {
  constexpr std::size_t chunk = 32;
  std::size_t p0 = 0;
  for (; p0 + chunk <= count; p0 += chunk) weighted_laguerre_chunk(x + p0, std::integral_constant<std::size_t, chunk>{}, count, x0, modes, make(p0));
  if (p0 < count) weighted_laguerre_chunk(x + p0, count - p0, count, x0, modes, make(p0));
}

}  // namespace

GRANMIX_VECTOR_CLONES void weighted_laguerre_rows(const double* x, std::size_t count, double x0, std::size_t modes, double* B) {
  weighted_laguerre_chunks(x, count, x0, modes, [B](std::size_t p0) {
    return Store{B + p0};
  });
}

GRANMIX_VECTOR_CLONES void collision_weighted_loss_rows(const double* x1, std::size_t count, double x0, std::size_t size, const double* B,
                                                        const double* wx, const double* wcc, double* loss) {
  for (std::size_t p = 0; p < count; ++p) loss[p] = B[p] * wx[p] - wcc[p];  // row 0, the constant 1 (1·wcc = wcc exactly)
  weighted_laguerre_chunks(x1, count, x0, size - 1, [=](std::size_t p0) {
    return Loss{B + count + p0, wx + p0, wcc + p0, loss + count + p0};
  });
}

GRANMIX_VECTOR_CLONES void loss_rows(const double* B, const double* B1, const double* wx, const double* wcc, std::size_t n, std::size_t count,
                                     double* loss) {
  for (std::size_t m = 0; m < n; ++m)
    for (std::size_t p = 0; p < count; ++p) loss[m * count + p] = B[m * count + p] * wx[p] - B1[m * count + p] * wcc[p];
}

namespace {

// The compiler's vector extension, two or four doubles, and its unaligned, aliasing form for loads and stores.
using Pair = double __attribute__((vector_size(16)));
using PairMem = double __attribute__((vector_size(16), aligned(8), may_alias));
using Quad = double __attribute__((vector_size(32)));
using QuadMem = double __attribute__((vector_size(32), aligned(8), may_alias));

// The K vectors of four points at offset `off` of R rows of a and C rows of b, W doubles per vector (unaligned loads).
template <class Vec, class Mem, int R, int C, int K>
[[gnu::always_inline]] inline void load_points(const double* const (&ra)[R], const double* const (&rb)[C], std::size_t off, Vec (&x)[R][K],
                                               Vec (&y)[C][K]) {
  constexpr int W = 4 / K;
  for (int k = 0; k < K; ++k) {
    for (int i = 0; i < R; ++i) x[i][k] = *reinterpret_cast<const Mem*>(ra[i] + off + std::size_t(k * W));
    for (int j = 0; j < C; ++j) y[j][k] = *reinterpret_cast<const Mem*>(rb[j] + off + std::size_t(k * W));
  }
}

// The row pointers of an R × C block: rows q … q + R − 1 of a and m … m + C − 1 of b, from point `off`.
template <int R, int C>
[[gnu::always_inline]] inline void block_rows(const double* a, const double* b, std::size_t count, std::size_t q, std::size_t m, std::size_t off,
                                              const double* (&ra)[R], const double* (&rb)[C]) {
  for (int i = 0; i < R; ++i) ra[i] = a + (q + std::size_t(i)) * count + off;
  for (int j = 0; j < C; ++j) rb[j] = b + (m + std::size_t(j)) * count + off;
}

// The R × C block of entries from row q of a and row m of b. Each entry keeps four partial sums, point l in lane
// (l − first) mod 4 — one Quad, or two Pairs: the same operations in the same order for either width.
template <class Vec, class Mem, int Sh, int R, int C>
[[gnu::always_inline]] inline void dot_block(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first,
                                             std::size_t len, const double* c, std::size_t shapes, std::size_t q, std::size_t m, double* out) {
  if constexpr (Sh > 0) shapes = Sh;
  constexpr int W = int(sizeof(Vec) / sizeof(double)), K = 4 / W;  // vectors per four points
  Vec sum[R][C][K] = {};
  const double* ra[R];
  const double* rb[C];
  block_rows<R, C>(a, b, count, q, m, 0, ra, rb);
  const std::size_t end = first + len, whole = first + len / 4 * 4;
  for (std::size_t l = first; l < whole; l += 4) {
    Vec x[R][K], y[C][K];
    load_points<Vec, Mem, R, C, K>(ra, rb, l, x, y);
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j)
        for (int k = 0; k < K; ++k) sum[i][j][k] += x[i][k] * y[j][k];
  }
  for (std::size_t l = whole; l < end; ++l) {  // the last len mod 4 points, each into its lane
    const int e = int(l - whole);
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j) sum[i][j][e / W][e % W] += ra[i][l] * rb[j][l];
  }
  // Each entry's lanes summed as (s₀ + s₂) + (s₁ + s₃) — the pair h = (s₀ + s₂, s₁ + s₃), then its two lanes, two
  // entries at once — and c[s] times the sum added to shape s's entry.
  for (int i = 0; i < R; ++i) {
    Pair h[C];
    for (int j = 0; j < C; ++j) {
      if constexpr (K == 1)
        h[j] = __builtin_shufflevector(sum[i][j][0], sum[i][j][0], 0, 1) + __builtin_shufflevector(sum[i][j][0], sum[i][j][0], 2, 3);
      else
        h[j] = sum[i][j][0] + sum[i][j][1];
    }
    double* row = out + (q + std::size_t(i)) * n + m;
    if constexpr (C == 1) {
      const double t = h[0][0] + h[0][1];
      for (std::size_t s = 0; s < shapes; ++s) row[s * n * n] += c[s] * t;
    } else {
      for (int j = 0; j < C; j += 2) {
        const Pair t = __builtin_shufflevector(h[j], h[j + 1], 0, 2) + __builtin_shufflevector(h[j], h[j + 1], 1, 3);
        for (std::size_t s = 0; s < shapes; ++s) {
          PairMem& to = *reinterpret_cast<PairMem*>(row + s * n * n + j);
          to = to + c[s] * t;
        }
      }
    }
  }
}

template <class Vec, class Mem, int Sh, int R>
[[gnu::always_inline]] inline void dot_rows(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first,
                                            std::size_t len, const double* c, std::size_t shapes, std::size_t q, double* out) {
  constexpr int C = sizeof(Vec) == sizeof(Quad) ? 4 : 2;  // the block's accumulators within 16 registers
  std::size_t m = 0;
  for (; m + C <= n; m += C) dot_block<Vec, Mem, Sh, R, C>(a, b, count, n, first, len, c, shapes, q, m, out);
  for (; m < n; ++m) dot_block<Vec, Mem, Sh, R, 1>(a, b, count, n, first, len, c, shapes, q, m, out);
}

template <class Vec, class Mem, int Sh>
[[gnu::always_inline]] inline void dot_products_of(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first,
                                                   std::size_t len, const double* c, std::size_t shapes, double* out) {
  std::size_t q = 0;
  for (; q + 2 <= n; q += 2) dot_rows<Vec, Mem, Sh, 2>(a, b, count, n, first, len, c, shapes, q, out);
  if (q < n) dot_rows<Vec, Mem, Sh, 1>(a, b, count, n, first, len, c, shapes, q, out);
}

// One or three shapes (the tracer problem's, the history tables') with the shape loop unrolled; any other count looped.
template <class Vec, class Mem>
[[gnu::always_inline]] inline void dot_products(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first,
                                                std::size_t len, const double* c, std::size_t shapes, double* out) {
  if (shapes == 1) return dot_products_of<Vec, Mem, 1>(a, b, count, n, first, len, c, shapes, out);
  if (shapes == 3) return dot_products_of<Vec, Mem, 3>(a, b, count, n, first, len, c, shapes, out);
  dot_products_of<Vec, Mem, 0>(a, b, count, n, first, len, c, shapes, out);
}

// shaped_products' block of R rows of a by C rows of b at one group of four h: each entry's four lanes in one Quad, or
// two Pairs; Fma(x, y, acc) = x·y + acc rounded once, lane by lane.
template <class Vec, class Mem, class Fma, int R, int C>
[[gnu::always_inline]] inline void shaped_block(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride,
                                                std::size_t L, const double* c, std::size_t shapes, std::size_t hb, std::size_t q, std::size_t m,
                                                double* lanes, Fma fma) {
  constexpr int W = int(sizeof(Vec) / sizeof(double)), K = 4 / W;
  Vec t[R][C][K] = {};
  const double* ra[R];
  const double* rb[C];
  block_rows<R, C>(a, b, count, q, m, hb, ra, rb);
  for (std::size_t l = 0, off = 0; l < L; ++l, off += stride) {
    Vec x[R][K], y[C][K];
    load_points<Vec, Mem, R, C, K>(ra, rb, off, x, y);
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j)
        for (int k = 0; k < K; ++k) t[i][j][k] = fma(x[i][k], y[j][k], t[i][j][k]);
  }
  for (std::size_t s = 0; s < shapes; ++s) {
    Vec w[K];
    for (int k = 0; k < K; ++k) w[k] = *reinterpret_cast<const Mem*>(c + s * stride + hb + std::size_t(k * W));
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j) {
        double* to = lanes + ((s * n + q + std::size_t(i)) * n + m + std::size_t(j)) * 4;
        for (int k = 0; k < K; ++k) {
          Mem& lane = *reinterpret_cast<Mem*>(to + k * W);
          lane = fma(w[k], t[i][j][k], lane);
        }
      }
  }
}

template <class Vec, class Mem, class Fma, int R = 2>
[[gnu::always_inline]] inline void shaped_products_of(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride,
                                                      std::size_t L, const double* c, std::size_t shapes, double* lanes, Fma fma) {
  constexpr int C = sizeof(Vec) == sizeof(Quad) ? 4 : 2;  // the block's accumulators within 16 registers (R = 2)
  for (std::size_t hb = 0; hb < stride; hb += 4) {  // one group of four h at a time: its points stay in the cache
    std::size_t q = 0;
    for (; q + R <= n; q += R) {
      std::size_t m = 0;
      for (; m + C <= n; m += C) shaped_block<Vec, Mem, Fma, R, C>(a, b, count, n, stride, L, c, shapes, hb, q, m, lanes, fma);
      for (; m < n; ++m) shaped_block<Vec, Mem, Fma, R, 1>(a, b, count, n, stride, L, c, shapes, hb, q, m, lanes, fma);
    }
    for (; q + 2 <= n; q += 2) {
      std::size_t m = 0;
      for (; m + C <= n; m += C) shaped_block<Vec, Mem, Fma, 2, C>(a, b, count, n, stride, L, c, shapes, hb, q, m, lanes, fma);
      for (; m < n; ++m) shaped_block<Vec, Mem, Fma, 2, 1>(a, b, count, n, stride, L, c, shapes, hb, q, m, lanes, fma);
    }
    for (; q < n; ++q)
      for (std::size_t m = 0; m < n; ++m) shaped_block<Vec, Mem, Fma, 1, 1>(a, b, count, n, stride, L, c, shapes, hb, q, m, lanes, fma);
  }
}

}  // namespace

void shaped_products_baseline(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L,
                              const double* c, std::size_t shapes, double* lanes) {
  shaped_products_of<Pair, PairMem>(a, b, count, n, stride, L, c, shapes, lanes,
                                    [](Pair x, Pair y, Pair acc) { return Pair{std::fma(x[0], y[0], acc[0]), std::fma(x[1], y[1], acc[1])}; });
}

void reduce_lanes(const double* lanes, std::size_t entries, double* out) {
  for (std::size_t e = 0; e < entries; ++e) out[e] += (lanes[4 * e] + lanes[4 * e + 2]) + (lanes[4 * e + 1] + lanes[4 * e + 3]);
}

void row_products_baseline(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first, std::size_t len,
                           const double* c, std::size_t shapes, double* out) {
  dot_products<Pair, PairMem>(a, b, count, n, first, len, c, shapes, out);
}

// AVX2 alone (no FMA, no BMI: exactly what the processor check below asks for).
#if defined(__x86_64__)
__attribute__((target("avx2"))) void row_products_avx2(const double* a, const double* b, std::size_t count, std::size_t n,
                                                                   std::size_t first, std::size_t len, const double* c, std::size_t shapes,
                                                                   double* out) {
  dot_products<Quad, QuadMem>(a, b, count, n, first, len, c, shapes, out);
}
bool avx2_available() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}
namespace {
struct FmaAvx2 {
  __attribute__((target("avx2,fma"))) Quad operator()(Quad x, Quad y, Quad acc) const { return _mm256_fmadd_pd(x, y, acc); }
};
}  // namespace
__attribute__((target("avx2,fma"))) void shaped_products_avx2(const double* a, const double* b, std::size_t count, std::size_t n,
                                                              std::size_t stride, std::size_t L, const double* c, std::size_t shapes,
                                                              double* lanes) {
  shaped_products_of<Quad, QuadMem>(a, b, count, n, stride, L, c, shapes, lanes, FmaAvx2{});
}
// The AVX2 kernel's operations (FmaAvx2, inlined: its target a subset of this one's) with 32 registers: 4 rows a block.
__attribute__((target("avx2,fma,avx512f,avx512vl"))) void shaped_products_avx512(const double* a, const double* b, std::size_t count,
                                                                                  std::size_t n, std::size_t stride, std::size_t L,
                                                                                  const double* c, std::size_t shapes, double* lanes) {
  shaped_products_of<Quad, QuadMem, FmaAvx2, 4>(a, b, count, n, stride, L, c, shapes, lanes, FmaAvx2{});
}
bool avx512_available() {
  static const bool yes = avx2_fma_available() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  return yes;
}
bool avx2_fma_available() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}
#else
void shaped_products_avx2(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L, const double* c,
                          std::size_t shapes, double* lanes) {
  shaped_products_baseline(a, b, count, n, stride, L, c, shapes, lanes);
}
void shaped_products_avx512(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L, const double* c,
                            std::size_t shapes, double* lanes) {
  shaped_products_baseline(a, b, count, n, stride, L, c, shapes, lanes);
}
bool avx512_available() { return false; }
bool avx2_fma_available() { return false; }
void row_products_avx2(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first, std::size_t len, const double* c,
                       std::size_t shapes, double* out) {
  row_products_baseline(a, b, count, n, first, len, c, shapes, out);
}
bool avx2_available() { return false; }
#endif

void shaped_products(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L, const double* c,
                     std::size_t shapes, double* lanes) {
  if (avx512_available())
    shaped_products_avx512(a, b, count, n, stride, L, c, shapes, lanes);
  else if (avx2_fma_available())
    shaped_products_avx2(a, b, count, n, stride, L, c, shapes, lanes);
  else
    shaped_products_baseline(a, b, count, n, stride, L, c, shapes, lanes);
}

void row_products(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first, std::size_t len, const double* c,
                  std::size_t shapes, double* out) {
  if (avx2_available())
    row_products_avx2(a, b, count, n, first, len, c, shapes, out);
  else
    row_products_baseline(a, b, count, n, first, len, c, shapes, out);
}

}  // namespace granmix::theory
