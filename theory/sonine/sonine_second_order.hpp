#pragma once
// The homogeneous cooling state of ONE species of inelastic hard spheres (d = 3, constant restitution α)
// in the second Sonine approximation, f = φ_M(1 + a₂S₂(c²) + a₃S₃(c²)) (Brilliantov & Pöschel, EPL 74,
// 424 (2006); Santos & Montanero, Granular Matter 11, 157 (2009), their "linear" scheme).
// Reduced units of Brilliantov & Pöschel: c = v/√(2T/m), φ_M = π^(−3/2) e^(−c²), collision moments
//   μ_p = −(1/2) ∫dc₁dc₂ φ_Mφ_M W ∫dσ̂ Θ(−c₁₂·σ̂) |c₁₂·σ̂| Δ(c₁^p + c₂^p),  W = 1 + Σ_i a₂S₂(c_i²) + a₃S₃(c_i²),
// kept linear in a₂, a₃ (products a₂a₃, a₂², … dropped): μ_p = M_p0 + M_p2 a₂ + M_p3 a₃. The HCS (scaled
// distribution stationary) then requires μ_p = (p/3) μ₂ ⟨c^p⟩, i.e.
//   μ₄ = 5 μ₂ (1 + a₂),   μ₆ = (105/4) μ₂ (1 + 3a₂ − a₃),
// linearised in a₂, a₃ as well: two linear equations. The coefficients (sonine_second_order.cpp) are
// exact polynomials in α, obtained by computer algebra (scripts/derive_sonine2_moments.py); μ₂ and μ₄ are
// van Noije & Ernst's (Granular Matter 1, 57 (1998)), and tests/theory/test_sonine_second_order.cpp
// checks all nine against an independent Gauss quadrature of the collision integral to rounding.
#include <array>

namespace granmix::theory {

// Coefficients of μ₂, μ₄, μ₆ divided by √(2π): [0] at a = 0, [1] of a₂, [2] of a₃.
struct HcsCollisionMoments {
  std::array<double, 3> mu2{}, mu4{}, mu6{};
};
HcsCollisionMoments hcs_collision_moments(double alpha);

struct SecondSonine {
  double a2 = 0.0;  // a₂[2]
  double a3 = 0.0;  // a₃[2]
};
// The linear second-Sonine HCS at restitution alpha in [0, 1] (a₂ = a₃ = 0 at α = 1 exactly).
SecondSonine second_sonine_hcs(double alpha);

// The alternative Santos & Montanero and docs/physics-beyond.md §5 favour: a₂ kept at a given value (the first-Sonine
// a₂[1]) and a₃ from the linearised sixth-moment balance alone. The spread between the two a₃ is part of the
// truncation uncertainty (the Sonine expansion converges slowly at strong dissipation: Brilliantov & Pöschel).
double third_sonine_given_a2(double alpha, double a2);

}  // namespace granmix::theory
