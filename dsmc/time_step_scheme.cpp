#include "time_step_scheme.hpp"

#include <cmath>
#include <numbers>

namespace granmix::dsmc {

TimeStepScheme::TimeStepScheme(Particles& p, const PairTable& pairs, const model::Restitution& law, Rng& rng, Counters& c,
                               double factor)
    : p_(p), pairs_(pairs), law_(law), rng_(rng), c_(c), factor_(factor), carry_(pairs.M * pairs.M, 0.0) {
  c_.reset(pairs.M);
}

void TimeStepScheme::run_until(double t_stop) {
  const double n1 = double(p_.count(0)) / pairs_.volume;
  // MG: λ11 = (√2 π n1 χ11 σ11²)⁻¹ with σ11 = diameter of species 1.
  const double lambda11 = 1.0 / (std::sqrt(2.0) * std::numbers::pi * n1 * pairs_.chi(0, 0) * pairs_.sigma2(0, 0));
  while (t_ < t_stop) {
    const double v01 = std::sqrt(2.0 * species_temperature(p_, 0) / p_.mass[0]);
    const double dt = std::min(factor_ * lambda11 / v01, t_stop - t_);
    const std::uint64_t anchors = c_.accepted / p_.size();
    step(dt);
    t_ = (t_stop - t_ <= dt) ? t_stop : t_ + dt;
    ++steps_;
    // Re-anchor the flight intercepts every N collisions, as the event loop does (particles.hpp);
    // a function of the counters, so a snapshot at a step boundary restores it.
    if (c_.accepted / p_.size() != anchors) reanchor(p_, t_);
    if (after_step_) after_step_();
  }
}

LoopState TimeStepScheme::state() const {
  LoopState s;
  s.t = t_, s.steps = steps_, s.carry = carry_;
  return s;
}

void TimeStepScheme::resume(const LoopState& s, const Counters& c) {
  t_ = s.t, steps_ = s.steps, carry_ = s.carry;
  c_ = c;
}

void TimeStepScheme::step(double dt) {
  const std::size_t M = pairs_.M;
  const double t_mid = t_ + 0.5 * dt;  // collisions of a step are placed at its midpoint (O(Δt))
  std::vector<double> vmax(M);
  for (std::size_t k = 0; k < M; ++k) vmax[k] = speed_max(p_, k);
  for (std::size_t i = 0; i < M; ++i)
    for (std::size_t j = 0; j < M; ++j) {
      const std::size_t ij = i * M + j;
      const double nj = double(p_.count(j)) / pairs_.volume;
      // ω_max = 4π σ_ij² n_j χ_ij (vmax_i + vmax_j): |g·σ̂| <= |g| <= vmax_i + vmax_j.
      const double omega_max = 4.0 * std::numbers::pi * pairs_.sigma2(i, j) * nj * pairs_.chi(i, j) * (vmax[i] + vmax[j]);
      carry_[ij] += 0.5 * double(p_.count(i)) * omega_max * dt;
      const auto candidates = static_cast<std::uint64_t>(carry_[ij]);
      carry_[ij] -= double(candidates);
      for (std::uint64_t n = 0; n < candidates; ++n) {
        ++c_.trials;
        const std::size_t a = p_.begin(i) + rng_.below(p_.count(i)), b = p_.begin(j) + rng_.below(p_.count(j));
        if (a == b) continue;
        const Vec3 u = rng_.unit_vector();  // σ̂ uniform (MG step 1)
        const Vec3 g = p_.v[a] - p_.v[b];
        const double ge = g.x * u.x + g.y * u.y + g.z * u.z;
        if (!(ge > 0.0) || !(rng_.uniform() * (vmax[i] + vmax[j]) < ge)) continue;  // Θ(g·σ̂) ω/ω_max
        const double eps = law_.eps_at(i, j, ge);
        collide(p_, a, b, p_.mass[i], p_.mass[j], eps, u, ge, t_mid);
        c_.count(i, j);
      }
    }
}

}  // namespace granmix::dsmc
