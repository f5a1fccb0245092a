#pragma once
// The closed forms of the tracer-diffusion collision integrals C_pq, p, q < 5, at constant restitution
// (docs/physics-beyond.md §3): C_pq = β P Σ coefficient · a^ia · β^ib over the rows of (source, p, q), with
// a = θ_k/(θ_k + θ_i), θ = T/m, β = μ_ik(1 + ε_ki), P = n_i σ_ki² χ_ki √(2π(θ_k + θ_i)); source 0 is the
// Maxwellian partner, sources 1 and 2 the coefficients of the partner's a₂ and a₃ (its scalar Sonine weights).
// Exact rational coefficients from scripts/derive_sonine_cpq.py (sympy; the derivation is in its docstring);
// theory/sonine/sonine_cpq_table.cpp is its output. Rows are sorted by source, p, q, ia, ib (sonine2_diffusion.cpp
// groups them by (source, p, q, ia) for Horner in β); ia runs from −p for source 0 (−4 … 11 in all).
#include <array>
#include <cstddef>

namespace granmix::theory {

struct SonineCpqTerm {
  int source, p, q, ia, ib;
  double coefficient;
};

// Sources of C_pq: 0 the Maxwellian partner, 1 and 2 the coefficients of the partner's a₂ and a₃.
inline constexpr unsigned sonine_cpq_sources = 3;

inline constexpr std::size_t sonine_cpq_term_count = 1810;
extern const std::array<SonineCpqTerm, sonine_cpq_term_count> sonine_cpq_terms;

}  // namespace granmix::theory
