#pragma once
// The intruder's temperature in time without the Sonine truncation: the speed grid of speed_grid.hpp
// integrated in the gas's scaled time s (ds = √T₁ dt, T₁(0) = 1) from a Maxwellian intruder at θ₀ = T₂/T₁,
//   gram dP/ds = [collisions + (ζ(s)/2) drift] P,   ζ(s) = ζ₁ + ξ₁₂(P(s)),
// the gas at its kinetic HCS shape (tracer_temperature.hpp, kinetic_tracer_gas) cooling at ζ₁ plus the intruders'
// heating of it at their density n₂ (as converged_intruder_temperature, whose θ is the limit s → ∞). Trapezoidal steps
// h = min(h_max, h₀ + s/20) (h₀ = 1e-3, h_max = 1/(2λ), λ the loss rate of an intruder three thermal speeds out), the
// ζ of the new step by two fixed-point passes; exact Haff clocks within a step (ζ fixed): T₁ and t.
// The intruders' mutual collisions matter here although n₂/n₁ = 1e-4: near the Santos–Dufty edge the intruder's velocity
// correlation decays in the scaled frame at κ = ν − ζ/2 = 7e-4 only (ν ≈ 0.0868, ζ/2 ≈ 0.0861), and the intruders erase
// each other's velocities at ν₂₂ = 1.8e-3: without them the MSD at t = 8e3 is 4.6% above DSMC (z = −5.6), with them
// within its error (docs/levels.md, "v2 Fig. 5's intruder").
// Why: v2 Fig. 5's intruder (m₂/m₁ = 100, ε = 0.5) settles slowly, near the Santos–Dufty edge: DSMC from a Maxwellian
// intruder at the first Sonine's θ = 504.6 dips to 481 (its flat-topped shape forming) and reaches 575 only at t ≈ 400.
#include <vector>

#include "theory/rates/collision_rates.hpp"

namespace granmix::theory {

// Per step n (from s[n] to s[n] + h[n]): the clocks at its start and the values at its midpoint.
struct TracerRelaxation {
  std::vector<double> h, zeta;  // step length in s and the gas's cooling rate at T₁ = 1 (ζ₁ + ξ₁₂)
  std::vector<double> theta;    // T₂/T₁
  std::vector<double> nu;       // the intruder's velocity erasure rate at T₁ = 1: TracerTemperature::nu + ν₂₂ (mutual collisions)
  std::vector<double> a2;       // its cumulant at its own temperature
  std::vector<double> theta_start;  // θ at each step's start (one more: the last step's end)
  // The intruder's MSD from s = 0 and Q = ⟨ΔR·c⟩ (dM/ds = 2Q) at each step's start (one more), from the l = 1 harmonic of
  // the same equation (speed_grid.hpp): the displacement-weighted distribution, no assumption on how the velocity
  // correlation decays.
  std::vector<double> msd_start, q_start;
};

// What the intruders at their density n₂ add beyond the tracer limit, to first order in n₂ (both on by default):
struct RelaxationOptions {
  // The gas's cumulant from DSMC's Maxwellian start (a₂ = 0) to its HCS value along the first Sonine's relaxation, in
  // the intruder's collisions and the gas's cooling rate; off: settled from the start.
  bool gas_relaxes = true;
  bool heating = true;            // their heating of the gas, ξ₁₂ from the gas's energy gains (converged_intruder_temperature)
  bool mutual_collisions = true;  // their collisions with each other, the partner a Maxwellian at θ (v1 A1, A2 for 22)
  // The gas's shape under that heating (with `heating`): the intruders' kicks put energy into few gas particles, a
  // suprathermal tail; here the gas's first-Sonine cumulant answers the sources of its ⟨w⁴⟩ and ⟨w²⟩ balances
  // quasi-statically, and its cooling rate ξ₁₁(1 + 3c/32) with it. Off by default: the first Sonine overshoots (v2 Fig. 5:
  // T₁ at t = 8e3 +2.2% against DSMC with it, −1.2% without; the tail's own fast cooling takes much of the source);
  // the difference it makes is the judged level's model error for that left-out reshaping (level "…-reshaped").
  bool gas_shape = false;
  // Once nothing changes any more (relax_intruder's settled steps: long, without solves); off: every step solved.
  bool settle = true;
};

// rates: the gas (0) and the intruder (1), constant restitution with ε₁₁ < 1; integrated until the real time t_end.
// Throws NumericalError where a step's system is singular or θ leaves the grid's range.
TracerRelaxation relax_intruder(const CollisionRates& rates, double theta0, double t_end, RelaxationOptions opt = {});

}  // namespace granmix::theory
