// Randomized DSMC properties, fixed seeds: the event loop conserves momentum to 1e-12
// (relative to Σ m|v|) at any ε and kinetic energy to 1e-12 at ε = 1; an ensemble gives the same
// numbers, bit for bit, on 1 and 2 threads.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "dsmc/ensemble.hpp"
#include "dsmc/event_loop.hpp"
#include "dsmc/pair_table.hpp"
#include "dsmc/particles.hpp"
#include "random_mixtures.hpp"

using namespace granmix;
using namespace granmix::dsmc;

namespace {

struct Sums {
  double px = 0, py = 0, pz = 0, scale = 0, energy = 0;
};

Sums sums(const Particles& p) {
  Sums s;
  for (std::size_t k = 0; k < p.species(); ++k)
    for (std::size_t a = p.begin(k); a < p.end(k); ++a) {
      const double m = p.mass[k];
      s.px += m * p.v[a].x, s.py += m * p.v[a].y, s.pz += m * p.v[a].z;
      s.scale += m * std::sqrt(p.v[a].x * p.v[a].x + p.v[a].y * p.v[a].y + p.v[a].z * p.v[a].z);
    }
  s.energy = kinetic_energy(p);
  return s;
}

}  // namespace

TEST_CASE("property: DSMC conserves momentum at any eps and energy at eps = 1 (random small mixtures)", "[property]") {
  test::MixtureSampler sample(15004);
  double worst_p = 0.0, worst_e = 0.0;
  std::uint64_t collisions = 0;
  for (int c = 0; c < 40; ++c) {
    test::RandomMixture m = sample.next(8);
    const bool elastic = c % 2 == 0;  // every other case elastic: the energy check
    if (elastic) m.law = model::Restitution::constant(m.mixture.size(), 1.0), m.eps = 1.0, m.viscoelastic = false;
    INFO("case " << c << ": " << m.describe());
    const std::size_t M = m.mixture.size();
    std::vector<std::size_t> counts = counts_for(m.mixture, 300);
    for (auto& n : counts) n = std::max<std::size_t>(n, 2);
    std::size_t N = 0;
    for (auto n : counts) N += n;
    Rng rng(15004, std::uint64_t(c));
    Particles p = maxwellian_particles(m.mixture, counts, std::vector<double>(M, 1.0), false, true, rng);
    const PairTable pairs(m.mixture, {}, double(N) / m.mixture.total_density());
    DirectSelector sel(pairs, p, 3);
    Counters counters;
    EventLoop<DirectSelector> loop(p, sel, m.law, rng, counters, p.size());
    const Sums before = sums(p);
    // 20 collisions per particle: the stop time doubles from the fastest pair's mean free time
    // (an inelastic gas cools and collides ever more slowly; 200 doublings bound the loop)
    double rate = 0.0;
    for (std::size_t k = 0; k < M; ++k)
      for (std::size_t i = 0; i < M; ++i) {
        const double s = m.mixture.sigma(k, i);
        rate = std::max(rate, m.mixture[i].density * s * s * std::sqrt(1.0 / m.mixture[k].mass + 1.0 / m.mixture[i].mass));
      }
    double t_stop = 1.0 / rate;
    for (int d = 0; d < 200 && counters.accepted < 20 * N; ++d, t_stop *= 2) loop.run_until(t_stop);
    CHECK(counters.accepted >= 20 * N);
    const Sums after = sums(p);
    collisions += counters.accepted;
    const double dp = std::sqrt(std::pow(after.px - before.px, 2) + std::pow(after.py - before.py, 2) + std::pow(after.pz - before.pz, 2));
    worst_p = std::max(worst_p, dp / before.scale);
    CHECK(dp <= 1e-12 * before.scale);
    if (elastic) {
      worst_e = std::max(worst_e, std::abs(after.energy / before.energy - 1));
      CHECK(after.energy == Approx(before.energy).epsilon(1e-12));
    } else {
      CHECK(after.energy <= before.energy * (1 + 1e-12));  // inelastic: never gains energy
    }
  }
  std::printf("DSMC conservation: %llu collisions, worst |dP|/sum m|v| = %.2e, worst elastic |dE/E| = %.2e\n",
              static_cast<unsigned long long>(collisions), worst_p, worst_e);
}

TEST_CASE("property: same seed - same numbers on 1 and 2 threads (random small mixtures)", "[property]") {
  test::MixtureSampler sample(15005);
  for (int c = 0; c < 6; ++c) {
    const test::RandomMixture m = sample.next(12);
    INFO("case " << c << ": " << m.describe());
    DsmcSetup s;
    s.mixture = m.mixture;
    s.law = m.law;
    s.counts = counts_for(m.mixture, 400);
    for (auto& n : s.counts) n = std::max<std::size_t>(n, 2);
    s.T0.assign(m.mixture.size(), 1.0);
    // times in units of the light species' free flight: early and a few collision times
    const double lambda = 1.0 / (m.mixture.total_density() * m.mixture[0].diameter * m.mixture[0].diameter);
    s.times = {0.1 * lambda * std::sqrt(m.mixture[0].mass), lambda * std::sqrt(m.mixture[0].mass)};
    s.msd = true, s.cumulant = true;
    s.replicas = 3, s.seed = 15005 + std::uint64_t(c);
    s.threads = 1;
    const DsmcResult a = run_ensemble(s);
    s.threads = 2;
    const DsmcResult b = run_ensemble(s);
    CHECK(a.T.mean == b.T.mean);
    CHECK(a.T.err == b.T.err);
    CHECK(a.msd.mean == b.msd.mean);
    CHECK(a.cumulant.mean == b.cumulant.mean);
    CHECK(a.accepted == b.accepted);
  }
}
