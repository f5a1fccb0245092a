#include "ensemble.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "event_loop.hpp"
#include "time_step_scheme.hpp"
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

// Seconds since `since`, and restart it.
double lap(std::chrono::steady_clock::time_point& since) {
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - since).count();
  since = now;
  return s;
}

void sample(const Particles& p, double t, const DsmcSetup& s, const Counters& c, ReplicaRecord& out) {
  const std::size_t M = p.species();
  for (std::size_t k = 0; k < M; ++k) {
    double v2 = 0.0, v4 = 0.0, r2 = 0.0;
    for (std::size_t j = p.begin(k); j < p.end(k); ++j) {
      const double w = norm2(p.v[j]);
      v2 += w, v4 += w * w;
      if (s.msd) {
        const Vec3 r = displacement(p, j, t);
        r2 += r.x * r.x + r.y * r.y + r.z * r.z;
      }
    }
    const double n = double(p.count(k));
    out.T.push_back(p.mass[k] * v2 / (3.0 * n));
    if (s.msd) out.msd.push_back(r2 / n);
    // c = 2[(3/5)⟨v⁴⟩/⟨v²⟩² − 1] (physics.md §6: c = 2a₂).
    if (s.cumulant) out.cumulant.push_back(2.0 * (0.6 * (v4 / n) / ((v2 / n) * (v2 / n)) - 1.0));
  }
  for (std::uint64_t v : c.species_collisions) out.species_collisions.push_back(double(v));
  for (std::uint64_t v : c.pair_collisions) out.pair_collisions.push_back(double(v));
  if (s.distribution_bins > 0) {
    // MG: Φ_k(v*) = v0³ f_k(v) / n_k, estimated as count / (N_k × shell volume in v* space).
    const std::size_t B = s.distribution_bins;
    double T = 0.0;
    for (std::size_t k = 0; k < M; ++k) T += double(p.count(k)) * species_temperature(p, k) / double(p.size());
    const double m1 = p.mass[0], m2 = M > 1 ? p.mass[1] : p.mass[0];
    const double v0 = std::sqrt(2.0 * T * (m1 + m2) / (m1 * m2)), width = s.distribution_vmax / double(B);
    for (std::size_t k = 0; k < M; ++k) {
      std::vector<double> h(B, 0.0);
      for (std::size_t j = p.begin(k); j < p.end(k); ++j) {
        const double v = std::sqrt(norm2(p.v[j])) / v0;
        const auto b = static_cast<std::size_t>(v / width);
        if (b < B) h[b] += 1.0;
      }
      for (std::size_t b = 0; b < B; ++b) {
        const double lo = b * width, hi = lo + width;
        const double shell = 4.0 * std::numbers::pi / 3.0 * (hi * hi * hi - lo * lo * lo);
        out.distribution.push_back(h[b] / (double(p.count(k)) * shell));
      }
    }
  }
}

// The stops of one replica in time order: samples, TAMSD starts (record tracer positions) and
// TAMSD ends (accumulate squared increments).
struct Stop {
  double t;
  enum Kind { start, end, sample } kind;
  std::size_t index, lag;
};

// TAMSD start times: t = 0 and a geometric grid from 1e-6 𝒯 to 𝒯. A cooling gas changes on the
// scale τ0 ≪ 𝒯 at first, which a uniform grid cannot resolve (it overweights the hot start).
std::vector<double> tamsd_starts(const DsmcSetup& s, std::size_t n) {
  std::vector<double> t = {0.0};
  for (std::size_t g = 1; g < n; ++g) t.push_back(s.tamsd_measurement_time * std::pow(10.0, -6.0 + 6.0 * double(g - 1) / double(n - 2)));
  return t;
}

// Trapezoid weights of the starts valid for a lag (t + Δ <= 𝒯): the time average over [0, 𝒯 − Δ]
// of physics.md §4 as a quadrature on the start grid.
std::vector<double> tamsd_weights(const std::vector<double>& starts, double lag, double T) {
  std::vector<double> w(starts.size(), 0.0);
  std::size_t n = 0;
  while (n < starts.size() && starts[n] + lag <= T) ++n;
  for (std::size_t g = 0; g < n; ++g) {
    const double left = g > 0 ? starts[g] - starts[g - 1] : 0.0, right = g + 1 < n ? starts[g + 1] - starts[g] : 0.0;
    w[g] = 0.5 * (left + right);
  }
  if (n == 1) w[0] = 1.0;
  return w;
}

std::vector<Stop> schedule(const DsmcSetup& s, const std::vector<double>& starts, const std::vector<std::vector<double>>& weights) {
  std::vector<Stop> stops;
  for (std::size_t j = 0; j < s.times.size(); ++j) stops.push_back({s.times[j], Stop::sample, j, 0});
  for (std::size_t g = 0; g < starts.size(); ++g) {
    stops.push_back({starts[g], Stop::start, g, 0});
    for (std::size_t l = 0; l < s.tamsd_lags.size(); ++l)
      if (weights[l][g] > 0.0) stops.push_back({starts[g] + s.tamsd_lags[l], Stop::end, g, l});
  }
  std::stable_sort(stops.begin(), stops.end(), [](const Stop& a, const Stop& b) { return a.t < b.t; });
  return stops;
}

template <class Selector>
ReplicaRecord run_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r) {
  auto clock = std::chrono::steady_clock::now();
  ReplicaRecord out;
  Rng rng(s.seed, r);
  const bool tamsd = s.tamsd_measurement_time > 0.0;
  Particles p = maxwellian_particles(s.mixture, s.counts, s.T0, s.msd || tamsd, s.rescale, rng);
  Selector sel(pairs, p, tamsd ? 1 : s.speed_classes);
  Counters c;
  EventLoop<Selector> loop(p, sel, s.law, rng, c, p.size());
  if (s.aged) {
    loop.cool_to(1.5 * double(p.size()));  // ⟨T⟩ = 2E/(3N) = 1
    loop.reset_clock();
  }
  const std::size_t M = p.species(), L = s.tamsd_lags.size();
  const std::vector<double> starts = tamsd ? tamsd_starts(s, 512) : std::vector<double>{};
  std::vector<std::vector<double>> weights;
  for (double lag : s.tamsd_lags) weights.push_back(tamsd_weights(starts, lag, s.tamsd_measurement_time));
  // Tracers: the first K particles of each species (initial velocities are i.i.d., so any K will do).
  std::vector<std::size_t> tracers(M);
  for (std::size_t k = 0; k < M; ++k) tracers[k] = std::min(s.tamsd_tracers, p.count(k));
  std::vector<std::vector<Vec3>> at_start(starts.size());
  std::vector<double> sum(L * M, 0.0), count(L * M, 0.0);
  out.seconds_setup += lap(clock);
  for (const Stop& stop : schedule(s, starts, weights)) {
    loop.run_until(stop.t);
    out.seconds_loop += lap(clock);
    if (stop.kind == Stop::sample) {
      sample(p, stop.t, s, c, out);
      out.rescaled_time.push_back(loop.rescaled_time());
    } else if (stop.kind == Stop::start) {
      for (std::size_t k = 0; k < M; ++k)
        for (std::size_t j = 0; j < tracers[k]; ++j) at_start[stop.index].push_back(displacement(p, p.begin(k) + j, stop.t));
    } else {
      std::size_t n = 0;
      for (std::size_t k = 0; k < M; ++k)
        for (std::size_t j = 0; j < tracers[k]; ++j, ++n) {
          const Vec3 a = at_start[stop.index][n], b = displacement(p, p.begin(k) + j, stop.t);
          const double w = weights[stop.lag][stop.index];
          sum[stop.lag * M + k] += w * ((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y) + (b.z - a.z) * (b.z - a.z));
          count[stop.lag * M + k] += w;
        }
    }
    out.seconds_sample += lap(clock);
  }
  for (std::size_t i = 0; i < sum.size(); ++i) out.tamsd.push_back(sum[i] / count[i]);
  out.trials = c.trials, out.accepted = c.accepted;
  return out;
}

ReplicaRecord run_time_step_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r) {
  if (s.aged || s.tamsd_measurement_time > 0.0)
    throw std::invalid_argument("DSMC: the timestep method has no aged start and no TAMSD");
  auto clock = std::chrono::steady_clock::now();
  Rng rng(s.seed, r);
  Particles p = maxwellian_particles(s.mixture, s.counts, s.T0, s.msd, s.rescale, rng);
  Counters c;
  TimeStepScheme scheme(p, pairs, s.law, rng, c, s.time_step_factor);
  ReplicaRecord out;
  out.seconds_setup += lap(clock);
  for (double t : s.times) {
    scheme.run_until(t);
    out.seconds_loop += lap(clock);
    sample(p, t, s, c, out);
    out.seconds_sample += lap(clock);
    out.rescaled_time.push_back(std::numeric_limits<double>::quiet_NaN());  // not tracked by the scheme
  }
  out.trials = c.trials, out.accepted = c.accepted, out.steps = scheme.steps();
  return out;
}

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
  const Method method = s.method == Method::automatic ? (M <= 8 ? Method::direct : Method::lowrank) : s.method;
  return {N, V, PairTable(s.mixture, s.chi, V), method};  // empty chi: dilute
}

ReplicaRecord compute_replica(const DsmcSetup& s, const Geometry& g, std::size_t r) {
  switch (g.method) {
    case Method::direct: return run_replica<DirectSelector>(s, g.pairs, r);
    case Method::lowrank: return run_replica<LowRankSelector>(s, g.pairs, r);
    case Method::timestep: return run_time_step_replica(s, g.pairs, r);
    case Method::bird_global: return run_replica<GlobalBirdSelector>(s, g.pairs, r);
    default: return run_replica<BirdSelector>(s, g.pairs, r);
  }
}

}  // namespace

ReplicaRecord run_one_replica(const DsmcSetup& s, std::size_t r) { return compute_replica(s, geometry(s), r); }

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
  std::size_t done = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t r = 0; r < s.replicas; ++r) {
    try {
      const ReplicaRecord* found = s.source && !s.unit_key.empty() ? s.source->find(s.unit_key, r) : nullptr;
      recs[r] = found ? *found : compute_replica(s, g, r);
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
