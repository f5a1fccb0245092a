#pragma once
#include "theory/histories/temperature_history.hpp"
// Initial partial temperatures of a scene (v1 text at Eq. 22; Fig. 3); see model/initial_state.hpp.
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "model/initial_state.hpp"

namespace granmix::theory {

std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates);

// A tracer scene's start (docs/physics.md §4): the gas at T₁ = 1, the intruders at θ₀ = T₂/T₁ of the scene's own initial
// state (`hcs`: the Maxwellian settled ratios, v1 Eq. A2), whichever level the scene judges. DSMC and the relaxing tracer
// form both start there, so a wrong θ in the judged level cannot move DSMC's start with it. Only the ratio is taken:
// the finite mixture's ⟨T⟩ = 1 normalisation would cool the gas by n₂θ/n₁.
double tracer_start_theta(const model::InitialState& init, const CollisionRates& rates);

// The aged start (v1 Fig. 3 dashed): from T_k = T_hot, cooled with the closures of `opt` until
// ⟨T⟩ = 1; the temperatures there and the cooling model's own unknowns (the cumulants of a relaxing
// Sonine model: the aged gas is no longer Maxwellian).
struct AgedState {
  std::vector<double> T, z;
};
AgedState aged_state(double T_hot, const CollisionRates& rates, const TemperatureOptions& opt);

}  // namespace granmix::theory
