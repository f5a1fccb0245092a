#include "ensemble.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "event_loop.hpp"
#include "time_step_scheme.hpp"
#include "model/enskog.hpp"

namespace granmix::dsmc {

Method parse_method(const std::string& name) {
  if (name == "auto") return Method::automatic;
  if (name == "direct") return Method::direct;
  if (name == "lowrank") return Method::lowrank;
  if (name == "bird") return Method::bird;
  if (name == "timestep") return Method::timestep;
  throw std::invalid_argument("unknown DSMC method '" + name + "'");
}

const char* to_string(Method m) {
  switch (m) {
    case Method::automatic: return "auto";
    case Method::direct: return "direct";
    case Method::lowrank: return "lowrank";
    case Method::bird: return "bird";
    case Method::timestep: return "timestep";
  }
  return "?";
}

std::vector<std::size_t> counts_for(const model::Mixture& mix, std::size_t total) {
  std::vector<std::size_t> c;
  for (std::size_t k = 0; k < mix.size(); ++k)
    c.push_back(static_cast<std::size_t>(std::llround(double(total) * mix.fraction(k))));
  return c;
}

namespace {

// Everything one replica records, [time * M + k].
struct ReplicaRecord {
  std::vector<double> T, msd, cumulant, pair_collisions, rescaled_time;
  std::uint64_t trials = 0, accepted = 0, steps = 0;
};

void sample(const Particles& p, double t, const DsmcSetup& s, const Counters& c, ReplicaRecord& out) {
  const std::size_t M = p.species();
  for (std::size_t k = 0; k < M; ++k) {
    double v2 = 0.0, v4 = 0.0, r2 = 0.0;
    for (std::size_t j = p.begin(k); j < p.end(k); ++j) {
      const double w = p.vx[j] * p.vx[j] + p.vy[j] * p.vy[j] + p.vz[j] * p.vz[j];
      v2 += w, v4 += w * w;
      if (s.msd) {  // v1 Eq. (15): add the free flight since the last collision, state untouched
        const double dt = t - p.t_last[j];
        const double x = p.rx[j] + p.vx[j] * dt, y = p.ry[j] + p.vy[j] * dt, z = p.rz[j] + p.vz[j] * dt;
        r2 += x * x + y * y + z * z;
      }
    }
    const double n = double(p.count(k));
    out.T.push_back(p.mass[k] * v2 / (3.0 * n));
    if (s.msd) out.msd.push_back(r2 / n);
    // c = 2[(3/5)⟨v⁴⟩/⟨v²⟩² − 1] (physics.md §6: c = 2a₂).
    if (s.cumulant) out.cumulant.push_back(2.0 * (0.6 * (v4 / n) / ((v2 / n) * (v2 / n)) - 1.0));
  }
  for (std::uint64_t v : c.pair_collisions) out.pair_collisions.push_back(double(v));
}

template <class Selector>
ReplicaRecord run_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r) {
  Rng rng(s.seed, r);
  Particles p = maxwellian_particles(s.mixture, s.counts, s.T0, s.msd, s.rescale, rng);
  Selector sel(pairs, p);
  Counters c;
  EventLoop<Selector> loop(p, sel, s.law, rng, c, p.size());
  if (s.aged) {
    loop.cool_to(1.5 * double(p.size()));  // ⟨T⟩ = 2E/(3N) = 1
    loop.reset_clock();
  }
  ReplicaRecord out;
  for (double t : s.times) {
    loop.run_until(t);
    sample(p, t, s, c, out);
    out.rescaled_time.push_back(loop.rescaled_time());
  }
  out.trials = c.trials, out.accepted = c.accepted;
  return out;
}

ReplicaRecord run_time_step_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r) {
  if (s.aged) throw std::invalid_argument("DSMC: the timestep method has no aged start");
  Rng rng(s.seed, r);
  Particles p = maxwellian_particles(s.mixture, s.counts, s.T0, s.msd, s.rescale, rng);
  Counters c;
  TimeStepScheme scheme(p, pairs, s.law, rng, c, s.time_step_factor);
  ReplicaRecord out;
  for (double t : s.times) {
    scheme.run_until(t);
    sample(p, t, s, c, out);
    out.rescaled_time.push_back(std::numeric_limits<double>::quiet_NaN());  // not tracked by the scheme
  }
  out.trials = c.trials, out.accepted = c.accepted, out.steps = scheme.steps();
  return out;
}

Estimate reduce(const std::vector<ReplicaRecord>& recs, std::vector<double> ReplicaRecord::*field) {
  Estimate e;
  const std::size_t n = (recs.front().*field).size(), R = recs.size();
  e.mean.assign(n, 0.0), e.err.assign(n, 0.0);
  for (const auto& r : recs)
    for (std::size_t j = 0; j < n; ++j) e.mean[j] += (r.*field)[j] / double(R);
  if (R > 1) {
    for (const auto& r : recs)
      for (std::size_t j = 0; j < n; ++j) e.err[j] += std::pow((r.*field)[j] - e.mean[j], 2);
    for (double& v : e.err) v = std::sqrt(v / double(R - 1) / double(R));
  }
  return e;
}

}  // namespace

DsmcResult run_ensemble(const DsmcSetup& s) {
  const std::size_t M = s.mixture.size();
  if (s.counts.size() != M || s.T0.size() != M) throw std::invalid_argument("DSMC: one count and one T per species");
  if (s.replicas == 0) throw std::invalid_argument("DSMC: at least one replica");
  std::size_t N = 0;
  for (std::size_t c : s.counts) N += c;
  // V from the total: n = N / V. Species densities are then N_k / V (counts_for keeps them
  // proportional to the mixture's n_k up to rounding).
  const double V = double(N) / s.mixture.total_density();
  const PairTable pairs(s.mixture, s.chi.empty() ? model::dilute_contact_values(M) : s.chi, V);
  const Method method = s.method == Method::automatic ? (M <= 8 ? Method::direct : Method::lowrank) : s.method;

  std::vector<ReplicaRecord> recs(s.replicas);
  const auto t0 = std::chrono::steady_clock::now();
  const int threads = s.threads > 0 ? s.threads : omp_get_max_threads();
  std::exception_ptr failure;
  std::size_t done = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t r = 0; r < s.replicas; ++r) {
    try {
      switch (method) {
        case Method::direct: recs[r] = run_replica<DirectSelector>(s, pairs, r); break;
        case Method::lowrank: recs[r] = run_replica<LowRankSelector>(s, pairs, r); break;
        case Method::timestep: recs[r] = run_time_step_replica(s, pairs, r); break;
        default: recs[r] = run_replica<BirdSelector>(s, pairs, r); break;
      }
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
#pragma omp critical
    if (s.progress) s.progress(++done, s.replicas);
  }
  if (failure) std::rethrow_exception(failure);

  DsmcResult out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.method = method, out.species = M, out.times = s.times.size(), out.replicas = s.replicas, out.particles = N;
  out.volume = V;
  out.T = reduce(recs, &ReplicaRecord::T);
  if (s.msd) out.msd = reduce(recs, &ReplicaRecord::msd);
  if (s.cumulant) out.cumulant = reduce(recs, &ReplicaRecord::cumulant);
  out.pair_collisions = reduce(recs, &ReplicaRecord::pair_collisions);
  out.rescaled_time = reduce(recs, &ReplicaRecord::rescaled_time);
  for (const auto& r : recs) out.trials += r.trials, out.accepted += r.accepted, out.steps += r.steps;
  return out;
}

}  // namespace granmix::dsmc
