#pragma once
// The per-point loops of the Galerkin pair integrals (tracer_diffusion_galerkin.cpp, add_pair_collisions): each impact
// speed evaluates the basis at ~10³ points twice, forms the loss rows and sums n × n products over them; v1 Fig. 8's
// pair tables run ~10⁹ points through these. They are built for AVX2 and AVX-512 as well as the x86-64 baseline and
// chosen at run time, and every version gives the same numbers: the elementwise loops round each IEEE +, ×, ÷, √ once
// as written (no FMA contraction in this file, CMakeLists.txt), and each product entry sums its points in one fixed order
// whatever the vector width (four partial sums, row_products; four lanes of written-out fused multiply-adds,
// shaped_products). tests/theory/test_point_kernels.cpp checks every kernel against a plain scalar loop bit for bit.
#include <cstddef>

namespace granmix::theory {

// Rows L[m·count + p] = L_m^(3/2)(x_p), m < modes: the recurrence of sonine_vector_basis run over all points at once.
void laguerre_rows(const double* x, std::size_t count, std::size_t modes, double* L);
// B[m·count + p] *= (x_p + x₀)^(−1/2) for first ≤ m < rows (collision_weighted_basis's weight).
void weight_rows(const double* x, std::size_t count, double x0, std::size_t first, std::size_t rows, double* B);
// Both at once for rows 0 … modes − 1: B[m·count + p] = L_m^(3/2)(x_p)·(x_p + x₀)^(−1/2), the same numbers as
// laguerre_rows then weight_rows, in one pass over the points (chunks of 32) instead of two over every row.
void weighted_laguerre_rows(const double* x, std::size_t count, double x0, std::size_t modes, double* B);
// The collision-weighted basis's loss rows (collision_weighted_basis: 1, then L_{m−1}(x)(x + x₀)^(−1/2)) at the
// post-collision points x1, never storing the basis there: loss[m·count + p] = B[m·count + p]·wx_p − b_m(x1_p)·wcc_p,
// m < size, b_m(x1_p) as weighted_laguerre_rows computes it: the same numbers as weighted_laguerre_rows then
// loss_rows, without writing b(x1) and reading it back (v1 Fig. 8: a separate loss_rows takes 11% of its kinetic level's time).
void collision_weighted_loss_rows(const double* x1, std::size_t count, double x0, std::size_t size, const double* B, const double* wx,
                                  const double* wcc, double* loss);
// The loss rows: loss[m·count + p] = B[m·count + p]·wx_p − B1[m·count + p]·wcc_p, m < n.
void loss_rows(const double* B, const double* B1, const double* wx, const double* wcc, std::size_t n, std::size_t count, double* loss);
// The product a·bᵀ over the points first … first + len − 1, weighted for each of `shapes` shapes s by c[s]:
// out[(s·n + q)·n + m] += c[s]·Σ_l a[q·count + l]·b[m·count + l] for q, m < n. Each entry sums its points into four
// partial sums (point l into sum (l − first) mod 4, in order of l) and adds them as (s₀ + s₂) + (s₁ + s₃): the same
// operations in the same order in every build.
void row_products(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first, std::size_t len, const double* c,
                  std::size_t shapes, double* out);

// The products of the partner-shaped pair integrals, whose shape factors depend on the point's W (h) alone. The points
// are laid out with h fastest, p = l·stride + h (stride a multiple of 4, the rows `count` long), and each lane e keeps
// the h ≡ e (mod 4):
//   t(h) = Σ_{l<L} a[q·count + l·stride + h]·b[m·count + l·stride + h], by fused multiply-adds in order of l from 0;
//   lanes[((s·n + q)·n + m)·4 + h mod 4] ← fma(c[s·stride + h], t(h), that lane), for h = 0, 1, … in order
// for q, m < n and s < shapes. reduce_lanes then adds each entry's four lanes into out as (s₀ + s₂) + (s₁ + s₃).
// Unlike row_products over one h at a time, no entry is reduced across its lanes before the end: v1 Fig. 8's pair
// tables (12–36 points per h) spend most of row_products there. Every build does the same operations in the same order
// (the baseline's fused multiply-adds by std::fma, correctly rounded on any processor).
void shaped_products(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L, const double* c,
                     std::size_t shapes, double* lanes);
void reduce_lanes(const double* lanes, std::size_t entries, double* out);
void shaped_products_baseline(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L,
                              const double* c, std::size_t shapes, double* lanes);
void shaped_products_avx2(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L, const double* c,
                          std::size_t shapes, double* lanes);  // AVX2 with FMA (avx2_fma_available)
bool avx2_fma_available();
void shaped_products_avx512(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t stride, std::size_t L, const double* c,
                            std::size_t shapes, double* lanes);
// The AVX2 kernel's operations and order, built with AVX-512VL for its 32 vector registers: blocks of 4 × 4 entries
// (16 sums, 8 loads per 16 fused multiply-adds) instead of 2 × 4 (8 sums, 6 loads per 8). v1 Fig. 8's kinetic level
// on one thread: 1.57 s against the AVX2 kernel's 1.68 s. shaped_products takes it where avx512_available.
bool avx512_available();

// The two builds of row_products, for tests: the baseline's (SSE2, two doubles per vector) and the AVX2 one (four),
// which row_products takes where the processor has AVX2 (avx2_available).
void row_products_baseline(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first, std::size_t len,
                           const double* c, std::size_t shapes, double* out);
void row_products_avx2(const double* a, const double* b, std::size_t count, std::size_t n, std::size_t first, std::size_t len, const double* c,
                       std::size_t shapes, double* out);
bool avx2_available();

}  // namespace granmix::theory
