#pragma once
// The closed forms of the tracer-diffusion collision integrals C_pq, p, q < 5, at constant restitution
// (physics-beyond.md §3): C_pq = β P Σ coefficient · a^ia · β^ib over the rows of (p, q), with
// a = θ_k/(θ_k + θ_i), θ = T/m, β = μ_ik(1 + ε_ki), P = n_i σ_ki² χ_ki √(2π(θ_k + θ_i)).
// Exact rational coefficients from scripts/derive_sonine_cpq.py (sympy; the derivation is in its docstring);
// theory/sonine_cpq_table.cpp is its output. Rows are sorted by p, q, ia, ib (sonine2_diffusion.cpp groups them
// by (p, q, ia) for Horner in β); ia runs down to −p.
#include <array>
#include <cstddef>

namespace granmix::theory {

struct SonineCpqTerm {
  int p, q, ia, ib;
  double coefficient;
};

inline constexpr std::size_t sonine_cpq_term_count = 395;
extern const std::array<SonineCpqTerm, sonine_cpq_term_count> sonine_cpq_terms;

}  // namespace granmix::theory
