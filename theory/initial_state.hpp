#pragma once
// Initial partial temperatures (v1 text at Eq. 22; Fig. 3):
//   equal    all T_k = 1
//   hcs      settled ratios with ⟨T⟩ = 1 (settled_ratios.hpp)
//   aged     start at equal T_k = T_hot, let the mixture cool until ⟨T⟩ = 1, take the temperatures
//            reached then (v1 Fig. 3 dashed lines)
//   explicit a list, one value per species
#include <string>
#include <vector>

#include "collision_rates.hpp"

namespace granmix::theory {

struct InitialState {
  enum class Kind { equal, hcs, aged, explicit_list } kind = Kind::equal;
  double T_hot = 100.0;       // aged only
  std::vector<double> values;  // explicit_list only
};

std::vector<double> initial_temperatures(const InitialState& init, const CollisionRates& rates);

}  // namespace granmix::theory
