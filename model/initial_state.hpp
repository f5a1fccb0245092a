#pragma once
// What a scene says about the initial temperatures (theory/histories/initial_state.hpp computes them):
//   equal    all T_k = 1
//   hcs      settled ratios with ⟨T⟩ = 1
//   aged     equal T_k = T_hot, cooled until ⟨T⟩ = 1 (v1 Fig. 3 dashed lines)
//   explicit one value per species
#include <vector>

namespace granmix::model {

struct InitialState {
  enum class Kind { equal, hcs, aged, explicit_list } kind = Kind::equal;
  double T_hot = 100.0;        // aged only
  std::vector<double> values;  // explicit_list only
};

}  // namespace granmix::model
