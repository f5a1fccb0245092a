#pragma once
// Tracer limit of a binary mixture (docs/physics.md §4, v2 Sec. II.6): species 1 is the gas, species 2
// the intruder with n_2 → 0. The gas follows Haff's law alone; the intruder temperature ratio
// θ = T_2/T_1 is the root of ξ_21(θ) = ξ_11 with intruder–intruder collisions dropped, and the
// intruder's velocity correlation time is τ_v,21 alone. Values at T_1 = ⟨T⟩ = 1.
// This is the paper level's tracer form; the kinetic level's is sonine_tracer.hpp.
#include "theory/rates/collision_rates.hpp"

namespace granmix::theory {

struct TracerLimit {
  double theta = 1.0;  // T_2/T_1
  double tau0 = 0.0;   // gas Haff time 2/ξ_11
  double tau_v_gas = 0.0, tau_v_intruder = 0.0;
  double D_gas = 0.0, D_intruder = 0.0;
};

TracerLimit tracer_limit(const CollisionRates& rates);

// The Maxwellian velocity memories τ_v,11 and τ_v,21 (v1 A1) and D_k = T_k τ_v,k/m_k (v1 Eq. 19) at
// T_1 = 1, T_2 = θ, with the given Haff time: the tracer state of any closure of θ and τ₀.
TracerLimit tracer_state(const CollisionRates& rates, double theta, double tau0);

}  // namespace granmix::theory
