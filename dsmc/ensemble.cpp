#include "ensemble.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "replica_run.hpp"
#include "model/enskog.hpp"
#include "model/enum_names.hpp"

namespace granmix::dsmc {

namespace {
constexpr model::EnumNames<Method, 6> method_names = {{{Method::automatic, "auto"},
                                                        {Method::direct, "direct"},
                                                        {Method::lowrank, "lowrank"},
                                                        {Method::bird, "bird"},
                                                        {Method::timestep, "timestep"},
                                                        {Method::bird_global, "bird-global"}}};
}  // namespace

Method parse_method(const std::string& name) { return model::parse_enum(method_names, name, "DSMC method"); }

const char* to_string(Method m) { return model::enum_name(method_names, m); }

std::vector<std::size_t> counts_for(const model::Mixture& mix, std::size_t total) {
  std::vector<std::size_t> c;
  for (std::size_t k = 0; k < mix.size(); ++k)
    c.push_back(static_cast<std::size_t>(std::llround(double(total) * mix.fraction(k))));
  return c;
}

namespace {
// One replica's histograms averaged over its sample times (settled runs, DsmcSetup).
std::vector<double> time_average(const std::vector<double>& per_time, std::size_t times) {
  const std::size_t block = per_time.size() / times;
  std::vector<double> out(block, 0.0);
  for (std::size_t j = 0; j < times; ++j)
    for (std::size_t i = 0; i < block; ++i) out[i] += per_time[j * block + i] / double(times);
  return out;
}

Estimate reduce(const std::vector<ReplicaRecord>& recs, std::vector<double> ReplicaRecord::*field) {
  Estimate e;
  const std::size_t n = (recs.front().*field).size(), R = recs.size();
  e.mean.assign(n, 0.0), e.err.assign(n, 0.0);
  e.replicas.reserve(n * R);
  for (const auto& r : recs) {
    e.replicas.insert(e.replicas.end(), (r.*field).begin(), (r.*field).end());
    for (std::size_t j = 0; j < n; ++j) e.mean[j] += (r.*field)[j] / double(R);
  }
  if (R > 1) {
    for (const auto& r : recs)
      for (std::size_t j = 0; j < n; ++j) e.err[j] += std::pow((r.*field)[j] - e.mean[j], 2);
    for (double& v : e.err) v = std::sqrt(v / double(R - 1) / double(R));
  }
  return e;
}

// What every replica of a set-up shares: the volume, the pair table and the method.
struct Geometry {
  std::size_t N = 0;
  double V = 0.0;
  PairTable pairs;
  Method method;
};

Geometry geometry(const DsmcSetup& s) {
  const std::size_t M = s.mixture.size();
  if (s.counts.size() != M || s.T0.size() != M) throw std::invalid_argument("DSMC: one count and one T per species");
  if (s.replicas == 0) throw std::invalid_argument("DSMC: at least one replica");
  std::size_t N = 0;
  for (std::size_t c : s.counts) N += c;
  // V from the total: n = N / V. Species densities are then N_k / V (counts_for keeps them
  // proportional to the mixture's n_k up to rounding).
  const double V = double(N) / s.mixture.total_density();
  return {N, V, PairTable(s.mixture, s.chi, V), resolved_method(s)};  // empty chi: dilute
}

}  // namespace

ReplicaRecord run_one_replica(const DsmcSetup& s, std::size_t r) { return run_replica(s, geometry(s).pairs, r); }

DsmcResult run_ensemble(const DsmcSetup& s) {
  const std::size_t M = s.mixture.size();
  const Geometry g = geometry(s);
  const std::size_t N = g.N;
  const double V = g.V;
  const Method method = g.method;
  std::vector<ReplicaRecord> recs(s.replicas);
  const auto t0 = std::chrono::steady_clock::now();
  const int threads = s.threads > 0 ? s.threads : omp_get_max_threads();
  std::exception_ptr failure;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t r = 0; r < s.replicas; ++r) {
    try {
      const ReplicaRecord* found = s.source && !s.unit_key.empty() ? s.source->find(s.unit_key, r) : nullptr;
      recs[r] = found ? *found : run_replica(s, g.pairs, r);
    } catch (...) {
#pragma omp critical
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);

  DsmcResult out;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Replicas computed elsewhere (the scheduler's units): the ensemble's cost is their CPU time.
  if (s.source) out.seconds = 0.0;
  out.method = method, out.species = M, out.times = s.times.size(), out.replicas = s.replicas, out.particles = N;
  out.volume = V;
  out.T = reduce(recs, &ReplicaRecord::T);
  if (s.msd) out.msd = reduce(recs, &ReplicaRecord::msd);
  if (s.cumulant) out.cumulant = reduce(recs, &ReplicaRecord::cumulant);
  out.species_collisions = reduce(recs, &ReplicaRecord::species_collisions);
  out.pair_collisions = reduce(recs, &ReplicaRecord::pair_collisions);
  out.rescaled_time = reduce(recs, &ReplicaRecord::rescaled_time);
  if (s.tamsd_measurement_time > 0.0) out.tamsd = reduce(recs, &ReplicaRecord::tamsd);
  if (s.distribution_bins > 0 && s.distribution_time_average)
    for (auto& r : recs) r.distribution = time_average(r.distribution, s.times.size());
  if (s.distribution_bins > 0) out.distribution = reduce(recs, &ReplicaRecord::distribution);
  for (const auto& r : recs) {
    out.trials += r.trials, out.accepted += r.accepted, out.steps += r.steps;
    out.seconds_setup += r.seconds_setup, out.seconds_loop += r.seconds_loop, out.seconds_sample += r.seconds_sample;
    if (s.source) out.seconds += r.seconds_setup + r.seconds_loop + r.seconds_sample;
  }
  return out;
}

}  // namespace granmix::dsmc
