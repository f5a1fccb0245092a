#include "sonine2_diffusion.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "sonine_pair_terms.hpp"

namespace granmix::theory {

// Closed forms of C_pq = ⟨S_q(c²) ∫dσ̂ Θ(g·σ̂)(g·σ̂) c·[c S_p(c²) − c′ S_p(c′²)]⟩ for one pair,
// derived (sympy, exact polynomial integration) by writing v = a g + G with g = v − w and
// G ⊥ g Gaussian, a = A_k/V, V = A_k + A_i, A = T/m; then the hemisphere around ĝ, the Gaussian
// moments of G and the Maxwell moments of |g| are elementary. With β = μ_ik(1+ε_ki) and
// P = n_i σ_ki² χ_ki √(2πV):
//   C₀₀ = 2βP                                   (= (3/2)ν_ki, physics-beyond §1)
//   C₀₁ = −aβP
//   C₁₀ = −βP (3a² − 9aβ + 10a + 4β² − 5β)/a
//   C₁₁ = βP (30 − 33β + 12β² + 22a − 9aβ − 3a²)/2
// Checks (tests/theory/test_sonine2_diffusion.cpp): an independent quadrature over both
// Maxwellians and σ̂; elastic equal temperatures: C₀₁ = C₁₀ (self-adjoint operator); elastic
// Lorentz gas (a = 1, β = 2): C₀₁/C₀₀ = −1/2, C₁₁/C₀₀ = 13/4, hence D[2]/D[1] = 13/12.
SonineCollisionIntegrals sonine2_pair_integrals(double weight, double mu, double eps, double Ak, double Ai) {
  const double V = Ak + Ai, a = Ak / V, b = mu * (1.0 + eps);
  const double bP = b * weight * std::sqrt(2.0 * std::numbers::pi * V);
  return {2.0 * bP, -a * bP, -bP * (3.0 * a * a - 9.0 * a * b + 10.0 * a + 4.0 * b * b - 5.0 * b) / a,
          0.5 * bP * (30.0 - 33.0 * b + 12.0 * b * b + 22.0 * a - 9.0 * a * b - 3.0 * a * a)};
}

SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T) {
  const model::Mixture& mix = rates.mixture();
  SonineTracerSums sum;
  for (std::size_t i = 0; i < mix.size(); ++i) {
    const double s = mix.sigma(k, i);
    const SonineTracerSums p = terms.tracer(k, i, mix[i].density * s * s * rates.chi(k, i), mix[k].mass, mix[i].mass, T[k], T[i]);
    sum.C.C00 += p.C.C00, sum.C.C01 += p.C.C01, sum.C.C10 += p.C.C10, sum.C.C11 += p.C.C11;
    sum.xi += p.xi;
  }
  return sum;
}

SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, std::size_t k, const double* T) {
  return sonine2_tracer_sums(rates, *make_sonine_pair_terms(rates.law()), k, T);
}

SonineCollisionIntegrals sonine2_collision_integrals(const CollisionRates& rates, std::size_t k, const double* T) {
  return sonine2_tracer_sums(rates, k, T).C;
}

double sonine2_factor(const SonineCollisionIntegrals& C, double zeta) {
  // D[2]/D[1] = (C₀₀ − ¾ζ) / [C₀₀ − ¾ζ − C₀₁(C₁₀ + 15ζ/4)/(C₁₁ − 45ζ/8)] (physics-beyond §3).
  const double first = C.C00 - 0.75 * zeta, c11 = C.C11 - 5.625 * zeta;
  const double second = first - C.C01 * (C.C10 + 3.75 * zeta) / c11;
  if (!(first > 0.0 && c11 > 0.0 && second > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return first / second;
}

double sonine2_factor(const CollisionRates& rates, std::size_t k, const double* T) {
  // ζ = ξ_k: the tagged species' temperature T_k sets the scaling of its tracer problem, and T_k
  // decays at ξ_k (equal to the common ζ once settled).
  const SonineTracerSums s = sonine2_tracer_sums(rates, k, T);
  return sonine2_factor(s.C, s.xi);
}

double kinetic_velocity_decay_rate(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T) {
  const SonineTracerSums s = sonine2_tracer_sums(rates, terms, k, T);
  const double factor = sonine2_factor(s.C, s.xi);
  // τ_v,k⁻¹ = ν_k − ξ_k/2 (physics-beyond §1; (2/3)C₀₀ − ξ_k/2 of these sums to 1e-12, tested) taken from the
  // rates' own v1 (A1)/(A3), the paper level's: one implementation of τ_v for both levels, so that an error
  // in it moves the judged curves too. No second-Sonine solution: the first-Sonine ν_k.
  const double inv_tau = rates.inv_tau_v_species(k, T);
  return 0.5 * s.xi + inv_tau / (std::isfinite(factor) ? factor : 1.0);
}

double kinetic_velocity_decay_rate(const CollisionRates& rates, std::size_t k, const double* T) {
  return kinetic_velocity_decay_rate(rates, *make_sonine_pair_terms(rates.law()), k, T);
}

SecondSonineDecay::SecondSonineDecay(const CollisionRates& rates, std::shared_ptr<const SoninePairTerms> terms)
    : rates_(rates), terms_(terms ? std::move(terms) : make_sonine_pair_terms(rates.law())) {}

void SecondSonineDecay::rates(const double* T, const double*, double* nu) const {
  for (std::size_t k = 0; k < rates_.size(); ++k) nu[k] = kinetic_velocity_decay_rate(rates_, *terms_, k, T);
}

void SecondSonineDecay::correlation_rates(const CollisionRates&, const double* T, const double*, const double* Q, double* dQ,
                                          double*) const {
  const std::size_t N = rates_.size();
  for (std::size_t k = 0; k < N; ++k) {
    const SonineTracerSums s = sonine2_tracer_sums(rates_, *terms_, k, T);
    const double q = Q[k], p = Q[N + k], source = 3.0 * T[k] / rates_.mixture()[k].mass;
    if (!std::isfinite(sonine2_factor(s.C, s.xi))) {  // no diffusive second-Sonine solution: first-Sonine ν_k
      const double nu1 = 0.5 * s.xi + rates_.inv_tau_v_species(k, T);
      dQ[k] = source - nu1 * q, dQ[N + k] = -nu1 * p;
      continue;
    }
    dQ[k] = source - (2.0 / 3.0) * s.C.C00 * q - (4.0 / 15.0) * s.C.C01 * p;
    // The mode's scaling terms with ξ_k of the same Maxwellian sums as C_pq (see the header).
    dQ[N + k] = s.xi * p - (2.5 * s.xi + (2.0 / 3.0) * s.C.C10) * q - (4.0 / 15.0) * s.C.C11 * p;
  }
}

}  // namespace granmix::theory
