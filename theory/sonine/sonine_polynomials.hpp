#pragma once
// Sonine polynomials of d = 3 in x = c² (c = v/√(2T/m)): the associated Laguerre polynomials L_n^(1/2),
// orthogonal over the Maxwellian φ_M ∝ e^(−c²), with the sign convention of van Noije & Ernst and
// Brilliantov & Pöschel (S_n(0) > 0). Over φ_M: ⟨S_2²⟩ = 15/8, ⟨S_3²⟩ = 35/16, and c⁴ = 2S_2 + lower,
// c⁶ = −6S_3 + lower, so that f = φ_M(1 + a₂S₂ + a₃S₃) has ⟨c⁴⟩ = (15/4)(1 + a₂) and
// ⟨c⁶⟩ = (105/8)(1 + 3a₂ − a₃). MG's Δ_k (Eq. 28) is S_2(λ_k v*²).
// The vector basis of the diffusion problem, c S_p(c²) (docs/physics-beyond.md §3), uses L_p^(3/2) instead:
// sonine_S1 below is L_1^(3/2) = 5/2 − x, and sonine_vector_basis gives them all.
#include <cstddef>

namespace granmix::theory {

inline double sonine_S1(double x) { return 2.5 - x; }
inline double sonine_S2(double x) { return 0.5 * x * x - 2.5 * x + 15.0 / 8.0; }
inline double sonine_S3(double x) { return -x * x * x / 6.0 + 1.75 * x * x - 35.0 / 8.0 * x + 35.0 / 16.0; }
inline double sonine_S4(double x) { return x * x * x * x / 24.0 - 0.75 * x * x * x + 63.0 / 16.0 * x * x - 105.0 / 16.0 * x + 315.0 / 128.0; }

// E[S_p(c²) | c_z] = L_p^(−1/2)(y), y = c_z²: the two perpendicular components, |c_⊥|² ~ Exp(1) over φ_M, averaged
// out (the Laguerre index drops by one per exponential convolution). The quadratures over the impact speed use them
// for the partner's Sonine weight (sonine_quadrature.cpp).
inline double sonine_axial_S2(double y) { return 0.5 * y * y - 1.5 * y + 0.375; }
inline double sonine_axial_S3(double y) { return -y * y * y / 6.0 + 1.25 * y * y - 1.875 * y + 0.3125; }
inline double sonine_axial_S4(double y) { return y * y * y * y / 24.0 - 7.0 / 12.0 * y * y * y + 35.0 / 16.0 * y * y - 35.0 / 16.0 * y + 35.0 / 128.0; }

// S[p] = L_p^(3/2)(x), p < modes (the recurrence (n+1)L_{n+1} = (2n + 5/2 − x)L_n − (n + 3/2)L_{n−1}).
inline void sonine_vector_basis(double x, std::size_t modes, double* S) {
  if (modes > 0) S[0] = 1.0;
  if (modes > 1) S[1] = 2.5 - x;
  for (std::size_t n = 1; n + 1 < modes; ++n)
    S[n + 1] = ((2.0 * double(n) + 2.5 - x) * S[n] - (double(n) + 1.5) * S[n - 1]) / double(n + 1);
}

}  // namespace granmix::theory
