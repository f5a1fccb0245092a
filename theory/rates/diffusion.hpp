#pragma once
// Diffusion in the settled (HCS) state and the cooling time τ₀ (v1 Eqs. 19–20; docs/physics.md §2–3).
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/velocity_memory.hpp"

namespace granmix::theory {

struct SettledDiffusion {
  std::vector<double> T;        // settled temperatures, ⟨T⟩ = 1
  std::vector<double> tau_v;    // τ_v,k at ⟨T⟩ = 1
  std::vector<double> D;        // D_k = T_k τ_v,k / m_k (v1 Eq. 19)
  std::vector<double> D_ratio;  // D_k / D_1
  double tau0 = 0.0;            // 2/ξ at ⟨T⟩ = 1 (Haff time; infinite for ε = 1)
  // The settled velocity memory of each species (velocity_memory.hpp), where a level has more than the one
  // exponential of (D_k, τ_v,k); empty otherwise.
  std::vector<VelocityMemory> memory;
  VelocityMemory memory_of(std::size_t k) const { return memory.empty() ? VelocityMemory::exponential(D[k], tau_v[k]) : memory[k]; }
};

// Everything at the given temperatures (no settling): τ_v,k, D_k.
SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T);
// The same at the settled temperature ratios.
SettledDiffusion settled_diffusion(const CollisionRates& rates);

}  // namespace granmix::theory
