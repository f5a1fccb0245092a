#pragma once
// Initial partial temperatures of a scene (v1 text at Eq. 22; Fig. 3); see model/initial_state.hpp.
#include <vector>

#include "collision_rates.hpp"
#include "model/initial_state.hpp"

namespace granmix::theory {

std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates);

}  // namespace granmix::theory
