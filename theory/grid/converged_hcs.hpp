#pragma once
// The homogeneous cooling state of a mixture without the Sonine truncation of the species' own distributions
// (target: MG's γ within 0.3%, and MG's c_k). Every species k has its stationary speed density in the scaled frame,
//   (ζ/2) ∂_v·(v φ_k) = Σ_j J_kj[φ_k; f_j],
// solved on cubic B-splines exactly as the tracer limit's intruder (speed_grid.hpp, tracer_temperature.hpp:
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
// passes). The cruder estimate, partners through a₂ alone (the a₃ term's size), bounds it about twice over (v1 Fig. 4's mixture: T₂/T₁ −1.4% against 3.2% at n₂ = 0.01, −0.16% against 0.42% at
// 0.03; its D ratio −0.99% against 2.1%).
// Constant restitution only (a viscoelastic mixture has no settled state).
#include <Eigen/Dense>

#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/sonine/sonine_hcs.hpp"

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
// moments: the gain into the smallest speeds comes from collisions whose post-collision sphere passes near v′ = 0, where
// the integrand over the partner's w_z has kinks (speed_grid.hpp, WzPanels). A Gauss–Hermite product rule,
// the same nodes for every speed, straddles them: MG Fig. 3's mixture elastic (Φ exactly Maxwellian) errs in its first
// bin of 0.05 by 13.7% / 75% (species 1 / 2) with 64 points, 5.4 / 45% with 128, 0.09 / 3.4% with 256, not
// monotonically (512 in w_z: 2.4 / 9.6% from 0.05 to 0.2 thermal widths, against 256's 1.4 / 5.3%); a trial space u²·Q
// (Φ itself a spline) does not help. So the distributions take w_z by Gauss–Legendre panels cut at those kinks for each
// speed u (distribution_panel_points per panel ≤ distribution_panel_width partner widths wide; |w_⊥|² by
// distribution_perp_points Gauss–Laguerre points): the elastic error from 0.05 to 0.2 widths 2.1e-4 / 2.4e-4, from 0.2
// to 1 width 0.9e-4. MG Fig. 3 at α = 0.5 differs by ≤ 3e-5 of Φ₂ in the first bin from the 256-point Hermite rule —
// the inelastic mixture's nodes straddle its kinks less — while the elastic check that judges the rule is 140 times
// smaller.
//   And every partner is seen through its full solved density (Partners::full: its rest beyond 1 + a₂S₂ + a₃S₃ as
// point masses, 8 directions): through a₂, a₃ alone — the one truncation the moments' solve keeps —
// MG Fig. 3's Δ₁ moves by 6e-3 (19% at its zero crossing, v* = 0.525), Φ₁ by ≤ 0.3%. The model error is computed by
// variants from that state: knots 3/2 as far apart (the splines' error), the coarser rule (its change is the rule's
// error where the rule converges), the partners' rests taken finer (16 directions, 4 speeds per knot interval), the
// domain 9/7 as wide (the tail near the grid's edge). The distributions' HCS (its T_k, c_k) is the moments' own plus
// that partner truncation: the moments' level keeps Sonine partners and computes their truncation as its model error.
inline constexpr std::size_t distribution_panel_points = 10, distribution_perp_points = 128;
inline constexpr double distribution_panel_width = 1.0;
enum class DistributionVariant { solved, sparser_knots, coarser_rule, partners_finer, wider_domain };
SettledHcs converged_distribution(const CollisionRates& rates, DistributionVariant variant);
// Forgets the distributions' states solved so far (the next converged_distribution solves again): for a benchmark's
// repeats, each of which should pay the solve as a run of `granmix theory` does.
void forget_converged_distributions();

}  // namespace granmix::theory
