#pragma once
// A Monte Carlo of the tagged-particle (Boltzmann–Lorentz) problem, written independently of theory/: the check of the
// tracer problems' diffusion coefficients (test_sonine2_diffusion.cpp) and stationary temperatures
// (test_tracer_temperature.cpp).
#include <array>
#include <cstdint>
#include <vector>

namespace granmix::test {

using Vec = std::array<double, 3>;
inline double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec axpy(double s, const Vec& x, const Vec& y) { return {y[0] + s * x[0], y[1] + s * x[1], y[2] + s * x[2]}; }

// The tagged-particle (Boltzmann–Lorentz) problem, simulated. Velocities are scaled with the bath's
// thermal speeds at a reference time, s is the matching clock (ds = dt·v_th(t)/v_th(0)); then the
// process is stationary: between collisions du/ds = (ζ/2)u (the bath cools at ζ while the tagged
// velocity stays), collisions with partner i at the rate n_i σ_ki² χ_ki ∫dw f_i(w) π|u − w| with
// the Maxwellian f_i of the reference time, u′ = u − μ_ik(1+ε)(g·σ̂)σ̂. The diffusion coefficient at
// the reference time is D = (1/3)∫₀^∞⟨u(0)·u(τ)⟩dτ (present velocity against past ones,
// docs/physics-beyond.md §2). By stationarity ⟨u(s)·∫_{s−U}^{s}u⟩ = ⟨u(s)·∫_s^{s+U}u⟩ = ∫₀^U⟨u(0)·u(τ)⟩dτ, so
// D is estimated as ⟨u(s)·[X(s+U) − X(s−U)]⟩/6 with X = ∫u ds, U = 10 first-Sonine correlation times
// (truncation e^{−10} ≈ 5e-5 of D for an exponential decay; 100 batch means give the error).
struct Partner {
  double weight, sd, beta;  // n_i σ_ki² χ_ki, √(T_i/m_i), μ_ik(1+ε_ki)
};
// u2: the stationary ⟨u²⟩ over the same grid points (3T_k/m_k of the tracer's own stationary state: with ζ the
// bath's cooling rate, the tracer limit's intruder temperature; tests/theory/test_tracer_temperature.cpp).
struct McDiffusion {
  double D = 0, err = 0;
  double u2 = 0, u2_err = 0;
  long collisions = 0;
};

McDiffusion tagged_particle_mc(const std::vector<Partner>& partners, double zeta, double sd_k, double corr_time,
                               double correlation_times, std::uint64_t seed);

}  // namespace granmix::test
