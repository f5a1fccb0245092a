#pragma once
// The closed forms of the scalar Sonine collision moments H(p; source), p = 1..3, at constant restitution
// (sonine_moment_cooling.hpp): the rate of ⟨c^(2p)⟩_k at fixed θ_k = T_k/m_k from collisions with species i is
//   β P [H(p; 0) + a_k2 H(p; 1) + a_k3 H(p; 2) + a_i2 H(p; 3) + a_i3 H(p; 4)] / β,
// H(p; source)/(β P) = Σ coefficient · a^ia · β^ib over the rows of (p, source), with c = v/√(2θ_k),
// a = θ_k/(θ_k + θ_i), β = μ_ik(1 + ε_ki), P = n_i σ_ki² χ_ki √(2π(θ_k + θ_i)); sources 1, 2 are the tagged
// species' own Sonine coefficients a₂, a₃, sources 3, 4 the partner's. Exact rational coefficients from
// scripts/derive_sonine_moments.py (sympy; the derivation is in its docstring); sonine_moment_table.cpp is its
// output. Rows are sorted by p, source, ia, ib; ia runs down to −p.
#include <array>
#include <cstddef>

namespace granmix::theory {

struct SonineMomentTerm {
  int p, source, ia, ib;
  double coefficient;
};

inline constexpr int sonine_moment_max = 3;      // moments ⟨c²⟩ … ⟨c⁶⟩, Sonine coefficients a₂, a₃
inline constexpr int sonine_moment_sources = 5;  // Maxwell, own a₂, own a₃, partner's a₂, partner's a₃
// The rates of one pair per unit Sonine coefficient, entry (p − 1)·sonine_moment_sources + source.
using SonineMomentRates = std::array<double, std::size_t(sonine_moment_max * sonine_moment_sources)>;
inline constexpr std::size_t sonine_moment_term_count = 187;
extern const std::array<SonineMomentTerm, sonine_moment_term_count> sonine_moment_terms;

}  // namespace granmix::theory
