#pragma once
// The intruder's speed density on a grid of cubic B-splines (used by tracer_temperature.hpp for its stationary
// state and tracer_relaxation.hpp for its relaxation in time). Species 0 the gas (Maxwellian times 1 + a₂S₂ + a₃S₃ at
// T₁ = 1), species 1 the intruder (n₁ → 0), in the gas's scaled frame, where between collisions dv/ds = (ζ/2)v. For a
// speed density P(u) = Σ_j P_j N_j(u) and every test function N_m the weak form of the inelastic Boltzmann–Lorentz
// equation reads
//   d/ds ∫ P N_m du = Σ_j [collisions + (ζ/2) drift]_mj P_j,
//   collisions_mj = ∫ N_j(u) ∫dw f_gas(w) ∫dσ̂ n₁σ₁₂²χ₁₂ (g·σ̂)Θ [N_m(|v′|) − N_m(u)] du,   drift_mj = ∫ N_j u N_m′ du,
// with gram_mj = ∫ N_m N_j du on the left (tracer_temperature.hpp has the quadratures and why B-splines).
// The same for a vector density v̂ G(u)/(4πu²) (the l = 1 harmonic: the intruder's velocity-weighted distribution, or its
// displacement-weighted one q(v) = ⟨ΔR δ(v − c)⟩), test functions v̂ N_m(u): the gain weighted by v̂·v̂′ (collisions_p1),
// the drift and Gram matrices unchanged; the source of q, the speed density P moving (dΔR/ds = c), is gram_u P with
// gram_u_mj = ∫ N_m N_j u du, and ⟨ΔR·c⟩ = ∫ u G du = u1·G.
#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/sonine/sonine_quadrature.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

// The stationary solvers' grid (tracer_temperature, converged_hcs; the relaxation's knots too): [0, U] with
// U = speed_grid_widths √(T/m) of the species solved for, speed_grid_knots knot intervals per √(T/m), a collision rule
// of speed_grid_rule_points (tracer_temperature.hpp has how they were chosen).
inline constexpr double speed_grid_widths = 7.0;
inline constexpr double speed_grid_knots = 8.0;
inline constexpr std::size_t speed_grid_rule_points = 12;

// The collision quadrature over the partner's velocity: n points in w_z (Gauss–Hermite) and |w_⊥|² (Gauss–Laguerre).
// σ̂ needs none: every σ̂ integral of the grid is exact (sphere_gain.hpp). And over the species' own speed u: `speeds` Gauss points per knot interval for the collision
// integrals ∫ N_j(u) C_m(u) du (and G, H, G₄), whose cost is per point and node; the splines' polynomial integrals
// (Gram, drift, moments) take 4 whatever it is, exact for the Gram matrix.
//   4 speeds: every solve whose density matters pointwise or whose grid is near its limit. 3 speeds
// (moment_collision_speeds): the converged HCS's moments. Measured against 4: γ and the T ratios of v1
// Figs. 4, 5, 7 and MG's μ = 2, 4 binaries move by ≤ 5.1e-8, the c_k by ≤ 1.2e-5 (v1 Fig. 4 at n₂ = 0.01; ≤ 1.2e-8 and
// 3.6e-7 elsewhere) — ≤ 3.6e-5 and 2.6e-4 of the grid's estimated error (converged_hcs.hpp) — and the D ratios of every
// kinetic-converged-hcs scene by ≤ 1.9e-5 of the model error computed at each point (6 speeds: 4's numbers to ten
// digits; 2: 1% of the grid's estimate). Not for the settled distributions: MG Fig. 7's Φ at v* = 2.55–2.85 (Φ ~ 1e-6)
// moves by up to 21× its computed model error (4 against 6 or 8: ≤ 0.5% of it); nor the heavy intruder's θ (v2 Fig. 5:
// 2.6e-6, beyond the 1e-6 model error of its early MSD).
inline constexpr std::size_t speed_grid_interval_points = 4;  // Gauss–Legendre points in u per knot interval (exact for the Gram matrix)
//   The settled distributions (converged_hcs.hpp) take w_z by panels instead: the integrand is not smooth in w_z where,
// at the intruder's speed u (v = u ẑ), with v′ = v − β(g·σ̂)σ̂ (v1 Eq. 3, MG Eqs. 23–24; β = m₁(1 + ε)/(m₁ + m₂)) on the
// sphere of centre c = v − βg/2 and radius R = βg/2, where |c|² − R² = v·(v − βg) = u((1 − β)u + βw_z):
// (i) the post-collision sphere passes through v′ = 0, |c| = R ⇔ w_z = −(1 − β)u/β (the
// lowest speed it reaches, |c − R|, turns there: the gain into the smallest speeds has a kink), (ii) g = 0, w_z = u,
// and (iii) c = 0, w_z = −(2 − β)u/β (the last two on the axis w_⊥ = 0, sharp features for the smallest |w_⊥|). A
// Gauss–Hermite rule in w_z, the same for every u, straddles them: MG Fig. 3's mixture elastic (Φ exactly Maxwellian)
// errs by 1.4% / 5.3% (species 1 / 2) from 0.05 to 0.2 thermal widths with 256 points; Gauss–Legendre panels cut at
// (i)–(iii) for each u reach 2.1e-4 / 2.4e-4 (10 points per panel ≤ one partner width wide; 8 points 7.9e-4 / 1.5e-3,
// and with the cut at (i) alone 1.9e-3 / 5.2e-3). |w_⊥|² stays Gauss–Laguerre: from one to two widths 1.4e-4 /
// 2.6e-4 with 64 points, 7e-6 / 1.7e-5 with 128, 5e-6 / 7e-6 with 256 (8 points per panel;
// test_converged_hcs.cpp, test_tracer_temperature.cpp).
struct WzPanels {
  GaussRule unit;      // the Gauss–Legendre points of one panel, on [0, 1] (empty: w_z by CollisionRule::wz)
  double width = 0.0;  // the widest panel, in the partner's √(T/m); the panels cover ±wz_panels_reach
  std::vector<double> later_perp_weight;  // [b]: the largest |w_⊥|² weight from node b on (where pruning may stop)
};
inline constexpr double wz_panels_reach = 8.6;  // the partner's Maxwellian there: e^(−37) ≈ 1e-16 of its peak
struct CollisionRule {
  GaussRule wz, wp, speeds;
  WzPanels panels;
  explicit CollisionRule(std::size_t n, std::size_t speeds_per_interval = speed_grid_interval_points);
  // w_z by panels of `points` Gauss–Legendre points at most `width` wide, cut at each u's (i)–(iii); |w_⊥|² by `perp`
  // Gauss–Laguerre points.
  CollisionRule(std::size_t points, double width, std::size_t perp);
};
inline constexpr std::size_t moment_collision_speeds = 3;

// A partner velocity w = (w_x, 0, w_z) with a signed weight (probability per partner): what a partner's density holds
// beyond its Sonine shape, as point masses (converged_hcs.cpp's full partners).
struct PartnerNode {
  double w_x, w_z, weight;
};
struct SpeedGridProblem {
  double m1, m2, sd_gas, beta, rate;  // sd_gas = √(T₁/m₁), beta = m₁(1 + ε)/(m₁ + m₂), rate = n₁σ₁₂²χ₁₂
  PartnerShape gas;
  std::vector<PartnerNode> rest;  // added to the Maxwellian times `gas` (empty: the partner is that alone)
};
// rates: the gas (0) and the intruder (1), constant restitution.
SpeedGridProblem speed_grid_problem(const CollisionRates& rates, const PartnerShape& gas);
// Any pair of a mixture (converged_hcs.hpp): species k the one whose density is solved for, partner j (a Maxwellian at
// T_j times its Sonine shape) in its place as the "gas"; the same numbers as speed_grid_problem for k = 1, j = 0, T_j = 1.
SpeedGridProblem speed_grid_pair(const CollisionRates& rates, std::size_t k, std::size_t j, double Tj, const PartnerShape& partner);

// The assembled weak form on K knot intervals of [0, U] (K + 3 splines), and the splines' integrals against what the
// solutions are read through: ∫N_j u^(2n) du (n = 0 … 3), ∫N_j G du (G(u) the energy the gas gains per unit time from an
// intruder of speed u) and ∫N_j H du (H(u) = u·⟨dv/ds⟩_coll, the collisions' rate of change of the intruder's velocity
// projected on it: −ν(u)u²).
struct SpeedGrid {
  double h = 0.0;
  Eigen::MatrixXd collisions, collisions_p1, drift, gram, gram_u;
  Eigen::VectorXd mass, u2, u4, u6, gain, drag, u1, gain4;  // u1_j = ∫N_j u du; gain4 as gain for the gas's Δ|w|⁴
  // N_j(U): the weak form's boundary term of the drift, −U N_m(U) P(U), where it flows out at U. Kept by the histories
  // and the stationary solves: without it the Galerkin drift has modes that alternate from knot
  // to knot at the edge — growing in a history (rate ∝ 1/h; speed_grid_cooling.cpp), and in a stationary solve reaching
  // the density's values far inside (its moments stay right to ~5e-6).
  Eigen::VectorXd edge;
};
// What to assemble: all of SpeedGrid, or the speed density's operator alone (collisions, drift, Gram matrices, mass,
// u², u⁴, u⁶, u1 — what converged_hcs.hpp needs; collisions_p1, gain, drag and gain4 left empty and speed_moments'
// gain, nu, gain4 NaN). One core, K = 56, the 12-point rule: density 1.3 ms, all 2.5 ms (8.5 and 13.4 ms with a
// quadrature over σ̂ instead of sphere_gain.hpp's exact integrals).
enum class SpeedGridParts { all, density };
// The knot intervals on OpenMP threads, each into its own columns, summed in interval order (the same numbers for any
// thread count).
SpeedGrid assemble_speed_grid(const SpeedGridProblem& p, double U, std::size_t K, const CollisionRule& rule,
                              SpeedGridParts parts = SpeedGridParts::all);

// The stationary speed density of (collisions + (ζ/2) drift) P = 0 with ∫P = 1, the drift with its outflow term at U
// (SpeedGrid::edge): without it MG Fig. 7's species 1 (α = 0.3) comes out with P(v*) alternating in sign beyond v* ≈ 1
// (−0.28 at 1.5, +1.26 at 2.5, where the Maxwellian is 0.07 and 5e-7) while ∫P and ⟨v²⟩ are right to 6e-7 and 1e-5;
// with it the density falls smoothly to ~1e-6 at 6 thermal widths. The last test function's
// equation (the last spline's, on the edge interval) gives way to the normalisation. Empty where the system is singular.
Eigen::VectorXd stationary_speed_density(const Eigen::MatrixXd& collisions, const SpeedGrid& g, double zeta);

// What a speed density says, at its own normalisation: θ = m₂⟨u²⟩/3 (T₂/T₁), the cumulants a₂, a₃ at θ, the gas's
// energy gain per intruder and unit time, and ν̄ = −⟨H⟩/⟨u²⟩ (the rate at which the collisions erase the intruder's
// velocity, averaged with weight u²: the velocity correlation's initial decay, with the scaling's ζ/2 apart).
struct SpeedMoments {
  double theta, a2, a3, gain, nu;
  double gain4;  // the rate of the gas's Δ|w|⁴ per intruder (its fourth moment's source: the intruders reshape the gas)
};
SpeedMoments speed_moments(const SpeedGrid& g, const SpeedGridProblem& p, const Eigen::VectorXd& P);

// How finely a partner's rest is taken: Gauss points per knot interval in its speed (speed_density_rest) and Gauss–
// Legendre directions about the species' velocity (partner_rest_nodes). The default: 2 and 4 — half the partner nodes
// of 4 speeds at the same accuracy, the direction rule setting it (below). The settled distributions take 2 and 8 for
// their partners and check them against 4 and 16 (converged_hcs.cpp, distribution_rests).
struct RestResolution {
  std::size_t speeds = 2, directions = 4;
};

// What a speed density P (knots h apart, ∫P = 1; species of mass m, its speed_moments r: θ, a₂, a₃) holds beyond the Maxwellian
// at θ times 1 + a₂S₂ + a₃S₃ — the part a partner's Sonine shape leaves out — as signed masses at res.speeds Gauss points per
// knot interval, pruned below 1e-8 of the largest (1e-6 moves nothing at five digits). Their sums of u⁰ and u² are ≤
// 8.6e-7 and 2.2e-5 of the sums of |mass| and |mass|u² (4 points, the rule of the grid's moments: 8.5e-7, 1.4e-5).
struct SpeedDensityRest {
  double theta = 1.0;
  std::vector<std::array<double, 2>> masses;  // (speed, mass), ∫P = 1
};
SpeedDensityRest speed_density_rest(double h, double m, const Eigen::VectorXd& P, const SpeedMoments& r, const RestResolution& res = {});
// Those masses as a partner at temperature T (speeds scaled by √(T/θ): the shape kept), the directions of w by a
// res.directions-point Gauss–Legendre rule in cos α about the species' velocity (the problem is symmetric about it). How well, as
// the rest's effect on the converged HCS (its T ratio, a₂ and the D ratios' partner part, converged_hcs.hpp), over v1
// Figs. 4 (n₂ = 0.01, 0.1), 5 (ε = 0.2, 0.8), 7 (ε = 0.2, 0.5, 0.8) and MG's μ = 2, 4 binaries against 4 speeds per
// interval and 12 directions: the direction rule sets it — 4 directions within 4.6% (v1 Fig. 5,
// ε = 0.8: the D ratio's part 1.176e-5 against 1.124e-5; v1 Fig. 4 at n₂ = 0.01, T₂/T₁'s 1.3628% against 1.3612%),
// 6 within 1.1% — and 2 speeds per interval move each by ≤ 0.6% from 4 (8: the same to five digits), at half the
// partner nodes (448 per pair, v1 Fig. 7). converged_hcs's check needs its change to a few percent: a part of a
// computed model error (v1 Fig. 7: ≤ 1.3e-4 of D_k/D_1 beside a total of ≤ 1.6e-3).
std::vector<PartnerNode> partner_rest_nodes(const SpeedDensityRest& rest, double T, const RestResolution& res = {});

// The n-point Gauss–Legendre rule on [a, b] (GSL's fixed tables).
GaussRule legendre(std::size_t n, double a, double b);

// The value at speed u of the density with spline coefficients P on knots h apart (0 beyond its last knot interval).
double speed_density_at(double h, const Eigen::VectorXd& P, double u);

// The Maxwellian speed density at θ on the grid (its L² projection).
Eigen::VectorXd maxwellian_speed_density(const SpeedGrid& g, double m2, double theta);

}  // namespace granmix::theory
