#pragma once
// The homogeneous cooling state of a mixture without the Sonine truncation of the species' own distributions (issue
// 12: MG γ within 0.3%, MG c_k). Every species k has its stationary speed density in the scaled frame,
//   (ζ/2) ∂_v·(v φ_k) = Σ_j J_kj[φ_k; f_j],
// solved on cubic B-splines exactly as the tracer limit's intruder (tracer_speed_grid.hpp, tracer_temperature.hpp:
// U = 7 √(T_k/m_k), 8 knots per √(T_k/m_k), the 12-point collision rule), with every partner j — species k itself
// included — a Maxwellian at T_j times 1 + a₂,j S₂ + a₃,j S₃, a₂,j and a₃,j the cumulants of j's own solved density.
// Self-consistency, per pass: each species' ζ_k is the cooling rate at which its solved temperature is the T_k its
// partners were given (a secant in ζ on the assembled operator: the collisions do not depend on ζ); the HCS asks
// ζ_k = ζ_0 and the partners' a₂, a₃ equal to the solved ones: one quasi-Newton step per pass in ln(T_k/T_0) and the
// shapes (the Maxwellian rates' Jacobian and −1 on the shapes to start, Broyden-updated). The start is the order-3
// Sonine HCS (sonine_hcs.hpp), so the passes are few (5–7 for MG's binaries, ~0.01 s each on 2 cores; 10 for v1 Fig. 4
// at n₂ = 0.01, where the light species' a₃ = −0.61).
// What is still truncated: the partners' shapes beyond a₃ (a species sees its partners through a₂, a₃ only; its own
// density is the grid's). `partner_truncation` computes that part: the same HCS with every partner seen through its
// full solved density (its rest beyond the Sonine shape as signed point masses, speed_density_rest, following the
// passes) — since 2026-12-05, stop 39; before, the estimate of partners through a₂ alone (the a₃ term's size), which
// bounded it about twice over (v1 Fig. 4's mixture: T₂/T₁ −1.4% against 3.2% at n₂ = 0.01, −0.16% against 0.42% at
// 0.03; its D ratio −0.99% against 2.1%).
// Constant restitution only (a viscoelastic mixture has no settled state).
#include <Eigen/Dense>

#include <vector>

#include "collision_rates.hpp"
#include "sonine_hcs.hpp"

namespace granmix::theory {

// How far a variant of the solution moves it: the largest relative change of any T_k/T_0 (one species: of ζ*), and of
// any a₂,k (c_k).
struct Change {
  double T = 0.0, a2 = 0.0;
};

// A species' solved speed density in MG's reduced speed v* = v/v₀ (sonine_hcs.hpp's v₀, at Σ x_k T_k = 1): spline
// coefficients on knots h apart, ∫ P dv* = 1. Its Φ(v*) = P(v*)/(4πv*²) is MG Eq. (27)'s Φ_k without the Sonine
// truncation (the settled distributions of MG Figs. 3, 7; 0 beyond the grid, 7 thermal widths of the species).
struct SpeedDensity {
  double h = 0.0;
  Eigen::VectorXd P;
  double phi(double v) const;
};

// A settled state: T_k (Σ x_k T_k = 1), c_k = 2a₂,k, a₃,k, λ_k, β_k, ζ* in MG's units (sonine_hcs.hpp), the cooling
// rate in code units at those T (∝ √T: at T_k λ it is zeta √λ), and every species' speed density.
struct SettledHcs {
  SonineHcs hcs;
  double zeta = 0.0;
  std::vector<SpeedDensity> density;
};

struct ConvergedHcs : SettledHcs {
  int passes = 0;
  // Error estimates, filled only by converged_hcs(…, true): the grid (twice the largest change with knots 3/2 as far
  // apart, with the 16-point collision rule, and with the domain 9/7 as wide), and the partners' truncation (the change
  // when every partner is seen through its full solved density).
  Change grid_change, partner_truncation;
  // The states behind them, to carry the estimates into what is computed from the HCS (a D ratio:
  // test_converged_hcs.cpp's "[.tolerances]"): knots 3/2 apart, the 16-point rule, the wider domain; full partners.
  std::vector<SettledHcs> grid_variants;
  SettledHcs partners_full;
};

// rates: constant restitution, χ as given. check: also compute the two error estimates (four more solves).
// Throws std::invalid_argument for a viscoelastic law, NumericalError where the passes do not settle.
ConvergedHcs converged_hcs(const CollisionRates& rates, bool check = false);

// The settled distributions pointwise (MG Figs. 3, 7: Φ_k, Δ_k, G_k at every v*) need a finer collision rule than the
// moments: the gain into the smallest speeds comes from collisions whose post-collision sphere passes near 0, a corner
// of the partners' velocities that a product rule samples coarsely. MG Fig. 3's species 1 (α = 0.5) at v* = 0.19 / 0.11
// / 0.04 (knots 0.05 apart): 1.0065 / 1.1485 / 1.3478 with 12 points, 1.0276 / 1.1169 / 1.1884 with 32, 1.0273 / 1.1183 /
// 1.1616 with 64 (DSMC, quick seed 1: 1.034 ± 0.007 at 0.175, 1.100 ± 0.019 at 0.075); beyond v* = 0.3 all within
// 0.3%; the moments move by ~1e-5 (measured 2026-12-05). The rule, not the splines, is what limits Φ near v = 0: the
// same mixture elastic (Φ exactly Maxwellian) errs in MG Fig. 3's first bin of 0.05 by 13.7% / 75% (species 1 / 2) with
// 64 points, 5.4 / 45% with 128, 0.7 / 20% with 192, 0.09 / 3.4% with 256; a trial space u²·Q (Φ itself a spline,
// smooth through v = 0) did not help (13.7 / 75% at 64, 0.73 / 8.2% at 256), nor, in it, knots twice as dense (13.3 /
// 64% at 64 points) or 8 speeds per knot interval (the same to 0.03%; measured 2026-12-06). So the distributions take 256 points (~0.1 s per MG binary and
// variant: the product rule's nodes below 1e-14 of the largest weight are left out, most of its 65 536), and their model
// error is computed by variants from that state: knots 3/2 as far apart (the splines' error), the rule of half the
// points (its change is the rule's error where the rule converges), every partner seen through its full solved density
// (the one truncation left), the domain 9/7 as wide (the tail near the grid's edge). MG Fig. 3's computed model errors
// with 64 → 256 points: Φ₁ ≤ 16% → ≤ 0.17%, Φ₂ ≤ 102% → ≤ 4.0% (its first bin; 0.9% in the second, ≤ 0.3% beyond),
// Δ₁ ≤ 127% → ≤ 20% (at its zero crossing, v* = 0.53; ≤ 1.4% in the first bins).
inline constexpr std::size_t distribution_rule_points = 256;
enum class DistributionVariant { solved, sparser_knots, coarser_rule, partners_full, wider_domain };
SettledHcs converged_distribution(const CollisionRates& rates, DistributionVariant variant);
// Forgets the distributions' states solved so far (the next converged_distribution solves again): for a benchmark's
// repeats, each of which should pay the solve as a run of `granmix theory` does.
void forget_converged_distributions();

}  // namespace granmix::theory
