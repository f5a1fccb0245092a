#include "scene_dsmc.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "distribution_table.hpp"
#include "model/enskog.hpp"
#include "model/errors.hpp"
#include "model/sha256.hpp"
#include "theory/histories/initial_state.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::dsmc {

namespace {

using model::Table;

// Every derived DSMC value below is a function of replica means; its error is the jackknife over
// replicas (ensemble.hpp), so sums over species and ratios keep their correlations.
Table make_table(const model::Scene& s, const DsmcSetup& setup, const DsmcResult& r) {
  const auto& o = s.observables;
  const std::size_t M = s.mixture.size(), R = r.replicas;
  Table t;
  t.columns = {"t", "species"};
  auto add = [&](const char* name) { t.columns.push_back(name), t.columns.push_back(std::string(name) + "_err"); };
  if (o.rescaled_time) add("t_s");
  if (o.temperatures) add("T");
  if (o.msd) add("msd");
  if (o.msd_ratio) add("msd_ratio");
  if (o.cumulant) add("c");
  if (o.gamma) add("gamma");
  if (o.tamsd) t.columns.push_back("lag"), add("tamsd");
  add("collisions");
  const double nan = Table::missing;
  for (std::size_t j = 0; j < setup.times.size(); ++j) {
    for (std::size_t k = 0; k <= M; ++k) {
      if (k == 0 && M == 1) continue;
      std::vector<double> row = {setup.times[j], double(k)};
      // Species k, or for k = 0 the density-weighted mean over species (⟨T⟩, total MSD v1 Eq. 16).
      auto species_value = [&](const Estimate& e) {
        if (k > 0) return std::pair{e.mean[j * M + k - 1], e.err[j * M + k - 1]};
        return jackknife(R, [&](std::size_t skip) {
          double m = 0.0;
          for (std::size_t a = 0; a < M; ++a) m += s.mixture.fraction(a) * e.mean_without(j * M + a, skip);
          return m;
        });
      };
      auto push = [&](std::pair<double, double> v) { row.push_back(v.first), row.push_back(v.second); };
      if (o.rescaled_time) push({r.rescaled_time.mean[j], r.rescaled_time.err[j]});
      if (o.temperatures) push(species_value(r.T));
      if (o.msd) push(species_value(r.msd));
      // ⟨R_k²⟩/⟨R_1²⟩ (v1 Fig. 8); species 1 is 1 by construction: not a measurement.
      if (o.msd_ratio) push(k <= 1 ? std::pair{nan, nan} : replica_ratio(r.msd, j * M + k - 1, r.msd, j * M));
      if (o.cumulant) push(k > 0 ? species_value(r.cumulant) : std::pair{nan, nan});
      if (o.gamma) push(k == 0 ? replica_ratio(r.T, j * M, r.T, j * M + 1) : std::pair{nan, nan});  // γ = T_1/T_2 (MG Eq. 45)
      if (o.tamsd) {
        row.push_back(setup.times[j]);  // lags are the time grid (as in theory.tsv)
        push(k > 0 ? std::pair{r.tamsd.mean[j * M + k - 1], r.tamsd.err[j * M + k - 1]} : std::pair{nan, nan});
      }
      // Collisions per particle: species k takes part in C_ik for i != k once and in C_kk twice; the
      // whole system's count sums the species (each collision twice).
      const double particles = k == 0 ? double(r.particles) : double(setup.counts[k - 1]);
      push(jackknife(R, [&](std::size_t skip) {
        double c = 0.0;
        for (std::size_t a = (k == 0 ? 0 : k - 1); a < (k == 0 ? M : k); ++a) c += r.species_collisions.mean_without(j * M + a, skip);
        return c / particles;
      }));
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

// Value and error (the column `name_err` that follows it) of column `name` in one row of a DSMC table.
std::pair<double, double> cell(const Table& t, std::size_t row, const std::string& name) {
  const int c = t.column(name);
  if (c < 0 || t.column(name + "_err") != c + 1) throw std::logic_error("DSMC table has no column " + name + " with its error");
  return {t.rows[row][c], t.rows[row][c + 1]};
}

// γ(n*)/γ(0) sweeps run an extra n* = 0 reference with the master seed.
bool has_reference_run(const model::Scene& s) {
  return s.observables.gamma && s.theory.sweep->parameter == model::Sweep::Parameter::n_star;
}

// Each sweep point has its own seed derived from the master seed: point n, seed + 1000003 (n + 1).
std::uint64_t point_seed(std::uint64_t seed, std::size_t n) { return seed + 1000003 * (n + 1); }

// One HCS run at a value x of the swept parameter, from the settled ratios.
model::Scene sweep_point_scene(const model::Scene& s, double x) {
  const auto& o = s.observables;
  model::Scene point = model::sweep_point(s, x);
  point.initial.kind = model::InitialState::Kind::hcs;
  point.observables = model::Observables{};
  point.observables.gamma = o.gamma, point.observables.msd = o.d_ratio, point.observables.cumulant = o.cumulant;
  return point;
}

// γ = T_1/T_2 of a settled run (MG Eq. 45), averaged over its [time] samples: the run starts from settled ratios, so
// every sample is in the HCS; its fluctuations decorrelate within a few collisions, so 21 samples over MG's 50–100 t₀
// halve γ's error bar against the last sample alone (mg-fig04-mu2, quick). Each sample's ratio of replica means, their
// mean jackknifed over replicas (the samples share them).
std::pair<double, double> settled_gamma(const DsmcResult& r) {
  const std::size_t M = r.species, J = r.times;
  return jackknife(r.replicas, [&](std::size_t skip) {
    double sum = 0.0;
    for (std::size_t j = 0; j < J; ++j) sum += r.T.mean_without(j * M, skip) / r.T.mean_without(j * M + 1, skip);
    return sum / double(J);
  });
}

}  // namespace

DsmcRun run_sweep_dsmc(const model::Scene& s, const RunOptions& opt) {
  const model::Sweep& sw = *s.theory.sweep;
  const auto& o = s.observables;
  const std::size_t M = s.mixture.size();
  const bool relative = has_reference_run(s);
  DsmcRun out;
  Table& t = out.table;
  t.columns = {sw.column(), "species"};
  auto add = [&](const char* name) { t.columns.push_back(name), t.columns.push_back(std::string(name) + "_err"); };
  if (o.d_ratio) add("D_ratio");
  if (o.gamma) add("gamma");
  if (relative) add("gamma_ratio");
  if (o.cumulant) add("c");
  const double nan = Table::missing;
  auto run_at = [&](double x, std::uint64_t point_seed) {
    RunOptions point_opt = opt;
    point_opt.seed = point_seed;
    const DsmcRun r = run_scene_dsmc(sweep_point_scene(s, x), point_opt);
    DsmcResult& a = out.result;
    a.method = r.result.method, a.species = M, a.replicas = r.result.replicas, a.particles = r.result.particles;
    a.trials += r.result.trials, a.accepted += r.result.accepted, a.seconds += r.result.seconds;
    a.seconds_setup += r.result.seconds_setup, a.seconds_loop += r.result.seconds_loop, a.seconds_sample += r.result.seconds_sample;
    return r;
  };
  const std::size_t per_time = M > 1 ? M + 1 : M;
  auto row_of = [&](std::size_t start, std::size_t k) { return start + (M > 1 ? k : k - 1); };
  std::pair<double, double> gamma0{nan, nan};
  if (relative) {
    const DsmcRun r0 = run_at(0.0, opt.seed);
    gamma0 = settled_gamma(r0.result);
  }
  for (std::size_t n = 0; n < s.dsmc.at.size(); ++n) {
    const double x = s.dsmc.at[n];
    const DsmcRun r = run_at(x, point_seed(opt.seed, n));
    const std::size_t last = r.table.rows.size() - per_time;
    const std::size_t J = r.setup.times.size();
    for (std::size_t k = (o.gamma ? 0 : 1); k <= M; ++k) {
      std::vector<double> row = {x, double(k)};
      auto push = [&](std::pair<double, double> v) { row.push_back(v.first), row.push_back(v.second); };
      if (o.d_ratio) {
        // Settled D_k/D_1 measured as the ratio of MSD increments between the first and the last
        // sample time (theory predicts exactly this: D_ratio_increment). Species 1 is 1 by
        // construction and not reported. Jackknife: the two increments share replicas.
        const Estimate& msd = r.result.msd;
        auto increment = [&](std::size_t kk, std::size_t skip) {
          return msd.mean_without((J - 1) * M + kk - 1, skip) - msd.mean_without(kk - 1, skip);
        };
        push(k <= 1 ? std::pair{nan, nan}
                    : jackknife(r.result.replicas, [&](std::size_t skip) { return increment(k, skip) / increment(1, skip); }));
      }
      const auto gamma = k == 0 && o.gamma ? settled_gamma(r.result) : std::pair{nan, nan};
      if (o.gamma) push(gamma);
      if (relative) push(k == 0 ? ratio_of_independent(gamma, gamma0) : std::pair{nan, nan});  // two independent runs
      if (o.cumulant) push(k == 0 ? std::pair{nan, nan} : cell(r.table, row_of(last, k), "c"));
      t.rows.push_back(std::move(row));
    }
  }
  return out;
}

DsmcSetup scene_setup(const model::Scene& s, const RunOptions& opt) {
  const std::string& fidelity = opt.fidelity;
  if (s.observables.d_ratio)
    throw InputError(s.file + ": DSMC does not measure d_ratio (allowed: temperatures, msd, cumulant, gamma, rescaled_time, tamsd)");
  const model::DsmcFidelity f = fidelity == "paper" ? s.dsmc.paper : s.dsmc.quick;
  DsmcSetup d;
  d.mixture = s.mixture;
  d.law = s.restitution;
  if (s.enskog) d.chi = model::enskog_contact_values(s.mixture);
  d.counts = counts_for(s.mixture, f.particles);
  for (std::size_t k = 0; k < d.counts.size(); ++k)
    if (d.counts[k] == 0)
      throw InputError(s.file + ": dsmc." + fidelity + ".particles = " + std::to_string(f.particles) + " leaves species " +
                       std::to_string(k + 1) + " without particles (allowed: enough for every species)");
  const theory::CollisionRates rates = theory::scene_rates(s, s.mixture, s.restitution);
  d.aged = s.initial.kind == model::InitialState::Kind::aged;
  if (d.aged) {
    d.T0.assign(s.mixture.size(), s.initial.T_hot);
  } else if (s.theory.tracer) {
    // Tracer scenes: the gas at T₁ = 1, the intruders at the scene's start ratio, never a number of the judged level.
    d.T0 = {1.0, theory::tracer_start_theta(s.initial, rates)};
  } else {
    d.T0 = theory::initial_temperatures(s.initial, rates);
  }
  const double unit = theory::scene_time_unit(s);
  d.times = s.times;
  for (double& t : d.times) t *= unit;
  d.method = parse_method(s.dsmc.method);
  d.time_step_factor = s.dsmc.time_step;
  if (d.method == Method::timestep && d.aged)
    throw InputError(s.file + ": dsmc.method = \"timestep\" has no aged start (allowed: auto, direct, lowrank, bird, bird-global)");
  d.msd = s.observables.needs_msd();
  const bool settled_distribution = s.observables.distribution_settled;
  d.cumulant = s.observables.cumulant || settled_distribution;  // Δ_k needs the simulation's c_k
  d.rescale = s.dsmc.rescale;
  d.distribution_bins = s.observables.distribution_bins;
  d.distribution_vmax = s.observables.distribution_vmax;
  d.distribution_time_average = settled_distribution;
  if (s.observables.tamsd) {
    d.tamsd_measurement_time = s.observables.tamsd_measurement_time * unit;
    d.tamsd_lags = d.times;
    d.tamsd_tracers = s.observables.tamsd_tracers;
  }
  d.seed = opt.seed;
  d.replicas = f.replicas;
  d.threads = opt.threads;
  d.scene_sha256 = model::sha256_hex(s.text);
  // Scene, fidelity and seed name the run: a sweep point's seed is its own (point_seed).
  d.unit_key = s.name + "." + fidelity + ".seed" + std::to_string(opt.seed) + "." + d.scene_sha256.substr(0, 12);
  d.source = opt.source, d.checkpoint = opt.checkpoint, d.stop = opt.stop;
  return d;
}

namespace {
// One replica has no spread: its error columns are NaN ("unknown"), never 0, so that nothing downstream reads an
// exact result into a single run.
void unknown_errors_of_one_replica(model::Table& t) {
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c].size() > 4 && t.columns[c].compare(t.columns[c].size() - 4, 4, "_err") == 0)
      for (auto& row : t.rows) row[c] = std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

DsmcRun run_scene_dsmc(const model::Scene& s, const RunOptions& opt) {
  DsmcRun run = run_scene_dsmc_tables(s, opt);
  if (run.result.replicas == 1) {
    unknown_errors_of_one_replica(run.table);
    unknown_errors_of_one_replica(run.distribution);
  }
  return run;
}

std::vector<std::string> run_notes(const model::Scene& s, const std::string& fidelity) {
  std::vector<std::string> notes;
  if (!s.dsmc.present) return notes;
  const model::DsmcFidelity f = fidelity == "paper" ? s.dsmc.paper : s.dsmc.quick;
  if (fidelity == "paper" && !s.dsmc.paper_given)
    notes.push_back("[dsmc] has no paper table: --fidelity paper runs the quick settings (" + std::to_string(f.particles) +
                    " particles x " + std::to_string(f.replicas) + " replicas)");
  // The split by density rounds each species' count; the shipped scenes keep that split (their results stay
  // reproducible), so a total it misses is stated, not silently changed.
  std::vector<model::Mixture> mixtures{s.mixture};
  if (s.theory.sweep)
    for (double x : s.dsmc.at) mixtures.push_back(model::sweep_point(s, x).mixture);
  std::vector<std::size_t> totals;
  for (const model::Mixture& m : mixtures) {
    std::size_t n = 0;
    for (std::size_t c : counts_for(m, f.particles)) n += c;
    if (n != f.particles && std::find(totals.begin(), totals.end(), n) == totals.end()) totals.push_back(n);
  }
  for (std::size_t n : totals)
    notes.push_back("dsmc." + fidelity + ".particles = " + std::to_string(f.particles) + " split over the species by density (each count rounded) gives " +
                    std::to_string(n) + " particles; the run uses " + std::to_string(n));
  return notes;
}

DsmcRun run_scene_dsmc_tables(const model::Scene& s, const RunOptions& opt) {
  if (!s.dsmc.present) throw InputError(s.file + ": scene has no [dsmc] table: nothing to simulate");
  if (s.theory.sweep) return run_sweep_dsmc(s, opt);
  DsmcRun run;
  DsmcSetup& d = run.setup;
  d = scene_setup(s, opt);
  const bool settled_distribution = s.observables.distribution_settled;
  const double unit = theory::scene_time_unit(s);
  run.result = run_ensemble(d);
  if (settled_distribution) {
    run.table = settled_distribution_table(s, d, run.result);
    return run;
  }
  run.table = make_table(s, d, run.result);
  theory::rescale_time_columns(run.table, 1.0 / unit);
  if (d.distribution_bins > 0) {
    const std::size_t M = s.mixture.size(), B = d.distribution_bins;
    const double width = d.distribution_vmax / double(B);
    run.distribution.columns = {"t", "species", "v", "phi", "phi_err"};
    for (std::size_t j = 0; j < d.times.size(); ++j)
      for (std::size_t k = 0; k < M; ++k)
        for (std::size_t b = 0; b < B; ++b) {
          const std::size_t idx = (j * M + k) * B + b;
          run.distribution.rows.push_back({s.times[j], double(k + 1), (b + 0.5) * width, run.result.distribution.mean[idx],
                                           run.result.distribution.err[idx]});
        }
  }
  return run;
}

std::vector<DsmcSetup> plan_scene_dsmc(const model::Scene& s, const RunOptions& opt) {
  if (!s.dsmc.present) return {};
  if (!s.theory.sweep) return {scene_setup(s, opt)};
  std::vector<DsmcSetup> setups;
  auto add = [&](double x, std::uint64_t seed) {
    RunOptions point_opt = opt;
    point_opt.seed = seed;
    setups.push_back(scene_setup(sweep_point_scene(s, x), point_opt));
  };
  if (has_reference_run(s)) add(0.0, opt.seed);
  for (std::size_t n = 0; n < s.dsmc.at.size(); ++n) add(s.dsmc.at[n], point_seed(opt.seed, n));
  return setups;
}

}  // namespace granmix::dsmc
