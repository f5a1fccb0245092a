#pragma once
// What the kinetic theory assumes, measured in the exact event-driven DSMC: per
// species and sample time the sums Σv², Σv⁴, ΣR·v and ΣR² over the particles of each replica. The
// study drives the event loop itself (dsmc/event_loop.hpp) instead of extending run_ensemble: the
// tagged correlation Q_k = ⟨R·v⟩ (docs/physics-beyond.md §2) is needed only here. Sums, not means, are
// kept so that replicas can be pooled (species of one particle) and left out one at a time (jackknife).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "model/mixture.hpp"
#include "model/restitution.hpp"

namespace granmix::bench {

struct TaggedRun {
  enum Moment { v2 = 0, v4 = 1, rv = 2, r2 = 3, moments = 4 };
  std::size_t species = 0, replicas = 0;
  std::vector<std::size_t> counts;
  std::vector<double> times;
  std::vector<double> sums;  // [((r * times + j) * species + k) * moments + q]
  std::uint64_t collisions = 0;
  double seconds = 0.0;
  double sum(std::size_t r, std::size_t j, std::size_t k, Moment q) const {
    return sums[((r * times.size() + j) * species + k) * moments + q];
  }
  // Per-particle mean of a moment over the replicas in use (excluded: one left out, or none).
  double mean(std::size_t j, std::size_t k, Moment q, std::size_t excluded = npos) const;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
};

// Particles per species for a total N at the mixture's fractions, rounded, at least one each.
std::vector<std::size_t> counts_at_least_one(const model::Mixture& mix, std::size_t total);

// Replicas in parallel (one Rng stream per replica: results do not depend on the thread count),
// Maxwellian start at T0 with zero total momentum (dsmc::maxwellian_particles), V = N / n.
TaggedRun run_tagged(const model::Mixture& mix, const model::Restitution& law, const std::vector<std::size_t>& counts,
                     const std::vector<double>& T0, const std::vector<double>& times, std::uint64_t seed, std::size_t replicas);

}  // namespace granmix::bench
