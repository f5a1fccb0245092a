#pragma once
#include "dsmc/ensemble.hpp"
// The tagged-particle velocity memory (docs/physics-beyond.md §2): Q = ⟨R·v⟩ obeys
//   dQ/dt = ⟨v²⟩ − ν Q,  dM/dt = 2Q  (M = ⟨R²⟩, Q(0) = M(0) = 0),
// where ⟨v²⟩ = 3T_k/m_k is exact (free flight between collisions) and ν is whatever the collisions do
// to R·v: the first-Sonine theory says ν_k = τ_v,k⁻¹ + ξ_k/2. Measured in a window [a, b]:
//   ν_eff = [∫_a^b ⟨v²⟩ dt − (Q(b) − Q(a))] / ∫_a^b Q dt.
// Integrals by Simpson's rule in s = ln t on a grid uniform in ln t (power laws in t are smooth in s).
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace granmix::bench {

// ∫ f dt over [t[a], t[b]] (b − a even) from samples f[j] on a grid uniform in ln t.
double integral_log_grid(const std::vector<double>& t, const std::vector<double>& f, std::size_t a, std::size_t b);

// ν_eff over [t[a], t[b]] from samples of ⟨v²⟩ and Q.
double effective_rate(const std::vector<double>& t, const std::vector<double>& v2, const std::vector<double>& Q, std::size_t a,
                      std::size_t b);

// M(t_j) from the ODE above with ⟨v²⟩ and ν given at the samples (interpolated as power laws between
// them; ν linearly where it is not positive), RK4 with steps ν Δt <= 0.05. Before t[0] the motion is
// taken as ballistic (M = ⟨v²⟩ t², Q = ⟨v²⟩ t): the grid must start at ν t[0] ≪ 1.
std::vector<double> msd_from_memory(const std::vector<double>& t, const std::vector<double>& v2, const std::vector<double>& nu);

// Jackknife over R replicas: the DSMC's own (f gets the replica left out, or npos for none).
using dsmc::jackknife;

}  // namespace granmix::bench
