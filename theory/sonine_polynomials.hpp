#pragma once
// Sonine polynomials of d = 3 in x = c² (c = v/√(2T/m)): the associated Laguerre polynomials L_n^(1/2),
// orthogonal over the Maxwellian φ_M ∝ e^(−c²), with the sign convention of van Noije & Ernst and
// Brilliantov & Pöschel (S_n(0) > 0). Over φ_M: ⟨S_2²⟩ = 15/8, ⟨S_3²⟩ = 35/16, and c⁴ = 2S_2 + lower,
// c⁶ = −6S_3 + lower, so that f = φ_M(1 + a₂S₂ + a₃S₃) has ⟨c⁴⟩ = (15/4)(1 + a₂) and
// ⟨c⁶⟩ = (105/8)(1 + 3a₂ − a₃). MG's Δ_k (Eq. 28) is S_2(λ_k v*²).
namespace granmix::theory {

inline double sonine_S1(double x) { return 2.5 - x; }
inline double sonine_S2(double x) { return 0.5 * x * x - 2.5 * x + 15.0 / 8.0; }
inline double sonine_S3(double x) { return -x * x * x / 6.0 + 1.75 * x * x - 35.0 / 8.0 * x + 35.0 / 16.0; }

}  // namespace granmix::theory
