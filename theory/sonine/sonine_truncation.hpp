#pragma once
// The computed truncation error of the first-Sonine HCS of one species (the tolerance policy of docs/judging.md: a
// tolerance is the judged theory's model error, the next order's correction, never a fitted DSMC
// deviation). The next order is the second Sonine approximation (sonine_second_order.hpp); the first-Sonine
// a₂[1] is the one theory/ already uses (sonine_hcs, one species: c/2 = van Noije–Ernst's a₂).
// Speeds are c = v/√(2T/m) of the species; for MG species k, c² = λ_k v*² (sonine_hcs.hpp).
// Limitation: this is a ONE-species result. For the Montanero–Garzó mixtures (near-equal species) the
// one-species truncation at the same α is a proxy for each species' truncation, not a mixture calculation.
// Near α = 1/√2 a₂[1] passes through zero, so the relative forms below diverge there: use the absolute ones.
#include "theory/sonine/sonine_second_order.hpp"

namespace granmix::theory {

// Which second-order distribution the estimates compare with:
//   linear:   (a₂[2], a₃[2]) of the linear ⟨c⁴⟩, ⟨c⁶⟩ system (Brilliantov & Pöschel 2006);
//   a2_first: a₂ kept at a₂[1], a₃ from the ⟨c⁶⟩ balance alone (third_sonine_given_a2; the variant Santos &
//             Montanero and docs/physics-beyond.md §5 favour). One-species DSMC at α = 0.5 (paper fidelity, seed 1)
//             gives a₃/a₂ = −0.11 … −0.17 (by seed and fit range): a2_first predicts −0.198, linear −0.393.
enum class SonineScheme { linear, a2_first };

struct SonineTruncation {
  double alpha = 1.0;
  double a2_first = 0.0;   // a₂[1] (first Sonine, the judged theory)
  SecondSonine linear;     // (a₂[2], a₃[2])
  SecondSonine a2_fixed;   // (a₂[1], a₃ given a₂[1])

  const SecondSonine& second(SonineScheme s) const { return s == SonineScheme::linear ? linear : a2_fixed; }
  // δ_a₂ = |a₂[2] − a₂[1]| / |a₂[1]| (linear scheme; the other keeps a₂): the model error of the cumulant
  // c = 2a₂ (MG Fig. 2's c_k).
  double a2_relative() const;
  // The a₃ term's share of the distribution, |a₃S₃(c²)| / |1 + a₂[1]S₂(c²)|; the same for MG's
  // G_k = e^(2β_k v*/ζ*) Φ_k (a common factor).
  double phi_a3_relative(double c, SonineScheme s) const;
  // The whole second-minus-first change of Φ (both normalised, both with ⟨c²⟩ = 3/2):
  // |(a₂ − a₂[1])S₂(c²) + a₃S₃(c²)| / |1 + a₂[1]S₂(c²)| (= phi_a3_relative for a2_first).
  double phi_relative(double c, SonineScheme s) const;
  // MG's Δ as the DSMC builds it, Δ = (2/c_meas)(Φ/Φ_M − 1) with the measured cumulant c_meas = 2a₂
  // (S₃ does not change ⟨c⁴⟩): second order gives S₂ + (a₃/a₂)S₃, first Sonine S₂. delta_shift is the
  // absolute change (a₃/a₂)S₃(c²); delta_a3_relative = |a₃S₃(c²)| / |a₂S₂(c²)| (diverges where S₂ = 0,
  // at c² = (5 ∓ √10)/2, i.e. c = 0.958 and 2.02: there judge the absolute shift).
  double delta_shift(double c, SonineScheme s) const;
  double delta_a3_relative(double c, SonineScheme s) const;
};

// alpha in [0, 1] (constant restitution).
SonineTruncation sonine_truncation(double alpha);

}  // namespace granmix::theory
