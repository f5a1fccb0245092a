#pragma once
// Montanero & Garzó's fixed-time-step DSMC (MG Sec. 3), for comparison with the exact event-driven
// loop. Each step Δt = factor λ11/v01(t), λ11 = (√2 π n1 χ11 σ11²)⁻¹, v01 = √(2 T1/m1), MG default
// factor 3e-3. For every ordered species pair (i, j), ½ N_i ω_max^(ij) Δt candidate pairs (the
// fractional part carried to the next step) are drawn uniformly; with σ̂ uniform on the sphere a
// pair collides with probability Θ(g·σ̂) ω/ω_max, ω = 4π σ_ij² n_j χ_ij |g·σ̂|. Summed over both
// orderings that is N_i ν_ij Δt collisions per step; velocities are frozen within a step, which is
// the scheme's O(Δt) error (docs/physics.md §7: it biases the cumulants).
#include <cstdint>
#include <functional>
#include <vector>

#include "event_loop.hpp"
#include "model/restitution.hpp"
#include "pair_table.hpp"

namespace granmix::dsmc {

class TimeStepScheme {
 public:
  TimeStepScheme(Particles& p, const PairTable& pairs, const model::Restitution& law, Rng& rng, Counters& c, double factor);
  void run_until(double t_stop);
  double time() const { return t_; }
  std::uint64_t steps() const { return steps_; }
  // Called after every step: a step boundary is where a snapshot restores exactly (the next step's
  // Δt and majorants are functions of the particles).
  void after_step(std::function<void()> f) { after_step_ = std::move(f); }
  LoopState state() const;
  void resume(const LoopState& s, const Counters& c);

 private:
  void step(double dt);
  Particles& p_;
  const PairTable& pairs_;
  const model::Restitution& law_;
  Rng& rng_;
  Counters& c_;
  double factor_, t_ = 0.0;
  std::uint64_t steps_ = 0;
  std::vector<double> carry_;  // fractional candidate counts per ordered pair
  std::function<void()> after_step_;
};

}  // namespace granmix::dsmc
