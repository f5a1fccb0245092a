#pragma once
// The velocity memory of a species whose temperature ratios have settled (homogeneous cooling or elastic
// equilibrium): its velocity correlation in the Haff clock s (ds = dt·√(T(t)/T(0)) = dt/(1 + t/τ₀)) as a sum of
// decaying modes, C(s) = ⟨v(0)·v(s)⟩ = Σ_j a_j e^(−λ_j s) (a_j, λ_j real or complex-conjugate pairs; velocities
// in the units of t = 0). One mode a = 3D₀/τ_v, λ = 1/τ_v is the papers' memory (v1 Eq. 17 at settled ratios);
// the kinetic-converged level has several (tracer_diffusion_galerkin.hpp). Each mode j is an exponential memory with
// D_j = a_j/(3λ_j), τ_j = 1/λ_j, so every closed form below is the one-mode form of docs/physics.md §3 summed over modes:
//   ⟨[R(t+Δ) − R(t)]²⟩ = Σ_j 6D_j [τ₀ L + τ_j (e^(−τ₀L/τ_j) − 1)],  L = ln(1 + Δ/(τ₀ + t))
// (v2 Eq. 22 at t = 0), and for an elastic gas (τ₀ = ∞) Σ_j 6D_j [Δ + τ_j (e^(−Δ/τ_j) − 1)].
#include <complex>
#include <vector>

namespace granmix::theory {

struct VelocityMemory {
  std::vector<std::complex<double>> weight, rate;  // a_j (velocity²), λ_j (1/time at t = 0), Re λ_j > 0
  static VelocityMemory exponential(double D0, double tau_v0);  // one mode: a = 3D₀/τ_v, λ = 1/τ_v
  double diffusion() const;                                     // D₀ = Σ_j a_j/(3λ_j)
};

// ⟨[R(t+lag) − R(t)]²⟩ with the settled memory m; tau0 = ∞ for an elastic gas.
double msd_increment(const VelocityMemory& m, double tau0, double t, double lag);

}  // namespace granmix::theory
