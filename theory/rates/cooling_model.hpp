#pragma once
// The two closures of the temperature ODE, pluggable (docs/physics-beyond.md §1, §4):
//   CoolingModel   partial cooling rates ξ_k in dT_k/dt = −ξ_k T_k, possibly with extra unknowns z
//                  integrated beside ln T_k (the relaxing Sonine cumulants, sonine_cooling.hpp);
//   VelocityDecay  the velocity correlation of a tagged particle in the VACF ODE: by default one mode,
//                  dQ_k/dt = 3T_k/m_k − ν_k Q_k (docs/physics-beyond.md §2); a model may bring more modes
//                  per species (the kinetic level's second Sonine mode, sonine2_diffusion.hpp).
// The defaults are the paper level (MaxwellClosures): Maxwellian ξ_k (v1 A2) and ν_k = τ_v,k⁻¹ + ξ_k/2,
// the first-Sonine momentum-transfer rate (docs/physics-beyond.md §1 identity). Implementations may keep scratch arrays
// (no allocation per call), so one model object serves one integration at a time.
#include <cstddef>
#include <vector>

#include "theory/rates/collision_rates.hpp"

namespace granmix::theory {

class CoolingModel {
 public:
  virtual ~CoolingModel() = default;
  // Number of extra unknowns z integrated with the temperatures (0 for a closed model).
  virtual std::size_t state_size() const { return 0; }
  // z at t = 0 and its absolute tolerances, given the initial temperatures and the relative tolerance.
  virtual void initial_state(const double* /*T0*/, double /*rtol*/, double* /*z*/, double* /*atol*/) const {}
  // ξ_k at temperatures T (and z), and dz/dt (state_size() values; untouched when 0).
  virtual void rates(const double* T, const double* z, double* xi, double* dz_dt) const = 0;
  // The cumulants c_k = 2a₂,k (docs/physics.md §6) at temperatures T and unknowns z (TemperatureHistory::states)
  // into c; false (c untouched) for a closure without them (Maxwellian: c_k = 0).
  virtual bool cumulants(const double* /*T*/, const double* /*z*/, double* /*c*/) const { return false; }
  // The third Sonine coefficients a₃,k from the unknowns z; false (a3 untouched) for a closure without them.
  virtual bool third_sonine(const double* /*z*/, double* /*a3*/) const { return false; }
};

class VelocityDecay {
 public:
  virtual ~VelocityDecay() = default;
  // ν_k at temperatures T, given the cooling rates ξ_k of the same state (the one-mode ODE's rate).
  virtual void rates(const double* T, const double* xi, double* nu) const = 0;
  // Unknowns per species of the velocity correlation: Q_k = ⟨Δr_k·v_k⟩ and modes() − 1 more.
  virtual std::size_t modes() const { return 1; }
  // Whether correlation_rates uses the species' Sonine coefficients (else they are not computed for it).
  virtual bool uses_sonine_coefficients() const { return false; }
  // dQ/dt of the modes() blocks of N unknowns in Q (block 0: Q_k; d⟨R_k²⟩/dt = 2Q_k) at temperatures T and
  // cooling rates ξ_k = −d ln T_k/dt, and the species' Sonine coefficients a2, a3 of the cooling closure (null:
  // Maxwellian). Default, one mode: dQ_k/dt = 3T_k/m_k − ν_k Q_k with ν_k of rates(); nu: N values of scratch.
  virtual void correlation_rates(const CollisionRates& r, const double* T, const double* xi, const double* Q, double* dQ,
                                 double* nu, const double* a2, const double* a3) const;
  // The rates are affine in Q. A model that keeps what its last correlation_rates call assembled offers
  // Jv = ∂(dQ/dt)/∂Q · v (modes() blocks of N) at that call's state without a collision integral again; without it
  // TemperatureHistory takes difference quotients of the whole right-hand side.
  virtual bool offers_correlation_jacobian() const { return false; }
  virtual void correlation_jacobian_times(const double* /*v*/, double* /*Jv*/) const {}
};

// The paper level, both closures in one object: ξ_k of v1 (A2) (= Garzó–Dufty at a₂ = 0) and
// ν_k = τ_v,k⁻¹ + ξ_k/2 with v1's τ_v,k⁻¹ (A1), the first-Sonine momentum-transfer rate. With
// `fused`, the cooling call also computes τ_v,k⁻¹ in the same pass over the pairs and the decay call
// at the same temperatures reuses it (the VACF MSD of hundreds of species costs one pair pass).
class MaxwellClosures final : public CoolingModel, public VelocityDecay {
 public:
  MaxwellClosures(const CollisionRates& rates, bool fused);
  void rates(const double* T, const double* z, double* xi, double* dz_dt) const override;  // cooling
  void rates(const double* T, const double* xi, double* nu) const override;                // decay

 private:
  const CollisionRates& rates_;
  bool fused_;
  mutable bool cached_ = false;
  mutable std::vector<double> T_, inv_tau_;  // the temperatures of the last fused pass and its τ_v⁻¹
};

}  // namespace granmix::theory
