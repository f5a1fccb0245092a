#pragma once
// The kinetic level's temperatures at Sonine order 3 (constant restitution): every species carries
// a₂ and a₃, f_k = f_M,k [1 + a_k2 S₂(c²) + a_k3 S₃(c²)] (S_p = L_p^(1/2)), relaxing from the Maxwellian
// start with the temperatures. The balances of ⟨c⁴⟩_k and ⟨c⁶⟩_k (c = v/√(2θ_k), θ = T/m) under
// collisions and the cooling θ̇_k = −ζ_k θ_k:
//   d⟨c^(2p)⟩_k/dt = R_kp + p ζ_k ⟨c^(2p)⟩_k,     ζ_k = −R_k1/(3/2),
// R_kp the collisional rate at fixed θ (sonine_moment_table.hpp, linear in the a's; the product of ζ's a-part
// with the moments' a-part is dropped, as MG's first Sonine drops it), ⟨c⁴⟩ = 15/4 (1 + a₂) and
// ⟨c⁶⟩ = 105/8 (1 + 3a₂ − a₃). At order 2 (a₃ ≡ 0, no ⟨c⁶⟩ balance) this is MG's first Sonine, i.e.
// SonineCooling's relaxing mode, to rounding (tested). Why order 3: DSMC's light species of v1 Figs. 2, 9, 10 run
// 2–4% warmer than the first-Sonine rates say, and `granmix bench gaps` shows the rates are right when given the
// measured c_k(t): it is the ⟨c⁴⟩ balance truncated at a₂ that is wrong for a species far from its partners'
// temperature (v1 Fig. 2: first Sonine settles its c₁ at 0.038, order 3 at 0.008, DSMC at −0.005 ± 0.003).
// Order 4 adds a₄ and the ⟨c⁸⟩ balance, ⟨c⁸⟩ = 945/16 (1 + 6a₂ − 4a₃ + a₄): the next order's
// correction to order 3's temperatures, the model error its scenes judge with (level kinetic-cooling4).
// Unknowns z: c_k = 2a_k2 (the cumulant, as SonineCooling's), then a_k3 (order ≥ 3), then a_k4 (order 4). One object
// serves one integration at a time.
#include <array>
#include <cstddef>
#include <vector>

#include <memory>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/cooling_model.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"

namespace granmix::theory {

// The rates of ⟨c^(2p)⟩_k, p = 1..4, at fixed θ_k from collisions with species i, per unit Sonine coefficient:
// entry (p − 1)·7 + source, sources Maxwell, own a₂, a₃, a₄, partner's a₂, a₃, a₄ (sonine_moment_table.hpp);
// weight = n_i σ_ki² χ_ki, mu = μ_ik = m_i/(m_i + m_k), A = T/m of k and i. order 2 or 3: only the entries of
// p ≤ 3 and a₂, a₃ (the rest NaN, as sonine_moment_quadrature's), from a table of those rows alone.
SonineMomentRates sonine_moment_pair(double weight, double mu, double eps, double Ak, double Ai, int order = sonine_moment_max);
// The same from the table's polynomials in β = μ_ik(1 + ε) (constant per pair: callers keep them), of the same order.
std::vector<double> sonine_moment_beta_polynomials(double beta, int order);
SonineMomentRates sonine_moment_pair_from(const std::vector<double>& polys, double weight, double beta, double Ak, double Ai, int order);
// Four pairs at once, lane l from weight[l], beta[l], Ak[l], Ai[l] and the polynomials interleaved, polys4[4·j + l]
// (`groups` = sonine_moment_beta_polynomials(·, order).size()): out[l] is exactly sonine_moment_pair_from's, for the
// first `lanes` lanes.
void sonine_moment_pairs4_from(const double* polys4, std::size_t groups, const double* weight, const double* beta, const double* Ak,
                               const double* Ai, int order, SonineMomentRates* out, std::size_t lanes = 4);

// From this many species the pair terms of a right-hand side are assembled on OpenMP threads (species by species):
// ~0.15 µs per pair at constant ε, so 16 species take ~40 µs, well above a fork and join; v1 Fig. 8's 43 species
// spent ~10% of its judged level's single-thread time here.
inline constexpr std::size_t parallel_moment_species = 16;

class SonineMomentCooling final : public CoolingModel {
 public:
  // order 2, 3 or 4; z0: the initial unknowns (empty: 0, the Maxwellian start); terms: the pair terms (null: made
  // from the law — closed forms at constant ε, the quadrature over the impact speed for a viscoelastic law).
  SonineMomentCooling(const CollisionRates& rates, int order, std::vector<double> z0 = {},
                      std::shared_ptr<const SoninePairTerms> terms = nullptr);

  int order() const { return order_; }
  std::size_t state_size() const override { return std::size_t(order_ - 1) * N_; }
  void initial_state(const double* T0, double rtol, double* z, double* atol) const override;
  void rates(const double* T, const double* z, double* xi, double* dz_dt) const override;
  bool cumulants(const double* T, const double* z, double* c) const override;
  bool third_sonine(const double* z, double* a3) const override;
  // The unknowns that are steady at these temperatures: dz/dt is affine in z at fixed T (the closure is
  // linear in the a's), so its zero is one linear solve (probed column by column, full-pivot LU); NumericalError
  // if singular. In the HCS (all ζ_k equal, sonine_hcs at order 3) these are the settled a's.
  std::vector<double> steady_state(const double* T) const;

 private:
  void assemble(const double* T) const;

  const CollisionRates& rates_;
  int order_;
  std::size_t N_;
  std::vector<double> z0_;
  std::shared_ptr<const SoninePairTerms> terms_;
  // At the last temperatures (assemble): per species k and moment p = 1..4 the Maxwell part R0 and the
  // coefficients of the own a₂ … a₄ (self_), per pair (k, i) those of the partner's (partner_).
  mutable std::vector<double> assembled_T_, R0_, self_, partner_, masses_;
  mutable bool assembled_ = false;
};

}  // namespace granmix::theory
