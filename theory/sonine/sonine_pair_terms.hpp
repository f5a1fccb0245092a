#pragma once
// Where the first-Sonine pair terms come from, chosen once per restitution law:
//   constant ε    MG's closed forms (sonine_terms.hpp) and the closed C_pq (sonine_cpq_table.hpp);
//   ε(u)          the quadrature over the normal impact speed (sonine_quadrature.hpp). ε depends on the
//                 physical impact speed, so the λ's must be in units with v0 = 1: λ_k = m_k/(2T_k).
// SonineSystem (cooling rates and cumulant equations) and the tracer sums of D to Sonine order M ask this object,
// never the law, so a viscoelastic gas gets the same kinetic level as a constant-ε one. The quadrature keeps
// the ε of its last evaluation per pair (no allocation, the same ε for the cooling and the decay closures
// when they share the object): like the closures, one object serves one integration at a time.
#include <array>
#include <cstddef>
#include <memory>

#include "model/restitution.hpp"
#include "theory/sonine/sonine2_diffusion.hpp"
#include "theory/sonine/sonine_moment_table.hpp"
#include "theory/sonine/sonine_terms.hpp"

namespace granmix::theory {

// λ_k = m_k v0²/(2T_k) of every species with √λ_k and 1/√λ_k, made once per assembly (SonineSystem).
struct SonineLambdas {
  const double *lambda, *sqrt_lambda, *inv_sqrt_lambda;
};

class SoninePairTerms {
 public:
  virtual ~SoninePairTerms() = default;
  // Species i with itself (w = x_i χ_ii s_ii), as sonine_self; and with every partner j at once into out's arrays (w[j] =
  // x_j χ_ij s_ij, mu[j] = m_j/(m_i+m_j)), as sonine_cross — entry j = i is written too and means nothing (the caller
  // drops it).
  virtual SonineMoments self(std::size_t i, double w, double lambda_i) const = 0;
  virtual void cross_row(std::size_t i, const double* w, const double* mu, const SonineLambdas& l, const SonineRow& out) const = 0;
  // Whether cross_row() and moments() may run on several threads at once, for distinct i resp. k (the closed forms:
  // yes; the quadrature shares its per-pair cache of ε between (i, j) and (j, i): no). SonineSystem::assemble and
  // SonineMomentCooling's assembly split their rows over threads when they may.
  virtual bool concurrent() const = 0;
  // The tracer problem of k with partner i (weight = n_i σ_ki² χ_ki, masses, temperatures): the Maxwellian
  // C_pq (p, q < modes) and ξ_ki (v1 A2 at constant ε, its quadrature otherwise); with partner_sonine also the
  // coefficients of the partner's a₂, a₃ in C_pq (closed forms at constant ε; the quadrature leaves them zero).
  virtual SonineTracerSums tracer(std::size_t k, std::size_t i, double weight, double mk, double mi, double Tk, double Ti,
                                  std::size_t modes, bool partner_sonine) const = 0;
  // The moment closure's pair rates at `order` 2 … 4 (sonine_moment_cooling.hpp): rates of ⟨c^(2p)⟩_k from collisions
  // with i per unit Sonine coefficient, in the table's layout (sonine_moment_table.hpp: Maxwell, own a₂ … a₄,
  // partner's a₂ … a₄); weight = n_i σ_ki² χ_ki. Closed forms at constant ε (every entry), the quadrature over the
  // impact speed otherwise (sonine_quadrature.hpp: entries beyond `order`, at least 3, are NaN).
  virtual SonineMomentRates moments(std::size_t k, std::size_t i, double weight, double mk, double mi, double Tk, double Ti, int order) const = 0;
  // moments() of species k with every partner i < N (all species) at once — weight[i], the masses m and temperatures T
  // of all species — into out[i], the same numbers: as many calls of moments() (the quadrature), or four partners per
  // vector (the closed forms: each lane's operations those of one pair's; SonineMomentCooling's assembly, N² pairs per
  // right-hand side).
  virtual void moments_row(std::size_t k, std::size_t N, const double* weight, const double* m, const double* T, int order,
                           SonineMomentRates* out) const;
};

std::shared_ptr<const SoninePairTerms> make_sonine_pair_terms(const model::Restitution& law);

}  // namespace granmix::theory
