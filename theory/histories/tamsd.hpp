#pragma once
// Time-averaged MSD of species k once the temperature ratios have settled (docs/physics.md §4):
//   δ²_k(Δ) = (1/(𝒯−Δ)) ∫₀^(𝒯−Δ) ⟨[R_k(t+Δ) − R_k(t)]²⟩ dt,
//   ⟨[R(t+Δ)−R(t)]²⟩ = 6 D_k(0) τ₀ [ln(s_Δ/s) − (1/p)(1 − (s/s_Δ)^p)],
//   s = 1 + t/τ₀, s_Δ = s + Δ/τ₀, p = τ₀/τ_v,k(0); the average over t by GSL QAG.
// This is the Langevin-type model; the real TAMSD departs from it for constant ε (docs/physics.md §4),
// so a DSMC deviation here is a result, not a bug.
#include "theory/rates/velocity_memory.hpp"

namespace granmix::theory {

// One exponential memory (D₀, τ_v,k(0)); the general settled memory in velocity_memory.hpp.
double msd_increment(double D0, double tau_v0, double tau0, double t, double lag);
double tamsd(double D0, double tau_v0, double tau0, double measurement_time, double lag);
double tamsd(const VelocityMemory& memory, double tau0, double measurement_time, double lag);

}  // namespace granmix::theory
