#include "replica_run.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "checkpoint_files.hpp"
#include "progress_counter.hpp"
#include "event_loop.hpp"
#include "model/errors.hpp"
#include "time_step_scheme.hpp"

namespace granmix::dsmc {

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
    // c = 2[(3/5)⟨v⁴⟩/⟨v²⟩² − 1] (docs/physics.md §6: c = 2a₂).
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

// TAMSD start times: t = 0 and a geometric grid of n − 1 from 1e-6 𝒯 to 𝒯 (a cooling gas changes on the scale τ0 ≪ 𝒯
// at first, which a uniform grid cannot resolve: it overweights the hot start), then one start per lag at 𝒯 − Δ, the
// end of that lag's average.
std::vector<double> tamsd_starts(const DsmcSetup& s, std::size_t n) {
  std::vector<double> t = {0.0};
  for (std::size_t g = 1; g < n; ++g) t.push_back(s.tamsd_measurement_time * std::pow(10.0, -6.0 + 6.0 * double(g - 1) / double(n - 2)));
  for (double lag : s.tamsd_lags) t.push_back(s.tamsd_measurement_time - lag);
  return t;
}

// Trapezoid weights for lag l: the time average over [0, 𝒯 − Δ] of docs/physics.md §4 as a quadrature on the grid's starts
// below 𝒯 − Δ and the lag's own start there (the grid's n first starts, then one per lag). Without that last start the
// average stopped at the grid's last start below 𝒯 − Δ while the theory's runs to 𝒯 − Δ: on v2 Fig. 5 the DSMC's TAMSD
// came out 2.7% high at short lags (a span 9733 for 9999.99, the increments there negligible).
std::vector<double> tamsd_weights(const std::vector<double>& starts, std::size_t n, std::size_t l, double lag, double T) {
  std::vector<std::size_t> nodes;
  for (std::size_t g = 0; g < n; ++g)
    if (starts[g] < T - lag) nodes.push_back(g);
  nodes.push_back(n + l);
  std::vector<double> w(starts.size(), 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double left = i > 0 ? starts[nodes[i]] - starts[nodes[i - 1]] : 0.0;
    const double right = i + 1 < nodes.size() ? starts[nodes[i + 1]] - starts[nodes[i]] : 0.0;
    w[nodes[i]] = 0.5 * (left + right);
  }
  if (nodes.size() == 1) w[nodes[0]] = 1.0;
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

// A replica's checkpointing (none for an anonymous set-up or without a folder): whether a snapshot is
// due at a refresh point, and writing it. Wall time decides only when a snapshot is taken; the
// snapshot is taken where the loop restores exactly, so the trajectory is the same either way.
class ReplicaCheckpoint {
 public:
  ReplicaCheckpoint(const DsmcSetup& s, std::size_t r)
      : s_(s), r_(r), on_(s.checkpoint != nullptr && !s.unit_key.empty()), last_(std::chrono::steady_clock::now()) {}
  bool on() const { return on_; }
  // Whether the loop needs the refresh hook: for snapshots, or to be abandoned (stop_request.hpp).
  bool hooked() const { return on_ || s_.stop != nullptr; }
  // The snapshot to resume from, if the folder has one (verified against the set-up).
  std::optional<ReplicaSnapshot> resume_point() const {
    if (!on_) return std::nullopt;
    const auto path = snapshot_path(s_, r_);
    const auto bytes = read_checkpoint_file(path);
    if (!bytes) return std::nullopt;
    ReplicaSnapshot snap = decode_snapshot(*bytes, path.string(), snapshot_identity(*s_.checkpoint, s_, r_));
    check_snapshot(s_, r_, snap, path.string());
    return snap;
  }
  // At a refresh point: a snapshot if the interval has passed or a stop was asked; after a stop's
  // snapshot the thread waits for the process to end (stop_request.hpp). fill(snapshot, true) lends
  // the replica's state to the snapshot, fill(snapshot, false) takes it back.
  template <class Fill>
  void at_refresh(Fill fill) {
    if (s_.stop) s_.stop->throw_if_abandoned();
    if (!on_) return;
    const bool stop = s_.checkpoint->stop && s_.checkpoint->stop->requested();
    const auto now = std::chrono::steady_clock::now();
    if (!stop && std::chrono::duration<double>(now - last_).count() < s_.checkpoint->every_seconds) return;
    ReplicaSnapshot snap;
    fill(snap, true);
    const std::string bytes = encode_snapshot(snapshot_identity(*s_.checkpoint, s_, r_), snap);
    fill(snap, false);
    const auto path = snapshot_path(s_, r_);
    write_checkpoint_file(path, bytes);
    last_ = std::chrono::steady_clock::now();
    if (s_.checkpoint->written) s_.checkpoint->written(path);
    if (stop) {
      s_.checkpoint->stop->leave(true);
      StopRequest::wait_for_exit();
    }
  }
  void finish(const ReplicaRecord& out) const {
    if (!on_) return;
    write_checkpoint_file(done_path(s_, r_), encode_done(snapshot_identity(*s_.checkpoint, s_, r_), out));
    std::error_code ec;
    std::filesystem::remove(snapshot_path(s_, r_), ec);  // the .done supersedes it
  }

 private:
  const DsmcSetup& s_;
  std::size_t r_;
  bool on_;
  std::chrono::steady_clock::time_point last_;
};

// Moves the replica's large state into a snapshot and back (lent, not copied: a copy would double the
// peak memory of a large run while it is written).
template <class T>
void lend(T& owner, T& snapshot, bool lending) {
  if (lending) snapshot = std::move(owner);
  else owner = std::move(snapshot);
}

bool has_tamsd(const DsmcSetup& s) { return s.tamsd_measurement_time > 0.0; }

// The stops of a set-up with its TAMSD start times and weights.
struct Plan {
  std::vector<double> starts;
  std::vector<std::vector<double>> weights;
  std::vector<Stop> stops;
};

Plan plan(const DsmcSetup& s) {
  Plan p;
  constexpr std::size_t grid_starts = 512;
  if (has_tamsd(s)) p.starts = tamsd_starts(s, grid_starts);
  for (std::size_t l = 0; l < s.tamsd_lags.size(); ++l)
    p.weights.push_back(tamsd_weights(p.starts, grid_starts, l, s.tamsd_lags[l], s.tamsd_measurement_time));
  p.stops = schedule(s, p.starts, p.weights);
  return p;
}

template <class Selector>
ReplicaRecord run_event_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r, ReplicaCheckpoint& ck) {
  auto clock = std::chrono::steady_clock::now();
  std::optional<ReplicaSnapshot> snap = ck.resume_point();
  ReplicaRecord out;
  Rng rng(s.seed, r);
  const bool tamsd = has_tamsd(s);
  const Plan pl = plan(s);
  const std::size_t M = s.mixture.size(), L = s.tamsd_lags.size();
  std::vector<std::vector<Vec3>> at_start(pl.starts.size());
  std::vector<double> sum(L * M, 0.0), count(L * M, 0.0);
  bool aging = s.aged;
  std::size_t first = 0;
  Particles p;
  if (snap) {
    p = std::move(snap->particles), out = std::move(snap->record);
    rng.restore(snap->rng);  // checked by check_snapshot (same stream)
    at_start = std::move(snap->tamsd_start), sum = std::move(snap->tamsd_sum), count = std::move(snap->tamsd_weight);
    aging = snap->aging, first = snap->stop;
  } else {
    p = maxwellian_particles(s.mixture, s.counts, s.T0, s.msd || tamsd, s.rescale, rng);
  }
  Selector sel(pairs, p, tamsd ? 1 : s.speed_classes);
  Counters c;
  EventLoop<Selector> loop(p, sel, s.law, rng, c, p.size());
  if (snap) loop.resume(snap->loop, snap->counters);
  std::size_t stop = first;
  PublishedCollisions progress;  // the progress line's view of this replica (dsmc/progress_counter.hpp)
  loop.at_refresh([&] {
    progress.at(c.accepted);
    if (!ck.hooked()) return;
    ck.at_refresh([&](ReplicaSnapshot& x, bool lending) {
      if (lending) x.aging = aging, x.stop = stop, x.rng = rng.state(), x.loop = loop.state(), x.counters = c;
      lend(p, x.particles, lending), lend(out, x.record, lending);
      lend(at_start, x.tamsd_start, lending), lend(sum, x.tamsd_sum, lending), lend(count, x.tamsd_weight, lending);
    });
  });
  if (aging) {
    loop.cool_to(1.5 * double(p.size()));  // ⟨T⟩ = 2E/(3N) = 1
    loop.reset_clock();
    aging = false;
  }
  // Tracers: the first K particles of each species (initial velocities are i.i.d., so any K will do).
  std::vector<std::size_t> tracers(M);
  for (std::size_t k = 0; k < M; ++k) tracers[k] = std::min(s.tamsd_tracers, p.count(k));
  out.seconds_setup += lap(clock);
  for (; stop < pl.stops.size(); ++stop) {
    const Stop& st = pl.stops[stop];
    loop.run_until(st.t);
    out.seconds_loop += lap(clock);
    if (st.kind == Stop::sample) {
      sample(p, st.t, s, c, out);
      out.rescaled_time.push_back(loop.rescaled_time());
    } else if (st.kind == Stop::start) {
      for (std::size_t k = 0; k < M; ++k)
        for (std::size_t j = 0; j < tracers[k]; ++j) at_start[st.index].push_back(displacement(p, p.begin(k) + j, st.t));
    } else {
      std::size_t n = 0;
      for (std::size_t k = 0; k < M; ++k)
        for (std::size_t j = 0; j < tracers[k]; ++j, ++n) {
          const Vec3 a = at_start[st.index][n], b = displacement(p, p.begin(k) + j, st.t);
          const double w = pl.weights[st.lag][st.index];
          sum[st.lag * M + k] += w * ((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y) + (b.z - a.z) * (b.z - a.z));
          count[st.lag * M + k] += w;
        }
    }
    out.seconds_sample += lap(clock);
  }
  for (std::size_t i = 0; i < sum.size(); ++i) out.tamsd.push_back(sum[i] / count[i]);
  out.trials = c.trials, out.accepted = c.accepted;
  return out;
}

ReplicaRecord run_time_step_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r, ReplicaCheckpoint& ck) {
  if (s.aged || has_tamsd(s)) throw std::invalid_argument("DSMC: the timestep method has no aged start and no TAMSD");
  auto clock = std::chrono::steady_clock::now();
  std::optional<ReplicaSnapshot> snap = ck.resume_point();
  Rng rng(s.seed, r);
  ReplicaRecord out;
  Particles p;
  std::size_t j = 0;
  if (snap) {
    p = std::move(snap->particles), out = std::move(snap->record), j = snap->stop;
    rng.restore(snap->rng);
  } else {
    p = maxwellian_particles(s.mixture, s.counts, s.T0, s.msd, s.rescale, rng);
  }
  Counters c;
  TimeStepScheme scheme(p, pairs, s.law, rng, c, s.time_step_factor);
  if (snap) scheme.resume(snap->loop, snap->counters);
  PublishedCollisions progress;  // the progress line's view of this replica (dsmc/progress_counter.hpp)
  scheme.after_step([&] {
    progress.at(c.accepted);
    if (!ck.hooked()) return;
    ck.at_refresh([&](ReplicaSnapshot& x, bool lending) {
      if (lending) x.stop = j, x.rng = rng.state(), x.loop = scheme.state(), x.counters = c;
      lend(p, x.particles, lending), lend(out, x.record, lending);
    });
  });
  out.seconds_setup += lap(clock);
  for (; j < s.times.size(); ++j) {
    scheme.run_until(s.times[j]);
    out.seconds_loop += lap(clock);
    sample(p, s.times[j], s, c, out);
    out.seconds_sample += lap(clock);
    out.rescaled_time.push_back(std::numeric_limits<double>::quiet_NaN());  // not tracked by the scheme
  }
  out.trials = c.trials, out.accepted = c.accepted, out.steps = scheme.steps();
  return out;
}

ReplicaRecord dispatch(const DsmcSetup& s, const PairTable& pairs, Method method, std::size_t r, ReplicaCheckpoint& ck) {
  switch (method) {
    case Method::direct: return run_event_replica<DirectSelector>(s, pairs, r, ck);
    case Method::lowrank: return run_event_replica<LowRankSelector>(s, pairs, r, ck);
    case Method::timestep: return run_time_step_replica(s, pairs, r, ck);
    case Method::bird_global: return run_event_replica<GlobalBirdSelector>(s, pairs, r, ck);
    default: return run_event_replica<BirdSelector>(s, pairs, r, ck);
  }
}

// The number of samples a replica has taken before stop `stop`.
std::size_t samples_before(const Plan& pl, std::size_t stop) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < stop; ++i) n += pl.stops[i].kind == Stop::sample;
  return n;
}

template <class V>
bool all_finite(const std::vector<V>& v) {
  for (const V& x : v)
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) return false;
  return true;
}

}  // namespace

Method resolved_method(const DsmcSetup& s) {
  if (s.method != Method::automatic) return s.method;
  return s.mixture.size() <= 8 ? Method::direct : Method::lowrank;
}

ReplicaRecord run_replica(const DsmcSetup& s, const PairTable& pairs, std::size_t r) {
  ReplicaCheckpoint ck(s, r);
  if (ck.on()) {
    const auto done = done_path(s, r);
    if (const auto bytes = read_checkpoint_file(done)) return decode_done(*bytes, done.string(), snapshot_identity(*s.checkpoint, s, r));
  }
  if (s.stop) s.stop->throw_if_abandoned();  // abandoned: start nothing new
  StopRequest* stop = ck.on() ? s.checkpoint->stop : nullptr;
  if (stop && !stop->enter()) StopRequest::wait_for_exit();  // stopping: start nothing new
  try {
    ReplicaRecord out = dispatch(s, pairs, resolved_method(s), r, ck);
    ck.finish(out);
    if (stop) stop->leave(false);
    return out;
  } catch (...) {
    if (stop) stop->leave(false);
    throw;
  }
}

void check_snapshot(const DsmcSetup& s, std::size_t r, const ReplicaSnapshot& x, const std::string& file) {
  auto refuse = [&](const std::string& why) {
    throw InputError(file + ": does not fit this run: " + why + " (allowed: a snapshot of this scene, fidelity and seed)");
  };
  const std::size_t M = s.mixture.size();
  const bool timestep = resolved_method(s) == Method::timestep, tamsd = has_tamsd(s);
  const Particles& p = x.particles;
  std::vector<std::size_t> offset = {0};
  for (std::size_t n : s.counts) offset.push_back(offset.back() + n);
  if (p.offset != offset) refuse("particle counts per species");
  if (p.mass.size() != M) refuse("species");
  for (std::size_t k = 0; k < M; ++k)
    if (p.mass[k] != s.mixture[k].mass) refuse("mass of species " + std::to_string(k + 1));
  const bool track = s.msd || tamsd;
  if (p.v.size() != offset.back() || p.track_displacement != track || p.flight.size() != (track ? p.v.size() : 0))
    refuse("particle records");
  if (!all_finite(p.v) || !all_finite(p.flight) || !std::isfinite(p.epoch)) refuse("a velocity or displacement that is not finite");
  if (!Rng(s.seed, r).restore(x.rng)) refuse("random stream state");
  const LoopState& l = x.loop;
  if (!std::isfinite(l.t) || !std::isfinite(l.ts) || !std::isfinite(l.t_e1) || !std::isfinite(l.e1_start) ||
      (!timestep && !(l.e1_start > 0.0)))
    refuse("loop clock");
  if (x.counters.species_collisions.size() != M || x.counters.pair_collisions.size() != (M <= pair_count_species_limit ? M * M : 0))
    refuse("collision counters");
  if (x.aging && !s.aged) refuse("an aging phase in a run without aged start");
  const Plan pl = timestep ? Plan{} : plan(s);
  const std::size_t stops = timestep ? s.times.size() : pl.stops.size();
  if (x.stop >= stops || (x.aging && x.stop != 0)) refuse("stop index " + std::to_string(x.stop));
  if (timestep ? x.loop.carry.size() != M * M : !x.loop.carry.empty()) refuse("time-step carries");
  const std::size_t n = timestep ? x.stop : samples_before(pl, x.stop), B = s.distribution_bins;
  const ReplicaRecord& rec = x.record;
  const std::size_t pair_cells = x.counters.pair_collisions.size();
  if (rec.T.size() != n * M || rec.msd.size() != (s.msd ? n * M : 0) || rec.cumulant.size() != (s.cumulant ? n * M : 0) ||
      rec.species_collisions.size() != n * M || rec.pair_collisions.size() != n * pair_cells || rec.rescaled_time.size() != n ||
      rec.distribution.size() != n * M * B || !rec.tamsd.empty())
    refuse("samples taken so far");
  std::size_t tracers = 0;
  for (std::size_t k = 0; k < M; ++k) tracers += std::min(s.tamsd_tracers, s.counts[k]);
  if (x.tamsd_start.size() != pl.starts.size() || x.tamsd_sum.size() != (tamsd ? s.tamsd_lags.size() * M : 0) ||
      x.tamsd_weight.size() != x.tamsd_sum.size())
    refuse("TAMSD accumulators");
  std::vector<bool> started(pl.starts.size(), false);
  for (std::size_t i = 0; i < x.stop && !timestep; ++i)
    if (pl.stops[i].kind == Stop::start) started[pl.stops[i].index] = true;
  for (std::size_t g = 0; g < x.tamsd_start.size(); ++g)
    if (x.tamsd_start[g].size() != (started[g] ? tracers : 0)) refuse("TAMSD tracer positions at start " + std::to_string(g));
}

}  // namespace granmix::dsmc
