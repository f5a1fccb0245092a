#include "theory/sonine/sonine_tracer.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "theory/sonine/sonine2_diffusion.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"

namespace granmix::theory {

namespace {

// The contact values of the tracer problem: the gas does not see the intruders, the intruders do not see
// each other (n₂ → 0). MG's equations take χ per row, so this is exact at any n₂.
std::vector<std::vector<double>> tracer_contact_values(const CollisionRates& r) {
  std::vector<std::vector<double>> chi = r.contact_values();
  chi[0][1] = 0.0, chi[1][1] = 0.0;
  return chi;
}

// θ and τ₀ of the first-Sonine tracer HCS (c = 0 with maxwell: MG's ζ at c = 0 is v1 A2).
TracerLimit sonine_settled(const CollisionRates& r, bool maxwell) {
  const model::Mixture& mix = r.mixture();
  const SonineHcs h = sonine_hcs(mix, r.law(), tracer_contact_values(r), maxwell);
  // ζ₁ = ζ* n σ₁₂² v0 (sonine_hcs.hpp units: n the total density, v0² = 2(m₁+m₂)/(m₁m₂) at T = Σ x_k T_k = 1),
  // at T₁ = h.T[0]; every rate scales as √T₁ at fixed θ.
  const double m1 = mix[0].mass, m2 = mix[1].mass, s12 = mix.sigma(0, 1);
  const double v0 = std::sqrt(2.0 * (m1 + m2) / (m1 * m2));
  const double zeta1 = h.zeta_star * mix.total_density() * s12 * s12 * v0 / std::sqrt(h.T[0]);
  return tracer_state(r, h.T[1] / h.T[0], zeta1 > 0.0 ? 2.0 / zeta1 : std::numeric_limits<double>::infinity());
}

// D_k[M]/D_k[1] of species k colliding with partner i only, at T_k, T_i (ζ = that pair's Maxwellian ξ_ki).
double pair_sonine_factor(const CollisionRates& r, const SoninePairTerms& terms, std::size_t k, std::size_t i, double Tk, double Ti,
                          std::size_t modes) {
  const SonineTracerSums p = sonine_pair_sums(r, terms, k, i, Tk, Ti, modes);
  const double f = sonine_factor(p.C, p.xi);
  return std::isfinite(f) ? f : 1.0;
}

}  // namespace

TracerLimit sonine_tracer_limit(const CollisionRates& r, SonineTracerClosure closure) {
  if (r.size() != 2) throw std::invalid_argument("tracer limit: needs exactly two species (gas, intruder)");
  const model::Restitution& law = r.law();
  const bool settles = !law.is_viscoelastic() && law.eps(0, 0) < 1.0;
  TracerLimit out = settles ? sonine_settled(r, !closure.cumulants) : tracer_limit(r);
  if (closure.sonine_order < 2) return out;
  const auto terms = make_sonine_pair_terms(law);
  const double f_gas = pair_sonine_factor(r, *terms, 0, 0, 1.0, 1.0, closure.sonine_order);
  const double f_intruder = pair_sonine_factor(r, *terms, 1, 0, out.theta, 1.0, closure.sonine_order);
  out.D_gas *= f_gas, out.tau_v_gas *= f_gas;  // τ_v = D m/T: the memory of the closed MSD
  out.D_intruder *= f_intruder, out.tau_v_intruder *= f_intruder;
  return out;
}

}  // namespace granmix::theory
