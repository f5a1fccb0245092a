#pragma once
// Moments of the restitution coefficient over the Maxwellian collision measure of a pair,
// weight u³ exp(-u²/(2V)) du on u = |g·e| >= 0, V = T_k/m_k + T_i/m_i:
//   W2 = ⟨(1+ε)²⟩   (velocity correlation)      D = ⟨1−ε²⟩   (energy loss)
// With them every rate of v1 Appendix A is one formula (see collision_rates.hpp):
//   constant ε:   W2 = (1+ε)², D = (1−ε)(1+ε)                       -> v1 Eqs. (A1), (A2)
//   series ε:     W2 = 4(1 + ½Σ A_n B_n), D = −Σ (2h_n + Σh_jh_l) 2B_n   -> v1 Eqs. (A3), (A4)
//   any ε(u):     1-D quadrature (exact contact table or Padé)     -> the same rates without the series
// D is carried instead of ⟨1+ε⟩ because 2⟨1+ε⟩ − ⟨(1+ε)²⟩ cancels catastrophically near ε = 1.
// B_n = ½ a^n Γ(2+n/20), a = (Aκ^(2/5))^(1/2) (2V)^(1/20)  (docs/physics.md §5; ⟨y^n⟩ = 2B_n).
#include "model/viscoelastic.hpp"

namespace granmix::theory {

struct CollisionMoments {
  double W2 = 4.0;  // ⟨(1+ε)²⟩
  double D = 0.0;   // ⟨1−ε²⟩
};

inline CollisionMoments constant_moments(double eps) { return {(1.0 + eps) * (1.0 + eps), (1.0 - eps) * (1.0 + eps)}; }

// a = (Aκ^(2/5))^(1/2) (2V)^(1/20): the only combination the viscoelastic moments depend on.
double viscoelastic_scale(double akappa, double V);

// v1 Eqs. (A3)/(A4): the truncated series h_1..h_9, moments in closed form.
CollisionMoments series_moments(double a);
// Gauss–Kronrod quadrature of the same moments with ε(y) of the given form (relative error ~1e-13).
CollisionMoments quadrature_moments(double a, model::ViscoelasticForm form);

}  // namespace granmix::theory
