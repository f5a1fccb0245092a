#pragma once
// Tracer diffusion of species k beyond the first Sonine approximation (physics-beyond.md §3;
// Garzó & Montanero PRE 69, 021301 (2004) at a₂ = 0, any number of partner species).
// The Chapman–Enskog solution of the tracer (Boltzmann–Lorentz) problem is expanded in
// c S_p(c²) f_M, c = V/√(2T_k/m_k), p = 0, 1. With the Maxwellian collision integrals C_pq
// (test function c S_q, basis c S_p, closed forms in sonine2_diffusion.cpp) and the time-derivative
// matrix of the scaled problem (−¾ζ, 0; 15ζ/4, −45ζ/8):
//   D_k[1] = (3T_k/2m_k) / (C₀₀ − ¾ζ) = T_k / (m_k(ν_k − ζ/2))
//   D_k[2] = (3T_k/2m_k) / [C₀₀ − ¾ζ − C₀₁(C₁₀ + 15ζ/4)/(C₁₁ − 45ζ/8)]
// Cost O(N) per species, no quadrature: meant for ODE right-hand sides.
#include <cstddef>
#include <memory>

#include "collision_rates.hpp"
#include "cooling_model.hpp"

namespace granmix::theory {

// C_pq summed over the partners i of species k (rates in the units of the mixture).
struct SonineCollisionIntegrals {
  double C00 = 0.0, C01 = 0.0, C10 = 0.0, C11 = 0.0;
};

// One pair (k, i): weight = n_i σ_ki² χ_ki, mu = μ_ik = m_i/(m_i+m_k), eps = ε_ki,
// Ak = T_k/m_k, Ai = T_i/m_i.
SonineCollisionIntegrals sonine2_pair_integrals(double weight, double mu, double eps, double Ak, double Ai);

// Σ_i over all partners of k at the temperatures T: closed forms at constant restitution, a quadrature over
// the normal impact speed for a viscoelastic law (sonine_pair_terms.hpp, sonine_quadrature.hpp).
SonineCollisionIntegrals sonine2_collision_integrals(const CollisionRates& rates, std::size_t k, const double* T);

// The same sums and, in the same pass, ξ_k = Σ_i ξ_ki (v1 Eq. A2 written as
// ξ_ki = ν_ki[(1−ε) − (1+ε) m_k(T_i−T_k)/((m_i+m_k)T_k)], exactly 0 for ε = 1, T_i = T_k).
struct SonineTracerSums {
  SonineCollisionIntegrals C;
  double xi = 0.0;
};
SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, std::size_t k, const double* T);
class SoninePairTerms;
// The same with the pair terms made once by the caller (make_sonine_pair_terms; for ODE right-hand sides).
SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T);

// D_k[2]/D_k[1] with the cooling rate zeta that scales the problem (the common ζ of the HCS).
// NaN where the truncated problem has no diffusive solution: C₀₀ − ¾ζ ≤ 0 (ν_k ≤ ζ/2, no first-Sonine
// D either: the Santos–Dufty regime of a large rare grain) or a non-positive second-Sonine denominator.
// Close to that edge (ν_k − ζ/2 ≪ ν_k) the factor grows without bound (2.06 for k = 40 of v1 Fig. 8 at
// the settled ratios): there the Sonine expansion does not converge and the factor is no estimate.
double sonine2_factor(const SonineCollisionIntegrals& C, double zeta);

// D_k[2]/D_k[1] at the temperatures T with ζ = ξ_k(T), the tagged species' own cooling rate: the
// tracer problem is scaled with T_k, whose decay rate is ξ_k. In the settled HCS every ξ_k equals
// the common ζ, so this is the Garzó–Montanero value; away from it, it is our choice (documented).
double sonine2_factor(const CollisionRates& rates, std::size_t k, const double* T);

// Velocity-decay rate of species k at the kinetic level (physics-beyond.md §3, last line):
//   ν_eff,k = ξ_k/2 + (ν_k − ξ_k/2)·D_k[1]/D_k[2],  ν_k − ξ_k/2 = τ_v,k⁻¹ (physics-beyond.md §1),
// the one-mode VACF rate with the diffusive D_k[2] (SecondSonineDecay::rates; the mixture's VACF ODE
// integrates two modes instead, below). Where the factor is NaN (see above) this is the
// first-Sonine ν_k, the rate the MSD needs without a diffusive regime.
double kinetic_velocity_decay_rate(const CollisionRates& rates, std::size_t k, const double* T);
double kinetic_velocity_decay_rate(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T);

// The kinetic level's velocity correlation: the VACF ODE with two Sonine modes per species (issue 12).
// Q_k = ⟨Δr_k·v_k⟩ = v_k Y₀ and P_k = v_k Y₁, Y_p = ⟨c S_p(c²)·Δr_k⟩, v_k = √(2T_k/m_k), from the Galerkin
// equations of §3 in time (dv_k/dt = −ζ_k v_k/2 taken out of Y_p):
//   dQ/dt = 3T_k/m_k − (2/3)C₀₀ Q − (4/15)C₀₁ P
//   dP/dt = ξ_k P − (5ξ_k/2 + (2/3)C₁₀) Q − (4/15)C₁₁ P,
// Q = P = 0 at t = 0 for any start. ξ_k in dP/dt is the Maxwellian cooling rate of the same sums as C_pq
// (a₂ = 0, like the collision integrals), not the level's Sonine ζ_k = −d ln T_k/dt, which Q feels through
// T_k: the kinematic ζ_k with a₂ but C_pq without it is inconsistent at O(a₂) and, measured against DSMC
// (quick, seed 1, max rel): bo1-fig05 D ratio at ε = 0.2 7.7% (ξ_k here: 2.9%; one mode: 2.2%), bo1-fig02
// light MSD 4.1% (3.1%), bo1-fig06 light MSD 6.7% (3.8%). Settled, D_k = (3T_k/2m_k)/[C₀₀ − ¾ζ_k −
// C₀₁(C₁₀ + 15ξ_k/4)/(C₁₁ − 15ξ_k/4 − 15ζ_k/8)]: D_k[2] of physics-beyond §3 where ζ_k = ξ_k.
// From a Maxwellian start the velocity first decays at the first-Sonine ν_k = (2/3)C₀₀ (P builds up
// over ~1/ν_k), and in the settled HCS the MSD slope is 6D_k[2]: the one-mode
// closure with ν_eff decayed at the long-time rate from t = 0 and lost the velocity memory too early
// (heavy species of bo1-fig06/-fig01: MSD up to 0.8% above DSMC at intermediate t, light ones 3–9% early).
// Where the second-Sonine problem has no diffusive solution (sonine2_factor NaN, a large rare grain near
// the Santos–Dufty edge) species k keeps one mode at the first-Sonine ν_k (as the one-mode closure did) and
// its P relaxes at ν_k, decoupled.
class SecondSonineDecay final : public VelocityDecay {
 public:
  // terms: pair terms shared with the cooling closure (null: the law's own).
  explicit SecondSonineDecay(const CollisionRates& rates, std::shared_ptr<const SoninePairTerms> terms = nullptr);
  // The one-mode equivalent ν_eff,k of kinetic_velocity_decay_rate (same long-time D).
  void rates(const double* T, const double*, double* nu) const override;
  std::size_t modes() const override { return 2; }
  void correlation_rates(const CollisionRates& r, const double* T, const double* xi, const double* Q, double* dQ,
                         double* nu) const override;

 private:
  const CollisionRates& rates_;
  std::shared_ptr<const SoninePairTerms> terms_;
};

}  // namespace granmix::theory
