#pragma once
// Settled (HCS) temperatures: roots of ξ_k = ξ_1 for all k with ⟨T⟩ = Σ n_k T_k / n = 1
// (v1 Eq. 24). For constant ε the rates scale as √T, so the ratios do not depend on ⟨T⟩; for a
// viscoelastic law the same criterion at ⟨T⟩ = 1 gives the momentary ratios (v1 text at Eq. 24).
//   two species: GSL Brent bracketing in ln(T_2/T_1), bracket widened until the sign changes;
//   more:        relax the ratio dynamics d ln T_k/dt = −(ξ_k − ξ̄) at fixed ⟨T⟩ with CVODE
//                (always converges to the stable state), then polish with damped Newton.
// A bare Newton/hybrid start from equal temperatures stalls on m = 1, 100; σ = 1, 1; ε = 0.5.
#include <vector>

#include "theory/rates/collision_rates.hpp"

namespace granmix::theory {

struct SettledState {
  std::vector<double> T;  // ⟨T⟩ = 1
  double residual = 0.0;  // max_k |ξ_k − ξ_1| / scale, scale = max_k(|ξ_k|, τ_v,k⁻¹)
  int iterations = 0;
};

SettledState settled_temperatures(const CollisionRates& rates);

// T_k/T_1 of the settled state.
std::vector<double> settled_ratios(const CollisionRates& rates);

}  // namespace granmix::theory
