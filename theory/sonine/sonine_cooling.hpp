#pragma once
// First-Sonine (Garzó–Dufty) partial cooling rates ζ_k(T, c) of N species at any temperature ratios,
// a CoolingModel for TemperatureHistory (docs/physics-beyond.md §4). The rates and the cumulant equations
// are MG's (sonine_system.hpp) evaluated at the current temperatures in physical units: v0 = 1 and
// σ_ref = 1, so λ_k = m_k/(2T_k) and ζ_k = n (z0_k + Σ_j Z_kj c_j), n the total density (at c = 0
// this is v1 (A2), CollisionRates::xi_all). The cumulants c_k = 2a₂,k are either
//   relaxing      integrated with the temperatures (extra unknowns z = c, c(0) given, Maxwellian 0):
//                 dc_k/dt = n (8λ_k²/15)(Σ_j K_kj c_j − A_k), the ⟨V⁴⟩ balance, linear in c as MG's;
//   quasi_static  the steady cumulants at the current temperatures, K c = A at every evaluation.
// Both have the HCS of sonine_hcs as their fixed point. Relaxing is the kinetic level's default:
// DSMC starts from Maxwellians and its cumulants build up over a few collisions (docs/levels.md);
// quasi-static jumps to them at t = 0 and costs an N×N LU per evaluation.
// Any restitution law: the pair terms follow it (sonine_pair_terms.hpp; a viscoelastic ε(u) by quadrature over
// the impact speed, whose cumulants then follow a time-dependent quasi-state as ε → 1). One object serves one
// integration at a time.
#include <memory>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/cooling_model.hpp"
#include "theory/sonine/sonine_system.hpp"

namespace granmix::theory {

enum class CumulantMode { relaxing, quasi_static };

class SonineCooling final : public CoolingModel {
 public:
  // c0: initial cumulants of the relaxing mode (empty: 0, the Maxwellian start); ignored by quasi_static.
  // terms: pair terms shared with another closure (null: the law's own, sonine_pair_terms.hpp).
  explicit SonineCooling(const CollisionRates& rates, CumulantMode mode = CumulantMode::relaxing, std::vector<double> c0 = {},
                         std::shared_ptr<const SoninePairTerms> terms = nullptr);

  CumulantMode mode() const { return mode_; }
  std::size_t state_size() const override { return mode_ == CumulantMode::relaxing ? N_ : 0; }
  void initial_state(const double* T0, double rtol, double* z, double* atol) const override;
  void rates(const double* T, const double* z, double* xi, double* dz_dt) const override;
  // c_k at temperatures T and the model's unknowns z (TemperatureHistory::states): z itself when
  // relaxing, the steady cumulants when quasi-static.
  bool cumulants(const double* T, const double* z, double* c) const override;

 private:
  void assemble(const double* T) const;

  const CollisionRates& rates_;
  CumulantMode mode_;
  std::vector<double> c0_;
  std::size_t N_;
  double n_;  // total density: ν_ref = n σ_ref² v0 with σ_ref = v0 = 1
  mutable SonineSystem system_;
  mutable std::vector<double> lambda_, c_, r_;
  mutable std::vector<double> assembled_T_;  // the temperatures system_ was last assembled at
  mutable bool assembled_ = false;
};

}  // namespace granmix::theory
