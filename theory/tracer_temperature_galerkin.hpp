#pragma once
// The intruder's homogeneous cooling state in the tracer limit without the Sonine truncation (issue 12): species 0
// the gas (its own HCS: cooling rate ζ₁, Sonine shape a₂, a₃), species 1 an intruder with n₁ → 0. Its velocity
// distribution, in units scaled with the cooling gas (c = v/√(2θ_ref), θ_ref ∝ T₁(t)), is stationary:
//   (ζ₁/2) ∂_c·(c φ) = J[φ; f_gas],   i.e.   ∫ φ [L†ψ + (ζ₁/2) v·∇_v ψ] dv = 0 for every test function ψ,
// L† the Boltzmann–Lorentz adjoint of tracer_diffusion_galerkin.hpp (partners at T₁ with the gas's shape). The test
// ψ = 1 gives 0 = 0 (the intruders' number), ψ = v² the energy balance ξ₂ = ζ₁ of every tracer form. Galerkin in
// φ = f_w Σ_q b_q P_q(c²), P_q = L_q^(1/2)(c²/λ) (orthogonal under f_w, the Maxwellian of temperature λ θ_ref, so
// ∫φ = b₀), tested with ψ_n = P_n, n ≥ 1:
//   Σ_q b_q [−C_qn + ζ₁ Σ_qn] = 0,  C_qn = ⟨P_q (−L†) P_n⟩_w (add_pair_collisions, TestForm::density),
//   Σ_qn = ⟨P_q c² P_n′(c²)⟩_w,  b₀ = 1.
// Its second moment gives θ = T₂/T₁, θ_ref is moved to it and the problem solved again until they agree (the basis
// then sits on the solution's own temperature; to 1e-12 in a few passes). With two functions and a Maxwellian gas
// this is the energy balance ξ₂₁(θ) = ξ₁₁ of v1 (A2) (the paper's tracer θ); with three, about the first Sonine (the
// intruder's own a₂, kept to all orders here). Why: a heavy intruder near the Santos–Dufty edge is far from any
// Sonine shape — v2 Fig. 5 (m₂/m₁ = 100, ε = 0.5): Maxwellian θ 412.9, first Sonine 504.6 (c₂ = −0.42), DSMC about 570;
// there this basis does not settle either (8 functions: 730, while a Monte Carlo of the same tracer problem gives 639;
// README, "v2 Fig. 5's intruder"), and `change` says so.
#include <cstddef>
#include <limits>

#include "collision_rates.hpp"
#include "tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

struct TracerTemperature {
  double theta = std::numeric_limits<double>::quiet_NaN();  // T₂/T₁ (NaN: no stationary solution in the basis)
  double a2 = 0.0, a3 = 0.0;  // the intruder's Sonine coefficients (its cumulants), at its own temperature
  // The truncation left: |θ′ − θ|/θ, θ′ the temperature one function fewer gives at the same basis temperature.
  double change = std::numeric_limits<double>::quiet_NaN();
};

inline constexpr std::size_t converged_temperature_basis = 8;

// rates: the gas (0) and the intruder (1); zeta1 the gas's cooling rate at T₁ = 1, gas its shape; theta_start a first
// guess of θ (the paper's or the first Sonine's); 2 ≤ size ≤ 8 functions (the pair rule's range). Throws NumericalError where the passes do not
// settle.
TracerTemperature converged_tracer_temperature(const CollisionRates& rates, double zeta1, const PartnerShape& gas, double theta_start,
                                               std::size_t size = converged_temperature_basis, double weight_temperature = 1.0);
// The same with the gas of the kinetic tracer form (sonine_tracer.hpp): its one-species first-Sonine HCS, a₂ = c₁/2
// (van Noije–Ernst) and ζ₁ = ξ₁₁(1 + 3c₁/32); started from that form's θ. Constant restitution only (a viscoelastic
// gas has no settled state): NaN otherwise.
TracerTemperature converged_tracer_temperature(const CollisionRates& rates, std::size_t size = converged_temperature_basis);

}  // namespace granmix::theory
