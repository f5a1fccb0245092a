#pragma once
// The intruder's homogeneous cooling state in the tracer limit without the Sonine truncation: species 0
// the gas (its own HCS: cooling rate ζ₁, Sonine shape a₂, a₃), species 1 an intruder with n₁ → 0. In the gas's scaled
// frame (T₁ = 1 at the reference time, velocities fixed while the gas cools: dv/ds = (ζ₁/2)v between collisions) the
// intruder's distribution is stationary:
//   (ζ₁/2) ∂_v·(v φ) = J[φ; f_gas],
// J the inelastic Boltzmann–Lorentz operator (hard spheres, constant ε): collisions with gas particles w at the rate
// n₁σ₁₂²χ₁₂ (g·σ̂)Θ(g·σ̂) dσ̂, g = v − w, v′ = v − μ(1+ε)(g·σ̂)σ̂, μ = m₁/(m₁ + m₂), the gas f_M(w)(1 + a₂S₂ + a₃S₃).
// φ is isotropic; its speed density P(u) is solved in weak form, for every test function ψ(u):
//   ∫ P(u) [ (ζ₁/2) u ψ′(u) + ∫dw f_gas(w) ∫dσ̂ n₁σ₁₂²χ₁₂ (g·σ̂)Θ [ψ(|v′|) − ψ(u)] ] du = 0,   ∫P = 1,
// with P and ψ in the same uniform cubic B-splines on [0, U] (C², so the quadrature over the collisions, whose
// post-collision speeds cross the knots, stays accurate). Quadratures: per knot interval 4 Gauss–Legendre points in
// u; given u (along z) the gas's w_z by 12 Gauss–Hermite points, |w_⊥|² by 12 Gauss–Laguerre points (w in the xz
// plane: the problem is symmetric about u), σ̂ exactly (the post-collision speed's density in closed
// form, sphere_gain.hpp) (`change` below says how far the rest is converged).
// θ = T₂/T₁ = m₂⟨u²⟩/3; the grid follows it: U = 7 √(θ/m₂), step √(θ/m₂)/8, solved again until θ moves by < 1e-5.
// Cost ~0.05–0.15 s (the knot intervals on OpenMP threads; the same numbers for any thread count).
// Why not a Sonine or Gaussian-weighted basis: a heavy intruder near the Santos–Dufty edge has a flat-topped
// distribution (v2 Fig. 5, m₂/m₁ = 100, ε = 0.5: a₂ = −0.38), which Laguerre polynomials under a Maxwellian do not
// settle on (3–8 functions: θ = 497 … 730); here θ = 638.70, against 638.8 ± 0.6 of a Monte Carlo of the same problem
// (scripts/tracer_intruder_mc.cpp) and the first Sonine's 504.6 (docs/levels.md, "v2 Fig. 5's intruder").
#include <limits>

#include "theory/rates/collision_rates.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

struct TracerTemperature {
  double theta = std::numeric_limits<double>::quiet_NaN();  // T₂/T₁ (NaN: no stationary solution)
  double a2 = 0.0, a3 = 0.0;  // the intruder's Sonine coefficients (its cumulants), at its own temperature
  // The solver's own error estimate, the larger of |θ′ − θ|/θ with a step 3/2 as long and with the collision quadrature
  // of half the points (6: it converges algebraically where the jumps in speed are comparable to the step, a heavy
  // intruder near equipartition — elastic m₂/m₁ = 100: θ − 1 = −1.6e-3 at 12 points, estimate 6.6e-3).
  double change = std::numeric_limits<double>::quiet_NaN();
  // What the intruders at their density n₂ add to the gas's cooling rate (the gas's energy gains in the same
  // collisions, per n₁(3/2)T₁): negative where they heat it. Not part of the tracer limit; see
  // converged_intruder_temperature.
  double xi12 = 0.0;
  // The rate at which the gas's collisions erase the intruder's velocity, averaged over its distribution with weight u²
  // (speed_grid.hpp): the initial decay rate of its velocity correlation in the lab frame (the Maxwellian's is v1's
  // τ_v⁻¹ + ξ₂₁/2, A1, A2).
  double nu = std::numeric_limits<double>::quiet_NaN();
};

// The gas of the kinetic tracer form (sonine_tracer.hpp): its one-species first-Sonine HCS (the tracer limit drops the
// intruders' collisions with it), a₂ = c₁/2 at ε₁₁, χ₁₁, its rate ζ₁ = ξ₁₁(1 + 3c₁/32) at T₁ = 1 (0 for an elastic gas),
// and that form's θ as a start. Constant restitution.
struct KineticTracerGas {
  double zeta1;
  PartnerShape shape;
  double theta_start;
};
KineticTracerGas kinetic_tracer_gas(const CollisionRates& rates);

// rates: the gas (0) and the intruder (1); zeta1 the gas's cooling rate at T₁ = 1, gas its shape; theta_start a first
// guess of θ (the paper's or the first Sonine's). Throws NumericalError where the grid does not settle on a θ.
TracerTemperature converged_tracer_temperature(const CollisionRates& rates, double zeta1, const PartnerShape& gas, double theta_start);
// The same with the gas of the kinetic tracer form (sonine_tracer.hpp): its one-species first-Sonine HCS, a₂ = c₁/2
// (van Noije–Ernst) and ζ₁ = ξ₁₁(1 + 3c₁/32); started from that form's θ. Constant restitution only (a viscoelastic
// gas has no settled state): NaN otherwise.
TracerTemperature converged_tracer_temperature(const CollisionRates& rates);
// The intruders at their own density heat (or cool) the gas: the same problem with the gas cooling at ζ = ζ₁ + ξ₁₂(θ),
// self-consistent (intruder–intruder collisions and the gas's change of shape left out). v2 Fig. 5 (n₂/n₁ = 1e-4):
// ξ₁₂/ζ = −4%, and at the Santos–Dufty edge θ is steep in ζ (d ln θ/d ln ζ ≈ 2.4): θ 639 → 580 (Monte Carlo, the same
// problem: 580.0 ± 0.6; DSMC ≈ 570; docs/levels.md, "v2 Fig. 5's intruder"). Its `change` is the last solve's. NaN where the
// intruders are more than 10% of the gas's energy budget at the tracer limit's θ (|ξ₁₂| > 0.1 ζ₁: then the gas's shape
// and their mutual collisions, both left out, matter as much).
// tracer: converged_tracer_temperature(rates), its start (its ξ₁₂ the first step).
TracerTemperature converged_intruder_temperature(const CollisionRates& rates, const TracerTemperature& tracer);

}  // namespace granmix::theory
