#pragma once
// The one event-driven DSMC loop, exact in time (no time step), parameterised at compile time by
// the pair selector so that its proposal inlines (docs/architecture.md §5). Steps (v1 Sec. II B, made exact
// for any selector): waiting time from the total majorant rate; a proposed pair; acceptance
// |g|/scale; direction e from the |g·e|-weighted hemisphere; ε at |g·e|; the collision.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "collision_rule.hpp"
#include "loop_state.hpp"
#include "model/errors.hpp"
#include "model/restitution.hpp"
#include "selectors.hpp"

namespace granmix::dsmc {

// Pair counts are kept up to this many species: the M×M table (and one copy per sample time) would
// cost more than the simulation beyond it (691 species: 3.8 MB touched at random per collision).
constexpr std::size_t pair_count_species_limit = 64;

struct Counters {
  std::uint64_t trials = 0, accepted = 0, refreshes = 0;
  std::vector<std::uint64_t> species_collisions;  // [k]: collisions species k took part in (i = k counts twice)
  std::vector<std::uint64_t> pair_collisions;     // [i*M + k], i <= k; empty above pair_count_species_limit
  void reset(std::size_t M) {
    species_collisions.assign(M, 0);
    pair_collisions.assign(M <= pair_count_species_limit ? M * M : 0, 0);
  }
  void count(std::size_t i, std::size_t k) {
    ++accepted, ++species_collisions[i], ++species_collisions[k];
    if (!pair_collisions.empty()) ++pair_collisions[i <= k ? i * species_collisions.size() + k : k * species_collisions.size() + i];
  }
};

template <class Selector>
class EventLoop {
 public:
  // Maximum speeds are raised at every collision and recomputed from the particles every
  // refresh_every accepted collisions, so that the acceptance does not decay as the gas cools.
  EventLoop(Particles& p, Selector& sel, const model::Restitution& law, Rng& rng, Counters& c, std::uint64_t refresh_every)
      : p_(p), sel_(sel), law_(law), rng_(rng), c_(c), refresh_every_(refresh_every), energy_(kinetic_energy(p)),
        e1_(species_energy(p, 0)), e1_start_(e1_), inverse_rate_(1.0 / sel.total_rate()) {
    c_.reset(p.species());
  }

  double time() const { return t_; }
  double energy() const { return energy_; }
  // Rescaled time t_s = ∫₀ᵗ √(T_1/T_1(0)) dt' (v1 Fig. 1), exact: T_1 is constant between the
  // collisions of species 1.
  double rescaled_time() const { return ts_ + std::sqrt(e1_ / e1_start_) * (t_ - t_e1_); }

  // Advance to t_stop. The Poisson process is memoryless: the waiting time that would cross
  // t_stop is discarded and a fresh one drawn on the next call.
  void run_until(double t_stop) { advance(t_stop, -1.0); }

  // Collide until the kinetic energy falls to energy_stop or below (v1 Fig. 3: age the gas until
  // ⟨T⟩ = 2E/(3N) = 1); it lands within one collision's loss, O(1/N) relative, of the target.
  void cool_to(double energy_stop) { advance(std::numeric_limits<double>::infinity(), energy_stop); }

  // Called at every refresh point (every refresh_every accepted collisions, never per trial), where
  // the selector has just been rebuilt from the particles and no proposal is drawn ahead: the one
  // place a snapshot restores exactly (dsmc/replica_snapshot.hpp).
  void at_refresh(std::function<void()> f) { at_refresh_ = std::move(f); }
  LoopState state() const {
    LoopState s;
    s.t = t_, s.ts = ts_, s.t_e1 = t_e1_, s.e1_start = e1_start_;
    return s;
  }
  // Continue from a snapshot taken at a refresh point. The selector was built from the snapshot's
  // particles (a refresh of a sorted array moves nothing, so it is the selector the run had) and the
  // energies recomputed from them, as the refresh did; the proposal the run drew right after the
  // snapshot is drawn now, so the stream is consumed in the same order.
  void resume(const LoopState& s, const Counters& c) {
    t_ = s.t, ts_ = s.ts, t_e1_ = s.t_e1, e1_start_ = s.e1_start;
    c_ = c;
    since_refresh_ = 0;
    selector_changed();
  }

  // Start the measurement here: t = 0, displacements and collision counts zero (v1 Fig. 3 dashed).
  void reset_clock() {
    t_ = 0.0;
    ts_ = 0.0, t_e1_ = 0.0, e1_start_ = e1_;
    if (p_.track_displacement) std::fill(p_.flight.begin(), p_.flight.end(), Vec3f{0, 0, 0});  // R = R0_e + v·0 = 0
    p_.epoch = 0.0;
    c_.reset(p_.species());
  }

 private:
  void advance(double t_stop, double energy_stop) {
    while (energy_ > energy_stop) {
      // The total rate changes only with the selector's state, so 1/rate is kept (no division per
      // trial) and the waiting time is a ziggurat exponential (no log per trial).
      const double t_next = t_ + rng_.standard_exponential() * inverse_rate_;
      if (!(t_next < t_stop)) {
        t_ = t_stop;
        return;
      }
      t_ = t_next;
      ++c_.trials;
      // Software pipelining: the next proposal is drawn now and its two velocity records
      // prefetched while this one is tested (their loads were the largest single cost in perf).
      // A proposal depends only on the selector's state, so it stays valid until that changes; when
      // an accepted collision raises a majorant it is discarded and drawn afresh (an unused draw).
      const Proposal q = has_next_ ? next_ : sel_.propose(rng_, p_);
      draw_next();
      if (q.a == q.b) continue;  // a particle with itself: zero true rate
      const Vec3 g = p_.v[q.a] - p_.v[q.b];
      const double g2 = norm2(g), x = rng_.uniform() * q.scale;
      // u·scale < weight·|g| compared squared (both sides >= 0): no square root on a rejection.
      if (!(x * x < q.weight * q.weight * g2)) continue;
      const double gn = std::sqrt(g2), inv = 1.0 / gn;
      const Vec3 e = rng_.hemisphere({g.x * inv, g.y * inv, g.z * inv});
      const double g_dot_e = g.x * e.x + g.y * e.y + g.z * e.z;
      const double eps = law_.eps_at(q.i, q.k, g_dot_e);
      const double ma = p_.mass[q.i], mb = p_.mass[q.k];
      const bool species1 = q.i == 0 || q.k == 0;
      if (species1) ts_ = rescaled_time(), t_e1_ = t_, e1_ -= species1_energy(q);
      collide(p_, q.a, q.b, ma, mb, eps, e, g_dot_e, t_);
      if (species1) e1_ += species1_energy(q);
      energy_ -= (1.0 - eps * eps) * (ma * mb / (ma + mb)) * g_dot_e * g_dot_e / 2.0;  // docs/physics.md §1
      c_.count(q.i, q.k);
      std::size_t b = q.b;  // kept on its particle while a moves between speed classes
      const bool moved_a = sel_.moved(q.a, q.i, b, p_);
      std::size_t unused = p_.size();
      const bool moved_b = sel_.moved(b, q.k, unused, p_);
      if (moved_a || moved_b) selector_changed();
      if (++since_refresh_ >= refresh_every_) {
        sel_.refresh(p_);
        const double e_particles = kinetic_energy(p_);
        check_energy_balance(e_particles);
        energy_ = energy_at_refresh_ = e_particles;  // drop the rounding accumulated over N collisions
        e1_ = species_energy(p_, 0);
        reanchor(p_, t_);  // keeps |R0_e| of the order of the displacement (particles.hpp)
        since_refresh_ = 0;
        ++c_.refreshes;
        if (at_refresh_) at_refresh_();  // before the next proposal is drawn (resume() draws it)
        selector_changed();
      }
    }
  }

  // Physics check at every refresh: the particles must carry the energy that the collisions' losses
  // (1−ε²) m_eff (g·e)²/2 (docs/physics.md §1) left them, up to rounding. A collision rule that breaks
  // momentum or the restitution law stops the run here instead of running on (a rule that gains
  // energy from ε ≤ 1 heats the gas without bound: the run to t_stop would never end). Rounding bound:
  // each bookkeeping step and each velocity update errs by at most a few ε_mach of the energy, and the
  // sum over the particles by N ε_mach of it, so 4 (N + collisions) ε_mach E is never reached by
  // rounding (typical drift: 1e-14), while a 2% error in the impulse moves E by ~1e-3 per refresh.
  void check_energy_balance(double e_particles) const {
    const double n = static_cast<double>(p_.size() + refresh_every_);
    const double bound = 4.0 * n * std::numeric_limits<double>::epsilon() * energy_at_refresh_;
    if (std::abs(e_particles - energy_) <= bound) return;
    throw NumericalError(fmt::format("DSMC event loop: energy balance broken at t = {:.9g}: the particles carry {:.12g}, the "
                                     "collisions' (1 - eps^2) losses leave {:.12g} (rounding allows {:.3g}): the collision rule "
                                     "does not match the restitution law (v1 Eq. 3)",
                                     t_, e_particles, energy_, bound));
  }

  // The selector's weights changed: the drawn-ahead proposal and the kept 1/rate are stale.
  void selector_changed() {
    inverse_rate_ = 1.0 / sel_.total_rate();
    draw_next();
  }

  void draw_next() {
    next_ = sel_.propose(rng_, p_);
    has_next_ = true;
    __builtin_prefetch(&p_.v[next_.a]);
    __builtin_prefetch(&p_.v[next_.b]);
    if (p_.track_displacement) {  // the flight intercepts are written if the pair collides
      __builtin_prefetch(&p_.flight[next_.a]);
      __builtin_prefetch(&p_.flight[next_.b]);
    }
  }

  // Kinetic energy that the particles of species 1 in proposal q carry.
  double species1_energy(const Proposal& q) const {
    auto e = [&](std::size_t a) { return 0.5 * p_.mass[0] * norm2(p_.v[a]); };
    return (q.i == 0 ? e(q.a) : 0.0) + (q.k == 0 ? e(q.b) : 0.0);
  }

  Particles& p_;
  Selector& sel_;
  const model::Restitution& law_;
  Rng& rng_;
  Counters& c_;
  std::uint64_t refresh_every_, since_refresh_ = 0;
  double t_ = 0.0;
  double energy_;
  double energy_at_refresh_ = energy_;  // the scale of the rounding the energy balance check allows
  double e1_, e1_start_;           // kinetic energy of species 1, now and at the clock's start
  double ts_ = 0.0, t_e1_ = 0.0;  // t_s accumulated up to t_e1_, the last change of e1_
  double inverse_rate_;            // 1 / sel_.total_rate(), renewed by selector_changed()
  Proposal next_{};               // the next trial's pair, drawn one trial ahead (has_next_)
  bool has_next_ = false;
  std::function<void()> at_refresh_;
};

}  // namespace granmix::dsmc
