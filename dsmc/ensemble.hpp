#pragma once
// Replicas of one DSMC set-up run in parallel (OpenMP), each with its own stream (seed, replica);
// every observable is reported as mean and standard error over replicas. Results do not depend on
// the number of threads: replica r always computes the same numbers and the reduction runs in
// replica order.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "model/mixture.hpp"
#include "model/restitution.hpp"
#include "replica_record.hpp"
#include "stop_request.hpp"

namespace granmix::dsmc {

// Replica records computed elsewhere, by another MPI rank (compare/scheduler.hpp): run_ensemble takes
// replica r of a set-up from here when the source has it, and computes it otherwise.
class ReplicaSource {
 public:
  virtual ~ReplicaSource() = default;
  virtual const ReplicaRecord* find(const std::string& unit_key, std::size_t replica) const = 0;
};

// Snapshots of replicas in flight, written into `dir` every `every_seconds` of wall time, and resumed
// from there (a run killed by a batch queue loses at most one interval).
// Each replica snapshots at the first refresh point after every_seconds of its own wall time (0: at
// every refresh point, for tests); wall time decides only when, never what (dsmc/replica_run.cpp).
struct Checkpointing {
  std::filesystem::path dir;
  double every_seconds = 600.0;
  std::string granmix_version;      // written into every file; files of another version are refused
  StopRequest* stop = nullptr;      // a signal's request to snapshot and stop (dsmc/stop_request.hpp)
  std::function<void(const std::filesystem::path&)> written;  // after each snapshot (tests: stop after the k-th)
};

enum class Method { automatic, direct, lowrank, bird, timestep, bird_global };
Method parse_method(const std::string& name);  // throws std::invalid_argument
const char* to_string(Method m);

struct DsmcSetup {
  model::Mixture mixture{{model::Species{}}};
  model::Restitution law = model::Restitution::constant(1, 1.0);
  std::vector<std::vector<double>> chi;  // empty: dilute
  std::vector<std::size_t> counts;       // particles per species
  std::vector<double> T0;                // initial temperatures
  std::vector<double> times;             // sample times (increasing)
  Method method = Method::automatic;     // automatic: direct up to 8 species, low-rank above
  bool msd = false, cumulant = false, rescale = true;
  // Aged start (v1 Fig. 3 dashed): T0 is the hot start; the gas cools until ⟨T⟩ = 1, then the
  // clock, displacements and collision counts are reset and the measurement begins.
  bool aged = false;
  double time_step_factor = 3e-3;  // timestep method: Δt = factor λ11/v01(t) (MG Sec. 3)
  // Time-averaged MSD (docs/physics.md §4) of `tamsd_tracers` particles per species over [0, 𝒯]: for
  // each lag, [R(t+Δ) − R(t)]² averaged over the tracers and, with trapezoid weights, over 512 start
  // times t <= 𝒯 − Δ (0 and a geometric grid from 1e-6 𝒯: the early, fast-cooling times need them).
  double tamsd_measurement_time = 0.0;  // 𝒯; 0: no TAMSD
  std::vector<double> tamsd_lags;
  std::size_t tamsd_tracers = 100;
  // Velocity distribution Φ_k(v*) (MG Eq. 12), v* = |v|/v0, v0² = 2T(m_1+m_2)/(m_1 m_2) with the
  // mixture temperature T = Σ x_k T_k (MG; m_2 = m_1 for one species): `bins` shells on [0, v_max].
  std::size_t distribution_bins = 0;  // 0: none
  double distribution_vmax = 4.0;
  // Settled (HCS) runs: Φ_k(v*) is stationary, so each replica's histogram is averaged over the
  // sample times before the replica statistics are taken (one block [(k * bins) + b]).
  bool distribution_time_average = false;
  // Speed classes per species for the direct and low-rank majorants (dsmc/speed_classes.hpp); 1 is
  // the paper's per-species vmax. TAMSD runs use 1: classes reorder particles, tracers need identity.
  // 3 is the fastest of 1–8 on the 691-species system (speed_classes.cpp).
  std::size_t speed_classes = 3;
  std::uint64_t seed = 1;
  std::size_t replicas = 1;
  int threads = 0;  // 0: all cores
  // Names this set-up's units of work (replicas) for the scheduler and the checkpoints: scene hash,
  // fidelity, seed of the run (scene_dsmc.cpp). Empty: an anonymous set-up (tests, benchmarks), which
  // is always computed here and never checkpointed. `scene_sha256` is checked against snapshots.
  std::string unit_key, scene_sha256;
  const ReplicaSource* source = nullptr;          // none: every replica computed here
  const Checkpointing* checkpoint = nullptr;      // none: no snapshots
  const StopRequest* stop = nullptr;              // a host's abandoning stop (stop_request.hpp); none: runs to the end
};

// Mean and standard error over independent replicas of a vector of observables, and each
// replica's own values, from which any derived quantity gets its error (jackknife below).
struct Estimate {
  std::vector<double> mean, err;  // standard error of the mean over replicas (0 for one replica)
  std::vector<double> replicas;   // [r * mean.size() + i]: replica r's value of element i
  std::size_t count() const { return mean.empty() ? 0 : replicas.size() / mean.size(); }
  // Mean of element i over every replica but `skip` (skip >= count(): over all of them).
  double mean_without(std::size_t i, std::size_t skip) const {
    const std::size_t R = count();
    if (skip >= R || R < 2) return mean[i];
    return (double(R) * mean[i] - replicas[skip * mean.size() + i]) / double(R - 1);
  }
};

// A quantity derived from replica means, f(skip) = its value from the means without replica `skip`
// (skip = npos, or any skip >= R: all replicas), with the jackknife standard error sqrt((R−1)/R Σ (f(r) − f̄)²). For a
// linear f it is exactly the standard error of the mean; for ratios and weighted sums of species it
// keeps the correlations between the parts (species trade energy; an MSD increment shares its
// endpoints' noise) that propagation "as if independent" gets wrong.
template <class F>
std::pair<double, double> jackknife(std::size_t R, F f) {
  const double all = f(static_cast<std::size_t>(-1));
  if (R < 2) return {all, 0.0};
  std::vector<double> loo(R);
  double m = 0.0;
  for (std::size_t r = 0; r < R; ++r) loo[r] = f(r), m += loo[r] / double(R);
  double v = 0.0;
  for (double x : loo) v += (x - m) * (x - m);
  return {all, std::sqrt(double(R - 1) / double(R) * v)};
}

// num[a]/den[b] of one run (the same replicas), with the jackknife error.
inline std::pair<double, double> replica_ratio(const Estimate& num, std::size_t a, const Estimate& den, std::size_t b) {
  return jackknife(num.count(), [&](std::size_t skip) { return num.mean_without(a, skip) / den.mean_without(b, skip); });
}

// a/b of two results of INDEPENDENT runs (value, standard error): relative errors in quadrature.
// Within one run use jackknife() instead: its parts share the replicas.
inline std::pair<double, double> ratio_of_independent(std::pair<double, double> a, std::pair<double, double> b) {
  const double q = a.first / b.first;
  return {q, std::abs(q) * std::hypot(a.second / a.first, b.second / b.first)};
}

struct DsmcResult {
  Method method = Method::direct;
  std::size_t species = 0, times = 0, replicas = 0, particles = 0;
  Estimate T, msd, cumulant;     // [time * M + k]
  Estimate rescaled_time;        // [time]: t_s = ∫ √(T_1/T_1(0)) dt (event-driven methods; NaN for timestep)
  Estimate tamsd;                // [lag * M + k]
  Estimate distribution;         // [(time * M + k) * bins + b]: Φ_k at the bin centre (time 0 only if averaged)
  Estimate species_collisions;   // [time * M + k]: collisions species k took part in (i = k twice), from t = 0
  Estimate pair_collisions;      // [time * M*M + i*M + k], i <= k, from t = 0; empty above 64 species
  std::uint64_t trials = 0, accepted = 0, steps = 0;  // steps: timestep method only
  double seconds = 0.0;          // wall time of the ensemble; CPU seconds of its replicas when they came from a source
  // CPU time by phase, summed over replicas: particle set-up (and aging), the event loop (pair
  // selection and collisions together: timing them apart would put a clock read on every event),
  // and sampling of observables.
  double seconds_setup = 0.0, seconds_loop = 0.0, seconds_sample = 0.0;
  double volume = 0.0;
  double acceptance() const { return trials ? double(accepted) / double(trials) : 0.0; }
  double collisions_per_second() const { return seconds > 0 ? double(accepted) / seconds : 0.0; }
};

DsmcResult run_ensemble(const DsmcSetup& setup);

// Replica r of a set-up alone, as run_ensemble computes it (the unit of work an MPI rank runs).
ReplicaRecord run_one_replica(const DsmcSetup& setup, std::size_t r);

// Particles per species for a total N, proportional to the number densities (rounded).
std::vector<std::size_t> counts_for(const model::Mixture& mix, std::size_t total);

}  // namespace granmix::dsmc
