#pragma once
// Tracer diffusion of species k beyond the first Sonine approximation (docs/physics-beyond.md §3;
// Garzó & Montanero PRE 69, 021301 (2004) at a₂ = 0, any number of partner species), to any order M ≤ 5.
// The Chapman–Enskog solution of the tracer (Boltzmann–Lorentz) problem is expanded in
// c S_p(c²) f_M, c = V/√(2T_k/m_k), S_p = L_p^(3/2), p < M (M "modes", the Sonine order of D). With the
// Maxwellian collision integrals C_pq (test function c S_q, basis c S_p; closed forms at constant ε,
// sonine_cpq_table.hpp), the norms N_p = ⟨c² S_p²⟩ = (2/√π)Γ(p + 5/2)/p! and the scaling matrix of the
// time derivative, M_pq = ⟨c² S_q (S_p + 2c² S_p′)⟩ (M_pp = (2p + 1)N_p, M_{p,p−1} = −(2p + 3)N_{p−1}, else 0):
//   D_k[M] = (3T_k/2m_k) (A⁻¹)₀₀,   A_pq = C_pq − (ζ/2) M_pq   (p, q < M)
//   D_k[1] = (3T_k/2m_k) / (C₀₀ − ¾ζ) = T_k / (m_k(ν_k − ζ/2))
//   D_k[2] = (3T_k/2m_k) / [C₀₀ − ¾ζ − C₀₁(C₁₀ + 15ζ/4)/(C₁₁ − 45ζ/8)]
// Elastic Lorentz gas: D[M]/D[1] = 1, 13/12, 1.10677, 1.11654, 1.12152 for M = 1…5, towards 32/(9π) = 1.1318
// from below; the 1:100 mixtures of v1 converge alternating (bo1-fig02, light species: 0.921, 0.940, 0.932,
// 0.937; DSMC 0.941 ± 0.005), so |D[M] − D[M−1]| bounds the truncation there. The kinetic level uses
// M = kinetic_sonine_order. Cost O(N M²) per species with the closed forms: meant for ODE right-hand sides.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/cooling_model.hpp"
#include "theory/sonine/sonine_cpq_table.hpp"

namespace granmix::theory {

inline constexpr std::size_t max_sonine_modes = 5;
// The Sonine order of the kinetic level's D (its VACF modes per species); kinetic-sonineN levels use N.
inline constexpr std::size_t kinetic_sonine_order = 4;

// C_pq summed over the partners i of species k (rates in the units of the mixture), p, q < modes.
struct SonineCollisionIntegrals {
  std::size_t modes = 0;
  std::array<double, max_sonine_modes * max_sonine_modes> c{};
  double operator()(std::size_t p, std::size_t q) const { return c[p * max_sonine_modes + q]; }
  double& operator()(std::size_t p, std::size_t q) { return c[p * max_sonine_modes + q]; }
  void add(const SonineCollisionIntegrals& o, double weight = 1.0) {
    modes = o.modes;
    for (std::size_t j = 0; j < c.size(); ++j) c[j] += weight * o.c[j];
  }
};

// N_p = ⟨c² S_p(c²)²⟩ over the Maxwellian, and M_pq of the scaled time derivative (above), p, q < 5.
double sonine_mode_norm(std::size_t p);
double sonine_scaling_matrix(std::size_t p, std::size_t q);

// One pair (k, i) at constant restitution: weight = n_i σ_ki² χ_ki, mu = μ_ik = m_i/(m_i+m_k), eps = ε_ki,
// Ak = T_k/m_k, Ai = T_i/m_i; p, q < modes (≤ max_sonine_modes).
SonineCollisionIntegrals sonine2_pair_integrals(double weight, double mu, double eps, double Ak, double Ai, std::size_t modes = 2);
// The same with a non-Maxwellian partner, f_i = f_M,i[1 + a_i2 S₂(c_i²) + a_i3 S₃(c_i²)] (scalar Sonine, L^(1/2)):
// [0] the Maxwellian C_pq, [1], [2] the coefficients of a_i2, a_i3 (linear in them; sonine_cpq_table.hpp).
std::array<SonineCollisionIntegrals, sonine_cpq_sources> sonine_pair_integrals_by_source(double weight, double mu, double eps, double Ak,
                                                                                        double Ai, std::size_t modes);
// The same in two steps, for ODE right-hand sides: the table's polynomials in β = μ(1 + ε) (constant for a pair),
// then the C_pq at the temperatures (the same numbers to the last bit), for the first `sources` sources.
std::vector<double> sonine_cpq_beta_polynomials(double beta, std::size_t modes, unsigned sources);
std::array<SonineCollisionIntegrals, sonine_cpq_sources> sonine_pair_integrals_from(const std::vector<double>& polys, double weight, double beta,
                                                                                   double Ak, double Ai, std::size_t modes, unsigned sources);

// The sums over all partners of k and, in the same pass, ξ_k = Σ_i ξ_ki (v1 Eq. A2 written as
// ξ_ki = ν_ki[(1−ε) − (1+ε) m_k(T_i−T_k)/((m_i+m_k)T_k)], exactly 0 for ε = 1, T_i = T_k): closed forms at
// constant restitution, a quadrature over the normal impact speed for a viscoelastic law
// (sonine_pair_terms.hpp, sonine_quadrature.hpp).
struct SonineTracerSums {
  SonineCollisionIntegrals C;
  double xi = 0.0;
  // Asked for with partner_sonine (constant ε only; zero otherwise): the coefficients of the partner's a₂, a₃ in C.
  std::array<SonineCollisionIntegrals, 2> C_partner{};
};
SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes = 2);
class SoninePairTerms;
// One partner i of k at T_k, T_i through the pair terms (weight n_i σ_ki² χ_ki): the summand of the sums below.
SonineTracerSums sonine_pair_sums(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, std::size_t i, double Tk,
                                  double Ti, std::size_t modes, bool partner_sonine = false);
// The same with the pair terms made once by the caller (make_sonine_pair_terms; for ODE right-hand sides).
SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T,
                                     std::size_t modes = 2);
SonineCollisionIntegrals sonine2_collision_integrals(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes = 2);

// D_k[M]/D_k[1], M = C.modes, with the cooling rate zeta that scales the problem (the common ζ of the HCS).
// NaN where the truncated problem has no diffusive solution: C₀₀ − ¾ζ ≤ 0 (ν_k ≤ ζ/2, no first-Sonine
// D either: the Santos–Dufty regime of a large rare grain), a non-positive D[M], or modes that grow
// instead of relaxing (an eigenvalue of A N⁻¹ with real part ≤ 0). Close to that edge (ν_k − ζ/2 ≪ ν_k)
// the factor grows without bound (D[2]/D[1] = 2.06 for k = 40 of v1 Fig. 8 at the settled ratios): there the
// Sonine expansion does not converge and the factor is no estimate.
double sonine_factor(const SonineCollisionIntegrals& C, double zeta);

// D_k[M]/D_k[1] at the temperatures T with ζ = ξ_k(T), the tagged species' own cooling rate: the
// tracer problem is scaled with T_k, whose decay rate is ξ_k. In the settled HCS every ξ_k equals
// the common ζ, so this is the Garzó–Montanero value (M = 2); away from it, it is our choice (documented).
double sonine_factor(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes);

// Velocity-decay rate of species k with D_k[M] (docs/physics-beyond.md §3, last line):
//   ν_eff,k = ξ_k/2 + (ν_k − ξ_k/2)·D_k[1]/D_k[M],  ν_k − ξ_k/2 = τ_v,k⁻¹ (docs/physics-beyond.md §1),
// the one-mode VACF rate with the same long-time D (SonineDecay::rates; the kinetic level's VACF ODE
// integrates M modes instead, below). Where the factor is NaN (see above) this is the first-Sonine ν_k,
// the rate the MSD needs without a diffusive regime.
double kinetic_velocity_decay_rate(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes);
double kinetic_velocity_decay_rate(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T,
                                   std::size_t modes);

// The kinetic level's velocity correlation: the VACF ODE with M Sonine modes per species.
// Z_p,k = v_k Y_p, Y_p = ⟨c S_p(c²)·Δr_k⟩, v_k = √(2T_k/m_k), Z₀ = Q_k = ⟨Δr_k·v_k⟩, from the Galerkin
// equations of §3 in time (dv_k/dt = −ξ_k v_k/2 taken out of Y_p; b_q = Z_q/N_q):
//   dZ_p/dt = δ_p0 3T_k/m_k − Σ_q C_pq b_q + (ξ_k/2) Σ_q M_pq b_q − (ξ_k/2) Z_p,
// i.e. for M = 2: dQ/dt = 3T_k/m_k − (2/3)C₀₀ Q − (4/15)C₀₁ P, dP/dt = ξ_k P − (5ξ_k/2 + (2/3)C₁₀) Q − (4/15)C₁₁ P;
// Z = 0 at t = 0 for any start. ξ_k in the scaling terms is the Maxwellian cooling rate of the same sums as
// C_pq (a₂ = 0, like the collision integrals), not the level's Sonine ζ_k = −d ln T_k/dt, which Q feels
// through T_k: the kinematic ζ_k with a₂ but C_pq without it is inconsistent at O(a₂) and, measured against
// DSMC (two modes, quick, seed 1, max rel): bo1-fig05 D ratio at ε = 0.2 7.7% (ξ_k here: 2.9%), bo1-fig02
// light MSD 4.1% (3.1%), bo1-fig06 light MSD 6.7% (3.8%). Settled, the MSD slope is 6D_k[M] where ζ_k = ξ_k.
// From a Maxwellian start the velocity first decays at the first-Sonine ν_k = (2/3)C₀₀ (the higher modes
// build up over ~1/ν_k); a one-mode closure with the long-time rate lost the velocity memory too early
// (heavy species of bo1-fig06/-fig01: MSD up to 0.8% above DSMC at intermediate t, light ones 3–9% early).
// Where the truncated problem has no diffusive solution (sonine_factor NaN, a large rare grain near the
// Santos–Dufty edge) species k keeps one mode at the first-Sonine ν_k and its other modes relax at ν_k,
// decoupled.
// Non-Maxwellian species (shaped; the cooling closure's a₂, a₃ given, constant ε, up to pair_cache_species species):
// f_k = f_M,k[1 + a_k2 S₂(c²) + a_k3 S₃(c²)] (scalar Sonine, L^(1/2)) changes two things. The streaming source
// ⟨v² S_p(c²)⟩ = (2T_k/m_k)⟨c² S_p⟩ over f_k gains N_p(a_kp − a_k,p+1) for p ≥ 1 (L_q^(1/2) = L_q^(3/2) −
// L_{q−1}^(3/2), so ⟨c² S_p S_q^(1/2)⟩ = N_p(δ_pq − δ_p,q−1)); and the partners' collision integrals become
// C_pq + Σ_i (a_i2 C_pq^(2) + a_i3 C_pq^(3)) (sonine_pair_integrals_by_source; linear in the a's, as the cooling
// closure is). The scaling terms then take the level's ζ_k = −d ln T_k/dt: the rate of the same a's, so the
// closure is consistent at O(a) again. The settled D (sonine_factor, diffusion_at) stays at a = 0.
class SonineDecay final : public VelocityDecay {
 public:
  // terms: pair terms shared with the cooling closure (null: the law's own). modes: 2 … max_sonine_modes.
  // shaped: the species' a₂, a₃ (from the cooling closure) in the source and the partners' C_pq (below).
  SonineDecay(const CollisionRates& rates, std::size_t modes, std::shared_ptr<const SoninePairTerms> terms = nullptr, bool shaped = false);
  // The one-mode equivalent ν_eff,k of kinetic_velocity_decay_rate (same long-time D).
  void rates(const double* T, const double*, double* nu) const override;
  std::size_t modes() const override { return modes_; }
  bool uses_sonine_coefficients() const override { return partner_sonine_; }
  void correlation_rates(const CollisionRates& r, const double* T, const double* xi, const double* Q, double* dQ, double* nu,
                         const double* a2, const double* a3) const override;

 private:
  // Per species at the temperatures of the last call: the sums and whether the problem is diffusive. CVODE's
  // difference-quotient Jacobian perturbs one unknown per column: the MSDs, modes and cumulants at unchanged T
  // (nothing to recompute), one T_j (only the pairs with j: kept per pair up to pair_cache_species species,
  // and summed in the same order, so the sums are bitwise those of a full pass).
  void update(const double* T) const;
  static constexpr std::size_t pair_cache_species = 300;

  const CollisionRates& rates_;
  std::size_t modes_;
  std::shared_ptr<const SoninePairTerms> terms_;
  bool partner_sonine_;  // the partners' a₂, a₃ in C_pq (constant ε, pairs cached)
  mutable std::vector<double> T_;
  mutable std::vector<SonineTracerSums> pairs_, sums_;
  mutable std::vector<char> diffusive_;
};

}  // namespace granmix::theory
