#pragma once
// Tracer diffusion of species k without the Sonine truncation: the tracer (Boltzmann–Lorentz) problem
// of sonine2_diffusion.hpp — partners at the temperatures T, optionally with their Sonine shape a₂, a₃, in a gas
// cooling at ζ — solved in a radial basis that holds its solution's shape, with a test weight under which the
// expansion converges also at strong dissipation, where the Sonine sequence D[M] does not (bo1-fig05 at ε = 0.2,
// light species: D[M]/D[1] = 0.820, 0.923, 0.825, 0.945 for M = 2…5; here 0.8741, 6–9 functions within 1e-3).
//
// Adjoint form (the generator of the tagged velocity in units scaled with the cooling gas, as the tagged-particle
// Monte Carlo of tests/theory/test_sonine2_diffusion.cpp): the velocity correlation is C(s) = ⟨v·φ(s)⟩_k with ∂_s φ = L†φ + (ζ/2)v·∇_v φ,
// φ(0) = v, and D = (1/3)∫₀^∞ C ds, where
//   L†φ(v) = Σ_i n_i σ_ki² χ_ki ∫dw f_i(w) ∫dσ̂ (g·σ̂)⁺ [φ(v′) − φ(v)],  v′ = v − μ_ik(1 + ε_ki)(g·σ̂)σ̂.
// Petrov–Galerkin in φ = √(2θ_k) c Σ_m d_m B_m(c²), c = v/√(2θ_k), θ_k = T_k/m_k, tested with c B_n over a
// Maxwellian f_w of temperature λT_k (λ = weight_temperature):
//   M ḋ = −A d,  M_nm = ⟨c² B_n B_m⟩_w,  A_nm = ⟨c B_n · (−L†)(c B_m)⟩_w − (ζ/2)⟨c² B_n (B_m + 2c² B_m′)⟩_w,
//   C(s) = 2θ_k r·d(s),  r_n = ⟨c² B_n⟩ over f_k (with its own a₂, a₃),  D = (2θ_k/3) r·A⁻¹ M d(0).
// With B_0 = 1 the vector c is in the basis, d(0) = e₀ and C(0) = 3θ_k exactly (the ballistic start).
// Why λ = 2: the scaling term is anti-coercive under a Maxwellian weight of temperature λT_k, −(ζ/2λ)c²φ², and the
// collisions damp only ∝ c; under λ = 1 (the Sonine problem's weight) the expansion diverges once the basis
// resolves c ~ λ·2ν′/ζ (bo1-fig05 at ε = 0.2, light species: 0.878, 0.870, 0.879, 0.867, 0.886, 0.849, 0.932,
// 0.722 for 3–10 functions); λ = 2 converges there and agrees with λ = 1 where both converge (tests).
// With B = L_m^(3/2) and λ = 1 this is D_k[M] of sonine2_diffusion.hpp exactly (tested to 1e-9). The basis used
// here is B_0 = 1, B_m = L_{m−1}^(3/2)(c²)/√(c² + x₀): with x₀ = 0 the Lorentz gas's exact memory 1/ν(c) ∝ 1/c is
// B_1, and x₀ = v₀²/(2θ_k), v₀ = Σ_i w_i √(8θ_i/π) / Σ_i w_i (the partners' mean speed, weighted as their
// collision rates) keeps ν(c) finite at c = 0 as moving partners do. The pair integrals are those of
// sonine_quadrature.hpp (the impact speed u, then W and |v_⊥|² given u, σ̂ = ẑ): u by the half-range Gauss rule at
// constant ε (16 nodes, RadialBasis::speed_points; 24 for a viscoelastic ε(u), law eps_at), W and |v_⊥|² by 60 × 36 Gauss points
// for the non-polynomial basis: 5e-4 of the elastic 1:100 light species' factor (1.11014 against 1.10958 with
// 120 × 80), 2.2e-3 in the Lorentz limit, ≤ 1e-4 at ε ≤ 0.8. Cost: ~5·10⁴ points per pair, 0.07–0.5 ms per pair with three partner
// shapes by the rule's tier (v1 Fig. 8's pairs; the basis evaluated over all points of one impact speed at
// once, the sums by the per-point kernels of point_kernels.hpp); the species on OpenMP threads.
#include <Eigen/Dense>

#include <complex>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/velocity_memory.hpp"

namespace granmix::theory {

class AxialShape;  // partner_axial_shape.hpp

// B_m(x) and x·dB_m/dx, x = c², m < size, at `count` points at once (the quadratures evaluate ~10⁵ points per pair;
// point by point the serial recurrence would be most of their cost): B[m·count + p] (each function's values contiguous, a
// row-major size × count matrix); xdB may be null.
struct RadialBasis {
  std::size_t size = 0;
  std::function<void(const double* x, std::size_t count, double* B, double* xdB)> eval;
  // The W × |v_⊥|² rule of its pair integrals (add_pair_collisions): 60 × 36 points unless the basis is smooth on the
  // scale of the velocities that meet (collision_weighted_basis at large x₀).
  std::size_t hermite_points = 60, laguerre_points = 36;
  // The impact speed's half-range rule at constant ε (half_range_rule): 16 nodes. Given W and |v_⊥|² the integrand is
  // smooth in u and the rule converges fast: against 32 nodes ≤ 5e-10 of a pair source's largest entry where the
  // partner is not hotter than at an equal start, 6.3e-6 at worst with it e⁴ times hotter (the W × |v_⊥|² tiers' own
  // budget: 5e-5); v1 Fig. 8's 43 species at their settled ratios: ≤ 1.7e-11 of each species' operator (24 nodes:
  // 3e-13; 12 nodes: 1.6e-5). tests/theory/test_tracer_diffusion_galerkin.cpp.
  std::size_t speed_points = 16;
  // The same rule for a viscoelastic ε(u), a function of u^(1/10) (sonine_quadrature.hpp: the rule's error then falls
  // as ~n^(−6), not geometrically): 24 nodes, ≤ 3e-8 of a pair source's largest entry against 48 (16 nodes 4.7e-6,
  // 12 nodes 8.6e-4; tests/theory/test_tracer_diffusion_galerkin.cpp); 80 nodes of a Gauss–Legendre rule in
  // (u/√(2V))^(1/10) err by 2.4e-7.
  std::size_t impact_points = 24;
  // The pair integrals' loss rows at the post-collision points x1 (add_pair_collisions): loss[m·count + p] =
  // B[m·count + p]·wx_p − b_m(x1_p)·wcc_p, B the basis at the pre-collision points. The Sonine basis: eval, then
  // loss_rows; the collision-weighted one in one pass that never stores b(x1) (point_kernels.hpp).
  std::function<void(const double* x1, std::size_t count, const double* B, const double* wx, const double* wcc, double* loss)> loss = nullptr;
};
RadialBasis sonine_radial_basis(std::size_t modes);                // L_m^(3/2)(x), m < modes (the Sonine modes)
// 1, then L_{m−1}^(3/2)(x)/√(x + x₀). Its pair rule by x₀ (the near-singular 1/√(c² + x₀) needs the points only where
// x₀ is small, the light species): 60 × 36 below x₀ = 1.5, 40 × 24 from 1.5, 30 × 16 from 4, 20 × 12 from 15. Each
// pair source within 1.6e-5 of its largest entry of the 60 × 36 rule's (tests/theory/test_tracer_diffusion_galerkin.cpp); in the
// history tables' own coordinates (galerkin_decay.hpp) ≤ 1.5e-4 against 120 × 72 over ρ within e^(±4) of the start
// (x₀ = 4.3–121, scenes and binaries), where 60 × 36 itself errs by 1e-3–3e-2 for the light
// species (x₀ = 0.01–0.7). 40 × 24 (v1 Fig. 8's species have x₀ = 1.1–4.2): ≤ 1.5e-5 against
// 90 × 54 at x₀ = 1.5–4 (v1 Fig. 8's pairs with partners 1, 2, 6, 13 at ρ within e^(±2) of the settled one; 60 × 36
// there 2.5e-7), 3e-5 at x₀ = 1.2, 5e-5 at 1.0, 1e-3 at 0.8 (hence from 1.5). Cost: 1/2.25, 1/4.5 resp. 1/9 of the
// finest rule's.
RadialBasis collision_weighted_basis(std::size_t size, double x0);

struct GalerkinOptions {
  double weight_temperature = 2.0;                          // λ of the test weight
  double zeta = std::numeric_limits<double>::quiet_NaN();   // the scaling rate; NaN: ξ_k(T), v1 (A2)
  const double* a2 = nullptr;                               // Sonine shape of every species (null: Maxwellian)
  const double* a3 = nullptr;
  // Every species' full settled density instead (null: the Sonine shape): the partners' axial shapes and the own
  // source r from it (partner_axial_shape.hpp; the D ratios' partners' truncation, converged_hcs_diffusion.hpp).
  const std::vector<AxialShape>* full = nullptr;
};
// The impact speed's rule where the partners are their full densities: E[f_i/f_M,i | c_iz] is a spline of the solved
// density, less smooth in u than a Sonine shape, so the 16 nodes of the polynomial shapes are not enough. v1 Fig. 5's
// D-ratio model error at ε = 0.8 (its partners' part moves): 0.2017% with 16 nodes, 0.1698% with 24, 0.1645% with 32
// (the D ratios themselves ≤ 4e-8 apart).
inline constexpr std::size_t full_shape_speed_points = 32;

// The pieces of the problem, for callers that assemble it at many states (galerkin_decay.hpp):
// the partner's shape f_i/f_M,i = one + a2 S₂(c_i²) + a3 S₃(c_i²);
// or, where `full` is set, that density's own E[f_i/f_M,i | c_iz] (partner_axial_shape.hpp; one, a2, a3 unused).
struct PartnerShape {
  double one = 1.0, a2 = 0.0, a3 = 0.0;
  const AxialShape* full = nullptr;
};
// the collisions of species k (its tracer at θ_k = T_k/m_k) with partner i at θ_i, for each of `count` partner shapes:
// out[j] += Σ ⟨c B_n · (−L†_i)(c B_m)⟩_w (no scaling term; constant ε: it scales as √θ_k at fixed θ_i/θ_k);
void add_pair_collisions(const CollisionRates& rates, std::size_t k, std::size_t i, double theta_k, double theta_i, const RadialBasis& basis,
                         double weight_temperature, const PartnerShape* shapes, std::size_t count, Eigen::MatrixXd* out);
// the averages that do not depend on the state: M, the scaling matrix S_nm = ⟨c² B_n (B_m + 2c² B_m′)⟩_w (A gets
// −(ζ/2)S) and r = r[0] + a_k2 r[1] + a_k3 r[2] over f_k.
struct GalerkinAverages {
  Eigen::MatrixXd M, S;
  Eigen::VectorXd r[3];
};
GalerkinAverages galerkin_averages(const RadialBasis& basis, double weight_temperature);

// The assembled problem of species k at the temperatures T.
struct TracerGalerkin {
  Eigen::MatrixXd A, M;
  Eigen::VectorXd r;  // ⟨c² B_n⟩ over f_k
  double theta = 0.0;  // T_k/m_k
};
TracerGalerkin tracer_galerkin(const CollisionRates& rates, std::size_t k, const double* T, const RadialBasis& basis,
                               const GalerkinOptions& opt = {});
// The problem in the first n functions of the basis (a nested basis: its smaller problem without a new quadrature).
TracerGalerkin leading_block(const TracerGalerkin& g, std::size_t n);
// An M-orthonormal basis of the span (columns Φ, ΦᵀMΦ = 1): the weighted functions come close to the constant B₀
// where the partners are fast (x₀ ≫ 1, a heavy tracer), so directions with an M-eigenvalue below 1e-11 of the
// largest are dropped (Φ = Q Λ^(−1/2) over the kept ones).
Eigen::MatrixXd m_orthonormal_basis(const Eigen::MatrixXd& M);
// D_k (NaN where there is no diffusive solution: a singular or non-positive problem, the Santos–Dufty regime).
double galerkin_diffusion(const TracerGalerkin& g);
// The velocity correlation as a sum of decaying modes (the eigenvalues of M⁻¹A): C(s) = Σ_j α_j e^(−λ_j s); none
// where a mode does not decay (no diffusive solution).
std::optional<VelocityMemory> galerkin_memory(const TracerGalerkin& g);

// The converged problem: collision_weighted_basis with `size` functions; D_k, D_k/D_k[1] (the first-Sonine D of
// v1 Eq. 19 at the same T) and the problem (for galerkin_memory).
struct ConvergedDiffusion {
  double D = 0.0, factor = 0.0;
  TracerGalerkin problem;
};
inline constexpr std::size_t converged_diffusion_basis = 8;
double converged_basis_x0(const CollisionRates& rates, std::size_t k, const double* T);  // its x₀ at the temperatures T
ConvergedDiffusion converged_tracer_diffusion(const CollisionRates& rates, std::size_t k, const double* T, const GalerkinOptions& opt = {},
                                              std::size_t size = converged_diffusion_basis);
// The truncation left: |D(size) − D(size − 1)|/D(size), relative, of a converged_tracer_diffusion result.
double converged_diffusion_change(const ConvergedDiffusion& c);

}  // namespace granmix::theory
