#pragma once
// Tracer limit of a binary mixture (physics.md §4, v2 Sec. II.6): species 1 is the gas, species 2
// the intruder with n_2 → 0. The gas follows Haff's law alone; the intruder temperature ratio
// θ = T_2/T_1 is the root of ξ_21(θ) = ξ_11 with intruder–intruder collisions dropped, and the
// intruder's velocity correlation time is τ_v,21 alone. Values at T_1 = ⟨T⟩ = 1.
#include "collision_rates.hpp"

namespace granmix::theory {

struct TracerLimit {
  double theta = 1.0;  // T_2/T_1
  double tau0 = 0.0;   // gas Haff time 2/ξ_11
  double tau_v_gas = 0.0, tau_v_intruder = 0.0;
  double D_gas = 0.0, D_intruder = 0.0;
};

TracerLimit tracer_limit(const CollisionRates& rates);

}  // namespace granmix::theory
