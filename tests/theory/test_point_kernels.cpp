// The Galerkin pair integrals' per-point loops (theory/grid/point_kernels.hpp) give the same numbers in every build: each
// is checked bit for bit against a plain scalar loop that does the documented operations in the documented order (this
// file is compiled without FMA contraction, tests/CMakeLists.txt), and row_products' baseline (SSE2) and AVX2 builds
// against each other. The elementwise loops run whichever build this processor selects (AVX-512, AVX2 or baseline).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "theory/grid/point_kernels.hpp"

using namespace granmix::theory;

namespace {

std::vector<double> uniform(std::size_t n, double lo, double hi, unsigned seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> v(n);
  for (double& x : v) x = u(g);
  return v;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// row_products' documented sums: entry (q, m) of shape s gains c[s]·((s₀ + s₂) + (s₁ + s₃)), s_e = Σ a·b over
// l = first + e, first + e + 4, … in order.
std::vector<double> products_by_hand(const std::vector<double>& a, const std::vector<double>& b, std::size_t count, std::size_t n,
                                     std::size_t first, std::size_t len, const std::vector<double>& c, std::vector<double> out) {
  for (std::size_t q = 0; q < n; ++q)
    for (std::size_t m = 0; m < n; ++m) {
      double lane[4] = {0.0, 0.0, 0.0, 0.0};
      for (std::size_t e = 0; e < 4; ++e)
        for (std::size_t l = first + e; l < first + len; l += 4) lane[e] += a[q * count + l] * b[m * count + l];
      const double t = (lane[0] + lane[2]) + (lane[1] + lane[3]);
      for (std::size_t s = 0; s < c.size(); ++s) out[(s * n + q) * n + m] += c[s] * t;
    }
  return out;
}

}  // namespace

TEST_CASE("point kernels: the elementwise loops equal plain scalar loops bit for bit", "[theory]") {
  for (std::size_t count : {1u, 7u, 960u, 2161u}) {
    const std::vector<double> x = uniform(count, 0.0, 40.0, 11 + count);
    for (std::size_t modes : {1u, 2u, 7u, 16u}) {
      std::vector<double> L(modes * count), ref(modes * count);
      laguerre_rows(x.data(), count, modes, L.data());
      for (std::size_t p = 0; p < count; ++p) {
        ref[p] = 1.0;
        if (modes > 1) ref[count + p] = 2.5 - x[p];
        for (std::size_t j = 1; j + 1 < modes; ++j)
          ref[(j + 1) * count + p] = ((2.0 * double(j) + 2.5 - x[p]) * ref[j * count + p] - (double(j) + 1.5) * ref[(j - 1) * count + p]) *
                                     (1.0 / double(j + 1));
      }
      CHECK(same_bits(L, ref));
    }
    for (std::size_t modes : {1u, 2u, 7u, 15u}) {  // weighted_laguerre_rows: laguerre_rows then weight_rows, one pass
      std::vector<double> W(modes * count), ref(modes * count);
      weighted_laguerre_rows(x.data(), count, 0.37, modes, W.data());
      laguerre_rows(x.data(), count, modes, ref.data());
      weight_rows(x.data(), count, 0.37, 0, modes, ref.data());
      CHECK(same_bits(W, ref));
    }
    const std::size_t rows = 8;
    std::vector<double> B = uniform(rows * count, -3.0, 3.0, 21 + count), ref = B;
    weight_rows(x.data(), count, 0.37, 1, rows, B.data());
    for (std::size_t m = 1; m < rows; ++m)
      for (std::size_t p = 0; p < count; ++p) ref[m * count + p] *= 1.0 / std::sqrt(x[p] + 0.37);
    CHECK(same_bits(B, ref));
    const std::vector<double> B1 = uniform(rows * count, -3.0, 3.0, 31 + count), wx = uniform(count, 0.0, 1.0, 41 + count),
                              wcc = uniform(count, -1.0, 1.0, 51 + count);
    std::vector<double> loss(rows * count), loss_ref(rows * count);
    loss_rows(B.data(), B1.data(), wx.data(), wcc.data(), rows, count, loss.data());
    for (std::size_t m = 0; m < rows; ++m)
      for (std::size_t p = 0; p < count; ++p) loss_ref[m * count + p] = B[m * count + p] * wx[p] - B1[m * count + p] * wcc[p];
    CHECK(same_bits(loss, loss_ref));
    // collision_weighted_loss_rows: the collision-weighted basis at x1 (1, then weighted_laguerre_rows) and loss_rows.
    const std::vector<double> x1 = uniform(count, 0.0, 40.0, 61 + count);
    std::vector<double> Bx1(rows * count, 1.0), fused(rows * count), fused_ref(rows * count);
    weighted_laguerre_rows(x1.data(), count, 0.37, rows - 1, Bx1.data() + count);
    loss_rows(B.data(), Bx1.data(), wx.data(), wcc.data(), rows, count, fused_ref.data());
    collision_weighted_loss_rows(x1.data(), count, 0.37, rows, B.data(), wx.data(), wcc.data(), fused.data());
    CHECK(same_bits(fused, fused_ref));
  }
}

TEST_CASE("point kernels: row_products sums in its documented order in every build", "[theory]") {
  const std::size_t count = 1000;
  const std::vector<double> a = uniform(16 * count, -2.0, 2.0, 5), b = uniform(16 * count, -2.0, 2.0, 6);
  for (std::size_t n : {1u, 3u, 5u, 8u, 10u, 16u})
    for (auto [first, len] : {std::pair<std::size_t, std::size_t>{0, 12}, {24, 24}, {100, 37}, {3, 2}, {0, 960}})
      for (std::size_t shapes : {1u, 3u}) {
        const std::vector<double> c = uniform(shapes, -1.5, 1.5, unsigned(7 + n + len));
        const std::vector<double> start = uniform(shapes * n * n, -1.0, 1.0, unsigned(9 + n));  // the sums accumulate
        const std::vector<double> ref = products_by_hand(a, b, count, n, first, len, c, start);
        std::vector<double> base = start, wide = start;
        row_products_baseline(a.data(), b.data(), count, n, first, len, c.data(), shapes, base.data());
        INFO("n " << n << ", points " << first << " + " << len << ", shapes " << shapes);
        CHECK(same_bits(base, ref));
        if (avx2_available()) {
          row_products_avx2(a.data(), b.data(), count, n, first, len, c.data(), shapes, wide.data());
          CHECK(same_bits(wide, ref));
        }
      }
}

namespace {

// shaped_products' documented sums (point_kernels.hpp): per h, t = Σ_l a·b by fused multiply-adds in order of l, then
// lane h mod 4 of entry (s, q, m) ← fma(c[s·stride + h], t, lane), h in order.
std::vector<double> shaped_by_hand(const std::vector<double>& a, const std::vector<double>& b, std::size_t count, std::size_t n,
                                   std::size_t stride, std::size_t L, const std::vector<double>& c, std::size_t shapes, std::vector<double> lanes) {
  for (std::size_t s = 0; s < shapes; ++s)
    for (std::size_t q = 0; q < n; ++q)
      for (std::size_t m = 0; m < n; ++m)
        for (std::size_t h = 0; h < stride; ++h) {
          double t = 0.0;
          for (std::size_t l = 0; l < L; ++l) t = std::fma(a[q * count + l * stride + h], b[m * count + l * stride + h], t);
          double& lane = lanes[((s * n + q) * n + m) * 4 + h % 4];
          lane = std::fma(c[s * stride + h], t, lane);
        }
  return lanes;
}

}  // namespace

TEST_CASE("point kernels: shaped_products sums in its documented order in every build", "[theory]") {
  // The pair tables' rules (H × L): 20 × 12, 40 × 24, 32 × 16 (30 rounded up to 4), 60 × 36; rows of 8 and odd sizes.
  for (auto [stride, L] : {std::pair<std::size_t, std::size_t>{20, 12}, {40, 24}, {32, 16}, {60, 36}, {4, 1}})
    for (std::size_t n : {1u, 3u, 5u, 8u, 10u})  // the AVX-512 build's blocks of four rows, then two, then one
      for (std::size_t shapes : {1u, 3u}) {
        const std::size_t count = stride * L;
        const std::vector<double> a = uniform(n * count, -2.0, 2.0, unsigned(5 + stride)), b = uniform(n * count, -2.0, 2.0, unsigned(6 + L));
        const std::vector<double> c = uniform(shapes * stride, -1.5, 1.5, unsigned(7 + n));
        const std::vector<double> start = uniform(shapes * n * n * 4, -1.0, 1.0, unsigned(9 + n));  // the lanes accumulate
        const std::vector<double> ref = shaped_by_hand(a, b, count, n, stride, L, c, shapes, start);
        std::vector<double> base = start, wide = start;
        shaped_products_baseline(a.data(), b.data(), count, n, stride, L, c.data(), shapes, base.data());
        INFO("n " << n << ", rule " << stride << " x " << L << ", shapes " << shapes);
        CHECK(same_bits(base, ref));
        if (avx2_fma_available()) {
          shaped_products_avx2(a.data(), b.data(), count, n, stride, L, c.data(), shapes, wide.data());
          CHECK(same_bits(wide, ref));
        }
        if (avx512_available()) {
          std::vector<double> widest = start;
          shaped_products_avx512(a.data(), b.data(), count, n, stride, L, c.data(), shapes, widest.data());
          CHECK(same_bits(widest, ref));
        }
      }
  // reduce_lanes: (s₀ + s₂) + (s₁ + s₃) added to each entry.
  const std::vector<double> lanes = uniform(12, -1.0, 1.0, 3);
  const std::vector<double> start = {0.5, -0.25, 2.0};
  std::vector<double> out = start;
  reduce_lanes(lanes.data(), 3, out.data());
  for (std::size_t e = 0; e < 3; ++e)
    CHECK(out[e] == start[e] + ((lanes[4 * e] + lanes[4 * e + 2]) + (lanes[4 * e + 1] + lanes[4 * e + 3])));
}
