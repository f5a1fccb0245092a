#pragma once
// The displacement of a species whose velocity correlation is a sum of exponential modes in the gas's scaled time s
// (ds = √T₁ dt, T₁(0) = 1; docs/physics-beyond.md §2), along steps over which every mode's weight and rate are constant:
//   ⟨c(s₁)·c(s₂)⟩ = Σ_j a_j(s₁) exp(−∫_{s₁}^{s₂} κ_j ds),  s₁ ≤ s₂,   dR/ds = c,
// Σ_j a_j = 3T_k/(m_k T₁) the scaled velocity's mean square, κ_j complex in conjugate pairs (velocity_memory.hpp's
// modes, shifted by −Δζ/2 where the gas cools at ζ₁ + Δζ). Per mode the Q-form (Q_j = the mode's part of ⟨ΔR·c⟩) is
// integrated exactly over each step:
//   dM_j/ds = 2Q_j,  dQ_j/ds = a_j − κ_j Q_j.
// With a, κ, ζ constant it is the closed form of velocity_memory.hpp (tests/theory/test_tracer_relaxation.cpp); it
// carries a temperature ratio and memory that change in time (tracer_relaxation.hpp) and a gas cooling at a changing
// rate (the intruders' heating).
#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

namespace granmix::theory {

struct MotionMode {
  std::vector<std::complex<double>> weight, kappa;  // a_j and κ_j per step
};

class ScaledTimeMotion {
 public:
  // Per step n: its length h[n] in s and the gas's cooling rate zeta[n] at T₁ = 1; the modes' values per step.
  ScaledTimeMotion(std::vector<double> h, std::vector<double> zeta, std::vector<MotionMode> modes);
  // ⟨[R(t + lag) − R(t)]²⟩ from the state at real time t (the velocity correlated across t); throws std::out_of_range
  // beyond the steps' last time.
  double increment(double t, double lag) const;
  double msd(double t) const;
  // (1/(𝒯 − Δ)) ∫₀^(𝒯−Δ) increment(t, Δ) dt, 𝒯 = measurement_time, by Gauss–Legendre between the steps' ends.
  double tamsd(double measurement_time, double lag) const;
  double end_time() const { return t_.back(); }
  // Where real time t falls: step n, σ into it (throws std::out_of_range outside [0, end_time()]); the gas's T₁ and the
  // scaled time s there.
  struct Place {
    std::size_t n;
    double sigma;
  };
  Place locate(double t) const;
  double T1(const Place& p) const { return T1_[p.n] * std::exp(-zeta_[p.n] * p.sigma); }
  double scaled_time(const Place& p) const { return s_[p.n] + p.sigma; }

 private:
  // One mode's state from s = 0 (Q = 0): M, Q and K = ∫κ ds.
  struct ModeState {
    std::complex<double> M, Q, K;
  };
  static ModeState state_after(const ModeState& x, std::complex<double> a, std::complex<double> kappa, double sigma);
  ModeState state(std::size_t j, const Place& p) const;
  // L_j(a, b) = ∫_a^b exp(−∫_a^σ κ_j) dσ = R(a) − e^(−(K(b) − K(a))) R(b), R(x) = L_j(x, last step's end): no exponential
  // of a growing K (a fast mode's would overflow), no difference of saturated integrals.
  std::complex<double> carried(std::size_t j, const Place& a, const Place& b) const;
  std::complex<double> rest(std::size_t j, const Place& p) const;  // R_j at p
  std::vector<double> h_, zeta_, t_, T1_, s_;  // t_, T1_, s_ at the steps' starts (one more)
  std::vector<MotionMode> modes_;
  std::vector<std::vector<ModeState>> nodes_;          // per mode, at the steps' starts
  std::vector<std::vector<std::complex<double>>> rest_;  // per mode, R at the steps' starts
};

}  // namespace granmix::theory
