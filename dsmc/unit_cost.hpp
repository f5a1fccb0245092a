#pragma once
// Expected cost of one replica of a DSMC set-up, in collisions (particles × collisions per particle):
// what the scheduler (compare/scheduler.hpp) sorts its units by, longest first, and what the makespan
// simulation of `granmix bench schedule` starts from. An estimate for ordering work, never reported as
// physics: Haff's law with the set-up's initial mean collision frequency ν̄ and cooling rate ξ̄,
//   collisions per particle to t = (2ν̄/ξ̄) ln(1 + ξ̄ t/2)   (T = T0/(1 + ξ̄ t/2)², ν ∝ √T),
// ν̄ t for an elastic gas, plus the collisions that cool an aged start from T_hot to ⟨T⟩ = 1; for a
// viscoelastic law (ε → 1 as the gas cools) the same balance integrated in ln T with ε at the thermal speed.
#include "ensemble.hpp"

namespace granmix::dsmc {

double estimated_collisions(const DsmcSetup& setup);

}  // namespace granmix::dsmc
