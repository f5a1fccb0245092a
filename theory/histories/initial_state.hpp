#pragma once
#include "theory/histories/temperature_history.hpp"
// Initial partial temperatures of a scene (v1 text at Eq. 22; Fig. 3); see model/initial_state.hpp.
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "model/initial_state.hpp"

namespace granmix::theory {

std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates);

// The aged start (v1 Fig. 3 dashed): from T_k = T_hot, cooled with the closures of `opt` until
// ⟨T⟩ = 1; the temperatures there and the cooling model's own unknowns (the cumulants of a relaxing
// Sonine model: the aged gas is no longer Maxwellian).
struct AgedState {
  std::vector<double> T, z;
};
AgedState aged_state(double T_hot, const CollisionRates& rates, const TemperatureOptions& opt);

}  // namespace granmix::theory
