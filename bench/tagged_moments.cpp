#include "tagged_moments.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <exception>

#include "dsmc/event_loop.hpp"
#include "dsmc/pair_table.hpp"

namespace granmix::bench {

namespace {

// One replica's sums at every sample time, [(j * M + k) * moments + q].
template <class Selector>
std::vector<double> replica_sums(const model::Mixture& mix, const model::Restitution& law, const dsmc::PairTable& pairs,
                                 const std::vector<std::size_t>& counts, const std::vector<double>& T0,
                                 const std::vector<double>& times, std::uint64_t seed, std::size_t r, std::uint64_t& collisions) {
  dsmc::Rng rng(seed, r);
  dsmc::Particles p = dsmc::maxwellian_particles(mix, counts, T0, true, true, rng);
  Selector sel(pairs, p, 3);  // 3 speed classes, as run_ensemble: swaps keep (v, R) records together
  dsmc::Counters c;
  dsmc::EventLoop<Selector> loop(p, sel, law, rng, c, p.size());
  const std::size_t M = p.species();
  std::vector<double> out;
  out.reserve(times.size() * M * TaggedRun::moments);
  for (double t : times) {
    loop.run_until(t);
    for (std::size_t k = 0; k < M; ++k) {
      double v2 = 0.0, v4 = 0.0, rv = 0.0, r2 = 0.0;
      for (std::size_t a = p.begin(k); a < p.end(k); ++a) {
        const dsmc::Vec3& v = p.v[a];
        const dsmc::Vec3 R = dsmc::displacement(p, a, t);
        const double w = dsmc::norm2(v);
        v2 += w, v4 += w * w, rv += R.x * v.x + R.y * v.y + R.z * v.z, r2 += dsmc::norm2(R);
      }
      out.insert(out.end(), {v2, v4, rv, r2});
    }
  }
  collisions = c.accepted;
  return out;
}

}  // namespace

double TaggedRun::mean(std::size_t j, std::size_t k, Moment q, std::size_t excluded) const {
  double s = 0.0, n = 0.0;
  for (std::size_t r = 0; r < replicas; ++r)
    if (r != excluded) s += sum(r, j, k, q), n += double(counts[k]);
  return s / n;
}

std::vector<std::size_t> counts_at_least_one(const model::Mixture& mix, std::size_t total) {
  std::vector<std::size_t> c;
  for (std::size_t k = 0; k < mix.size(); ++k)
    c.push_back(std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(double(total) * mix.fraction(k)))));
  return c;
}

TaggedRun run_tagged(const model::Mixture& mix, const model::Restitution& law, const std::vector<std::size_t>& counts,
                     const std::vector<double>& T0, const std::vector<double>& times, std::uint64_t seed, std::size_t replicas) {
  TaggedRun out;
  out.species = mix.size(), out.replicas = replicas, out.counts = counts, out.times = times;
  std::size_t N = 0;
  for (std::size_t c : counts) N += c;
  const dsmc::PairTable pairs(mix, {}, double(N) / mix.total_density());
  std::vector<std::vector<double>> per(replicas);
  std::vector<std::uint64_t> coll(replicas, 0);
  std::exception_ptr failure;
  const auto t0 = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t r = 0; r < replicas; ++r) {
    try {
      // The selector run_ensemble's `auto` picks: the exact table up to 8 species, low rank above.
      per[r] = mix.size() <= 8 ? replica_sums<dsmc::DirectSelector>(mix, law, pairs, counts, T0, times, seed, r, coll[r])
                               : replica_sums<dsmc::LowRankSelector>(mix, law, pairs, counts, T0, times, seed, r, coll[r]);
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t r = 0; r < replicas; ++r) out.sums.insert(out.sums.end(), per[r].begin(), per[r].end()), out.collisions += coll[r];
  return out;
}

}  // namespace granmix::bench
