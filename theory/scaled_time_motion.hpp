#pragma once
// The displacement of a species whose velocity correlation decays with one exponential in the gas's scaled time s
// (ds = √T₁ dt, T₁(0) = 1; physics-beyond §2), along steps over which everything is constant:
//   ⟨c(s₁)·c(s₂)⟩ = v(s₁) exp(−∫_{s₁}^{s₂} κ ds),  s₁ ≤ s₂,   dR/ds = c,
// v = 3T_k/(m_k T₁) the scaled velocity's mean square and κ = ν_k − ζ/2 its decay (ν_k the collisions' rate of
// erasing the velocity, ζ the gas's cooling rate at T₁ = 1). Per step the Q-form (Q = ⟨ΔR·c⟩) is integrated exactly:
//   dM/ds = 2Q,  dQ/ds = v − κQ.
// With v, κ, ζ constant it is the closed form of msd.hpp and the TAMSD of tamsd.hpp (tests/theory/test_tracer_relaxation.cpp);
// it carries a temperature ratio and memory that change in time (tracer_relaxation.hpp) and a gas cooling at a changing
// rate (the intruders' heating).
#include <cmath>
#include <cstddef>
#include <vector>

namespace granmix::theory {

class ScaledTimeMotion {
 public:
  // Per step n: its length h[n] in s, the gas's cooling rate zeta[n] at T₁ = 1, and the species' v[n], kappa[n].
  ScaledTimeMotion(std::vector<double> h, std::vector<double> zeta, std::vector<double> v, std::vector<double> kappa);
  // ⟨[R(t + lag) − R(t)]²⟩ from the state at real time t (the velocity correlated across t); throws std::out_of_range
  // beyond the steps' last time.
  double increment(double t, double lag) const;
  double msd(double t) const { return increment(0.0, t); }
  // (1/(𝒯 − Δ)) ∫₀^(𝒯−Δ) increment(t, Δ) dt by GSL QAG (relative 1e-10), 𝒯 = measurement_time.
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
  std::vector<double> h_, zeta_, v_, kappa_, t_, T1_, s_;  // t_, T1_, s_ at the steps' starts (one more)
};

}  // namespace granmix::theory
