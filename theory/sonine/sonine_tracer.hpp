#pragma once
// The tracer limit at the kinetic level (docs/physics-beyond.md §3–4): species 1 the gas, species 2
// an intruder with n₂ → 0, values at T₁ = 1. The same closures as the kinetic level of a mixture, with
// the collisions the tracer limit drops left out (gas–intruder for the gas, intruder–intruder):
//   θ = T₂/T₁   the first-Sonine (Garzó–Dufty) HCS of the pair, MG Eqs. (31)–(45) with those collisions'
//               contact values set to 0: the gas keeps its one-species a₂ (van Noije–Ernst), the intruder
//               has its own a₂ from its ⟨V⁴⟩ balance with the gas, and ζ₂(θ; c₁, c₂) = ζ₁(c₁);
//   τ₀ = 2/ζ₁   the gas's first-Sonine cooling rate (ζ₁ = ξ₁₁ (1 + 3c₁/32), c₁ = 2a₂);
//   D_k         to Sonine order M (sonine2_diffusion.hpp) of the gas (self-diffusion) and of the intruder
//               among the gas, each scaled with its own Maxwellian ξ_k as the mixture's kinetic level does;
//               τ_v,k = D_k m_k/T_k, so that the closed MSD and TAMSD (msd.hpp, tamsd.hpp) are those of the
//               velocity correlation decaying at ν_eff = ξ_k/2 + τ_v,k⁻¹ (docs/physics-beyond.md §2–3).
// Equal to the mixture's kinetic level at n₂/n₁ → 0 (tests/theory/test_sonine_tracer.cpp). Where the first
// Sonine has no settled state (elastic gas: the Maxwellian equilibrium, θ = 1; a viscoelastic law) θ and τ₀
// are the Maxwellian tracer values (tracer_limit.hpp); where the order M has no diffusive solution
// (NaN factor) D_k stays first-Sonine.
#include <cstddef>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/tracer_limit.hpp"

namespace granmix::theory {

// Which corrections over the paper's tracer form are on: both off gives tracer_limit() (to the root tolerance).
struct SonineTracerClosure {
  bool cumulants = true;      // a₂ of gas and intruder in θ and ζ₁ (off: MG at c = 0, = v1 A2)
  std::size_t sonine_order = 2;  // D_k[sonine_order] (sonine2_diffusion.hpp); 1: the first-Sonine D_k
};

TracerLimit sonine_tracer_limit(const CollisionRates& rates, SonineTracerClosure closure = {});

}  // namespace granmix::theory
