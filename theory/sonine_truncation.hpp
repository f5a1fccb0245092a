#pragma once
// The computed truncation error of the first-Sonine HCS of one species (issue 11's tolerance policy: a
// tolerance is the judged theory's model error, the next order's correction, never a fitted DSMC
// deviation). The next order is the second Sonine approximation (sonine_second_order.hpp); the first-Sonine
// a₂[1] is the one theory/ already uses (sonine_hcs, one species: c/2 = van Noije–Ernst's a₂).
// Speeds are c = v/√(2T/m) of the species; for MG species k, c² = λ_k v*² (sonine_hcs.hpp).
// Limitation: this is a ONE-species result. For the Montanero–Garzó mixtures (near-equal species) the
// one-species truncation at the same α is a proxy for each species' truncation, not a mixture calculation.
// Near α = 1/√2 a₂[1] passes through zero, so the relative forms below diverge there: use the absolute ones.
namespace granmix::theory {

struct SonineTruncation {
  double alpha = 1.0;
  double a2_first = 0.0;   // a₂[1] (first Sonine)
  double a2_second = 0.0;  // a₂[2] (second Sonine, linear scheme)
  double a3_second = 0.0;  // a₃[2]
  // a₃ with a₂ held at a₂[1] (third_sonine_given_a2, Santos–Montanero's variant): not used by the estimates
  // below, reported beside a₃[2] as the spread of the a₃ estimate itself.
  double a3_given_a2_first = 0.0;

  // δ_a₂ = |a₂[2] − a₂[1]| / |a₂[1]|: the model error of the cumulant c = 2a₂ (MG Fig. 2's c_k).
  double a2_relative() const;
  // The a₃ term's share of the distribution, |a₃S₃(c²)| / |1 + a₂[1]S₂(c²)|; the same for MG's
  // G_k = e^(2β_k v*/ζ*) Φ_k (a common factor).
  double phi_a3_relative(double c) const;
  // The whole second-minus-first change of Φ (both normalised, both with ⟨c²⟩ = 3/2):
  // |(a₂[2] − a₂[1])S₂(c²) + a₃S₃(c²)| / |1 + a₂[1]S₂(c²)|.
  double phi_relative(double c) const;
  // MG's Δ as the DSMC builds it, Δ = (2/c_meas)(Φ/Φ_M − 1) with the measured cumulant c_meas = 2a₂
  // (S₃ does not change ⟨c⁴⟩): second Sonine gives S₂ + (a₃/a₂[2])S₃, first Sonine S₂. delta_shift is the
  // absolute change (a₃/a₂[2])S₃(c²); delta_a3_relative = |a₃S₃(c²)| / |a₂[2]S₂(c²)| (diverges where S₂ = 0,
  // at c² = (5 ∓ √10)/2, i.e. c = 0.958 and 2.02: there judge the absolute shift).
  double delta_shift(double c) const;
  double delta_a3_relative(double c) const;
};

// alpha in [0, 1] (constant restitution).
SonineTruncation sonine_truncation(double alpha);

}  // namespace granmix::theory
