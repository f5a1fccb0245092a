#pragma once
// The closed forms of the scalar Sonine collision moments H(p; source), p = 1..4, at constant restitution
// (sonine_moment_cooling.hpp): the rate of ⟨c^(2p)⟩_k at fixed θ_k = T_k/m_k from collisions with species i is
//   β P [H(p; 0) + Σ_q a_kq H(p; q − 1) + Σ_q a_iq H(p; q + 2)] / β   (q = 2, 3, 4),
// H(p; source)/(β P) = Σ coefficient · a^ia · β^ib over the rows of (p, source), with c = v/√(2θ_k),
// a = θ_k/(θ_k + θ_i), β = μ_ik(1 + ε_ki), P = n_i σ_ki² χ_ki √(2π(θ_k + θ_i)); sources 1, 2, 3 are the tagged
// species' own Sonine coefficients a₂, a₃, a₄, sources 4, 5, 6 the partner's. Exact rational coefficients from
// scripts/derive_sonine_moments.py (sympy; the derivation is in its docstring); sonine_moment_table.cpp is its
// output. Rows are sorted by p, source, ia, ib; ia runs down to −p.
#include <array>
#include <cstddef>

namespace granmix::theory {

struct SonineMomentTerm {
  int p, source, ia, ib;
  double coefficient;
};

inline constexpr int sonine_moment_max = 4;      // moments ⟨c²⟩ … ⟨c⁸⟩, Sonine coefficients a₂, a₃, a₄
inline constexpr int sonine_moment_sources = 1 + 2 * (sonine_moment_max - 1);  // Maxwell, own a₂ … a₄, partner's a₂ … a₄
// The rates of one pair per unit Sonine coefficient, entry (p − 1)·sonine_moment_sources + source.
using SonineMomentRates = std::array<double, std::size_t(sonine_moment_max * sonine_moment_sources)>;
inline constexpr std::size_t sonine_moment_term_count = 544;
extern const std::array<SonineMomentTerm, sonine_moment_term_count> sonine_moment_terms;

}  // namespace granmix::theory
