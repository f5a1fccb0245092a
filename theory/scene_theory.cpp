#include "theory/scene_theory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

#include "theory/rates/diffusion.hpp"
#include "theory/grid/galerkin_decay.hpp"
#include "theory/level_choice.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/histories/initial_state.hpp"
#include "model/enskog.hpp"
#include "model/errors.hpp"
#include "theory/histories/msd.hpp"
#include "theory/numerics/parallel_each.hpp"
#include "theory/numerics/shell_average.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/histories/tamsd.hpp"
#include "theory/rates/time_unit.hpp"

namespace granmix::theory {

namespace {

using model::Table;
constexpr double nan = Table::missing;

MomentMethod moment_method(const std::string& name) {
  return name == "series" ? MomentMethod::series : name == "quadrature" ? MomentMethod::quadrature : MomentMethod::automatic;
}

// Settled quantities along a parameter: D_k/D_1 (v1 Eq. 19), the first-Sonine γ = T_1/T_2 with the
// Maxwellian γ beside it, and the cumulants c_k (MG App. A). Species 0 rows carry γ; along n* also
// γ(α, n*)/γ(α, 0) (MG Fig. 6).
// Per-time values of every species, however they were computed.
struct Sample {
  double t_s = nan;
  std::vector<double> T, msd, D_ratio, tamsd;
};

std::vector<Sample> history_samples(const model::Scene& s, const CollisionRates& rates, const TheoryLevel& level, SolverStats& stats,
                                    std::shared_ptr<GalerkinPairTables> tables = nullptr);

// The theory's prediction of what the DSMC measures along a sweep (dsmc.at): D_k/D_1 as the ratio of
// MSD increments between the first and the last [time] sample, from DSMC's start (the "hcs" initial state), computed
// through the level's MSD in time (transients and the MSD offset included); a level whose MSD is the closed form of its
// own settled state has the start's effect carried by its start_companion (theory_level.hpp). start_error (asked with
// `checked`, per species, species 1: 0): that factor's model error, |its value by the lower companion over the
// companion's − 1|.
struct IncrementRatios {
  std::vector<double> ratio, start_error;
};

IncrementRatios increment_ratios(const model::Scene& point, const TheoryLevel& level, bool checked) {
  model::Scene p = point;
  p.initial.kind = model::InitialState::Kind::hcs;
  p.observables = model::Observables{};
  p.observables.msd = true;
  const CollisionRates rates = scene_rates(p, p.mixture, p.restitution);
  // The histories below solve the same Galerkin problem (the converged levels' bases come from the Maxwellian settled
  // temperatures, theory_level.cpp) and reach the same nodes: their pair tables are built once (v1 Fig. 7's checked
  // points: ~52 nodes, ~37 ms, each).
  const auto tables = std::make_shared<GalerkinPairTables>();
  auto ratios = [&](const TheoryLevel& l) {
    SolverStats unused;
    const std::vector<Sample> m = history_samples(p, rates, l, unused, tables);
    std::vector<double> out;
    for (std::size_t k = 0; k < p.mixture.size(); ++k) out.push_back((m.back().msd[k] - m.front().msd[k]) / (m.back().msd[0] - m.front().msd[0]));
    return out;
  };
  IncrementRatios out{ratios(level), std::vector<double>(p.mixture.size(), 0.0)};
  const TheoryLevel::StartCompanions companion = level.start_companion();
  if (companion.level.empty()) return out;
  // The start's effect: the companion's VACF history from DSMC's start (the Maxwellian HCS ratios, Maxwellian shapes)
  // over the companion's closed form from its own settled state (ratios and shapes) at the same T₁(0) — the kind of
  // object this level's increments are. (A VACF history from the settled ratios alone starts Maxwellian in shape: at v1
  // Fig. 4 same-material, n₂ = 0.001, it is 0.55% below that closed form, so both halves of the start count.)
  auto start_factor = [&](const std::string& name) {
    const std::unique_ptr<TheoryLevel> c = make_theory_level(name);
    TemperatureOptions opt;
    const std::vector<double> start = c->initial_temperatures(p.initial, rates, opt);
    std::vector<double> settled = c->settled_temperatures(rates);
    const double scale = start[0] / settled[0];
    for (double& T : settled) T *= scale;
    const SettledDiffusion d = c->diffusion_at(rates, settled);
    const double t0 = p.times.front(), t1 = p.times.back();
    auto increment = [&](std::size_t k) { return msd_increment(d.memory_of(k), d.tau0, 0.0, t1) - msd_increment(d.memory_of(k), d.tau0, 0.0, t0); };
    std::vector<double> f = ratios(*c);
    for (std::size_t k = 0; k < f.size(); ++k) f[k] /= increment(k) / increment(0);
    return f;
  };
  const std::vector<double> f = start_factor(companion.level);
  for (std::size_t k = 0; k < f.size(); ++k) out.ratio[k] *= f[k];
  if (!checked) return out;
  const std::vector<double> lower = start_factor(companion.lower);
  for (std::size_t k = 0; k < f.size(); ++k) out.start_error[k] = std::abs(lower[k] / f[k] - 1.0);
  return out;
}

Table sweep_table(const model::Scene& s, const TheoryLevel& level) {
  const model::Sweep& sw = *s.theory.sweep;
  const auto& o = s.observables;
  const std::size_t N = s.mixture.size();
  const bool relative = o.gamma && sw.parameter == model::Sweep::Parameter::n_star;
  Table t;
  t.columns = {sw.column(), "species"};
  const bool increments = o.d_ratio && s.dsmc.present && s.times.size() >= 2;
  if (o.d_ratio) t.columns.push_back("D_ratio");
  if (increments) t.columns.push_back("D_ratio_increment");
  // The level's own model error of D_k/D_1, where it computes one: at the DSMC points only (four more HCS solves each),
  // plus its start factor's (increment_ratios: one more VACF history).
  const bool errors = increments && level.computes_d_ratio_error();
  if (errors) t.columns.push_back("D_ratio_error");
  if (o.gamma) t.columns.push_back("gamma"), t.columns.push_back("gamma_maxwell");
  // gamma_ratio_maxwell: the same ratio from Maxwellian γ's, so that a scene can judge the first-Sonine
  // ratio with its last correction as model error (correction_from = "maxwell").
  if (relative) t.columns.push_back("gamma_ratio"), t.columns.push_back("gamma_ratio_maxwell");
  if (o.cumulant) t.columns.push_back("c");
  // The level's HCS (MG's first Sonine, or order 3) and the Maxwellian one beside it.
  auto sonine_of = [](const TheoryLevel& l, const model::Scene& p) { return l.hcs(scene_rates(p, p.mixture, p.restitution)); };
  auto maxwell_of = [](const model::Scene& p) { return sonine_hcs(p.mixture, p.restitution, scene_contact_values(p), true); };
  const double gamma0 = relative ? sonine_of(level, model::sweep_point(s, 0.0)).gamma() : nan;
  const double gamma0_maxwell = relative ? maxwell_of(model::sweep_point(s, 0.0)).gamma() : nan;
  // The points on OpenMP threads, each wholly on one with a level object of its own (a level keeps a memo: one per
  // thread), their rows then in sweep order: the numbers do not depend on the thread count. (Each of v1 Fig. 7's 11
  // points solves the four species' converged HCS and tracer problems.)
  // A DSMC point with the level's error estimates (the points are on the sweep's grid exactly: model/scene.cpp).
  auto is_checked = [&](double x) { return errors && std::find(s.dsmc.at.begin(), s.dsmc.at.end(), x) != s.dsmc.at.end(); };
  auto point_rows = [&](double x) {
    std::vector<std::vector<double>> out;
    const std::unique_ptr<TheoryLevel> own = level.descriptor().make();
    const model::Scene p = model::sweep_point(s, x);
    SettledDiffusion d;
    std::vector<double> error(N, nan);
    const bool checked = is_checked(x);
    if (o.d_ratio) {
      const CollisionRates rates = scene_rates(p, p.mixture, p.restitution);
      // Asked first: the level keeps the checked state for the D and increments that follow. (The DSMC points are on
      // the grid exactly: model/scene.cpp puts them there.)
      if (checked) error = own->d_ratio_error(rates);
      d = own->diffusion_at(rates, own->settled_temperatures(rates));
    }
    const IncrementRatios inc = increments ? increment_ratios(p, *own, checked) : IncrementRatios{};
    for (std::size_t k = 0; checked && k < N; ++k) error[k] += inc.start_error[k];  // the start factor's part
    SonineHcs sonine, maxwell;
    if (o.gamma || o.cumulant) sonine = sonine_of(*own, p);
    if (o.gamma) maxwell = maxwell_of(p);
    for (std::size_t k = (o.gamma ? 0 : 1); k <= N; ++k) {
      std::vector<double> row = {x, double(k)};
      if (o.d_ratio) row.push_back(k ? d.D_ratio[k - 1] : nan);
      if (increments) row.push_back(k > 1 ? inc.ratio[k - 1] : nan);  // species 1: 1 by construction
      if (errors) row.push_back(k > 1 ? error[k - 1] : nan);
      if (o.gamma) row.push_back(k ? nan : sonine.gamma()), row.push_back(k ? nan : maxwell.gamma());
      if (relative) row.push_back(k ? nan : sonine.gamma() / gamma0), row.push_back(k ? nan : maxwell.gamma() / gamma0_maxwell);
      if (o.cumulant) row.push_back(k ? sonine.c[k - 1] : nan);
      out.push_back(std::move(row));
    }
    return out;
  };
  std::vector<std::vector<std::vector<double>>> rows(sw.values.size());
  // The DSMC points first: with their error estimates each costs ~4 plain points (v1 Fig. 7), and one of them started
  // late keeps a thread busy while the other idles. The rows stay in sweep order.
  std::vector<std::size_t> order(sw.values.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_partition(order.begin(), order.end(), [&](std::size_t j) { return is_checked(sw.values[j]); });
  parallel_each(order.size(), [&](std::size_t n) {
    const std::size_t j = order[n];
    try {
      rows[j] = point_rows(sw.values[j]);
    } catch (const NumericalError& e) {  // a solver failed at one point: say which (exit 3 names the solver and the point)
      throw NumericalError(std::string(e.what()) + " (at the sweep point " + sw.column() + " = " + fmt::format("{:g}", sw.values[j]) + ")");
    }
  });
  for (auto& point : rows)
    for (auto& row : point) t.rows.push_back(std::move(row));
  return t;
}

// The level's settled distribution on the DSMC bins (MG Figs. 3, 7), each value the shell
// average of what a histogram bin estimates: Φ_k (Eq. 27; at order 3 with a₃S₃), the Maxwellian with the same
// λ_k, Δ_k from those two as MG Eq. (27) defines it (→ Eq. 28 for narrow bins), G_k = exp(2β_k v*/ζ*) Φ_k
// (Eq. 30) at the bin centre v*, and the Maxwellian G. The weight exp(2β_k v*/ζ*) is part of G's definition,
// the first-Sonine one at every level, as the DSMC's (dsmc/distribution_table.cpp).
Table distribution_table(const model::Scene& s, const TheoryLevel& level) {
  const auto& o = s.observables;
  const TheoryLevel::SettledDistribution d = level.settled_distribution(scene_rates(s, s.mixture, s.restitution));
  const SonineHcs& h = d.hcs;
  const SonineHcs first = sonine_hcs(s.mixture, s.restitution, scene_contact_values(s));
  Table t;
  t.columns = {"v", "species", "phi", "phi_maxwell", "delta", "G", "G_maxwell"};
  // A level's own computed error of Φ per bin (kinetic-hcs-converged): relative for Φ and G (MG Eq. 30: G = weight·Φ),
  // and carried into Δ = (2/c)(Φ/Φ_M − 1) (MG Eq. 27), whose absolute error is (2/|c|)(Φ/Φ_M)·e, as a relative one of Δ.
  if (d.bin_error) t.columns.push_back("phi_error"), t.columns.push_back("delta_error");
  const double width = o.distribution_vmax / double(o.distribution_bins);
  for (std::size_t b = 0; b < o.distribution_bins; ++b) {
    const double lo = b * width, hi = lo + width, v = 0.5 * (lo + hi);
    for (std::size_t k = 0; k < s.mixture.size(); ++k) {
      const double phi = shell_average([&](double u) { return d.phi(k, u); }, lo, hi);
      const double maxwell = shell_average([&](double u) { return maxwellian_phi(h.lambda[k], u); }, lo, hi);
      const double tail = std::exp(first.tail_exponent(k) * v), delta = 2.0 / h.c[k] * (phi / maxwell - 1.0);
      t.rows.push_back({v, double(k + 1), phi, maxwell, delta, tail * phi, tail * maxwell});
      if (!d.bin_error) continue;
      const double e = d.bin_error(k, lo, hi);
      t.rows.back().push_back(e), t.rows.back().push_back(2.0 / std::abs(h.c[k]) * (phi / maxwell) * e / std::abs(delta));
    }
  }
  return t;
}

Table time_table(const model::Scene& s, const std::vector<Sample>& samples) {
  const auto& o = s.observables;
  const std::size_t N = s.mixture.size();
  Table t;
  t.columns = {"t", "species"};
  if (o.rescaled_time) t.columns.push_back("t_s");
  if (o.temperatures) t.columns.push_back("T");
  if (o.msd) t.columns.push_back("msd");
  if (o.msd_ratio) t.columns.push_back("msd_ratio");
  if (o.d_ratio) t.columns.push_back("D_ratio");
  if (o.gamma) t.columns.push_back("gamma");
  if (o.tamsd) t.columns.push_back("lag"), t.columns.push_back("tamsd");
  const bool total_row = N > 1 && (o.temperatures || o.msd || o.gamma);
  for (std::size_t j = 0; j < s.times.size(); ++j) {
    const Sample& x = samples[j];
    for (std::size_t k = total_row ? 0 : 1; k <= N; ++k) {
      std::vector<double> row = {s.times[j], static_cast<double>(k)};
      const bool all = k == 0;  // species 0: ⟨T⟩ and the total MSD (v1 Eq. 16)
      if (o.rescaled_time) row.push_back(x.t_s);
      if (o.temperatures) row.push_back(all ? s.mixture.mean_temperature(x.T) : x.T[k - 1]);
      if (o.msd) row.push_back(all ? msd_total(s.mixture, x.msd) : x.msd[k - 1]);
      if (o.msd_ratio) row.push_back(all ? nan : x.msd[k - 1] / x.msd[0]);
      if (o.d_ratio) row.push_back(all ? nan : x.D_ratio[k - 1]);
      if (o.gamma) row.push_back(all ? x.T[0] / x.T[1] : nan);
      if (o.tamsd) row.push_back(s.times[j]), row.push_back(all ? nan : x.tamsd[k - 1]);
      t.rows.push_back(std::move(row));
    }
  }
  return t;
}

// Tracer limit in the level's closure (tracer_form.hpp): the MSD and the TAMSD from the same velocity correlation.
std::vector<Sample> tracer_samples(const model::Scene& s, const CollisionRates& rates, const TheoryLevel& level) {
  const double t_end = std::max(s.times.back(), s.observables.tamsd ? s.observables.tamsd_measurement_time : 0.0);
  const std::unique_ptr<TracerForm> form = level.tracer_form(rates, tracer_start_theta(s.initial, rates), t_end);
  std::vector<Sample> out;
  for (double t : s.times) {
    Sample x;
    const std::array<double, 2> T = form->temperatures(t);
    x.T = {T[0], T[1]};
    x.t_s = form->reduced_time(t);
    for (std::size_t k = 0; k < 2; ++k) {
      x.msd.push_back(form->msd(k, t));
      x.D_ratio.push_back(k == 0 ? 1.0 : form->D_ratio(t));
      if (s.observables.tamsd) x.tamsd.push_back(form->tamsd(k, s.observables.tamsd_measurement_time, t));
    }
    out.push_back(std::move(x));
  }
  return out;
}

std::vector<Sample> history_samples(const model::Scene& s, const CollisionRates& rates, const TheoryLevel& level, SolverStats& stats,
                                    std::shared_ptr<GalerkinPairTables> tables) {
  const auto& o = s.observables;
  const MsdMethod method = level.msd_method(s);
  TemperatureOptions opt;
  opt.rtol = s.theory.rtol;
  opt.t_first = s.times.front();
  const bool msd = o.needs_msd();
  opt.reduced_time = o.rescaled_time || (msd && method == MsdMethod::eq17);
  opt.diffusion_integral = msd && method == MsdMethod::longtime;
  opt.vacf = msd && method == MsdMethod::vacf;
  opt.galerkin_tables = std::move(tables);
  level.configure(opt, rates);
  const std::vector<double> T0 = level.initial_temperatures(s.initial, rates, opt);
  const TemperatureHistory h(rates, T0, s.times.back(), opt);
  stats = h.stats();
  const bool settled = o.tamsd || (msd && method == MsdMethod::closed);
  const SettledDiffusion d0 = settled ? level.diffusion_at(rates, T0) : SettledDiffusion{};
  const std::size_t N = rates.size();
  std::vector<Sample> out;
  const Eq17Msd eq17(h);
  for (double t : s.times) {
    Sample x;
    x.T.resize(N);
    h.temperatures(t, x.T.data());
    if (o.rescaled_time) x.t_s = h.reduced_time(t, 0);
    for (std::size_t k = 0; k < N; ++k) {
      if (msd) {
        switch (method) {
          case MsdMethod::eq17: x.msd.push_back(eq17(k, t)); break;
          case MsdMethod::vacf: x.msd.push_back(h.msd_vacf(t, k)); break;
          case MsdMethod::longtime: x.msd.push_back(6.0 * h.diffusion_integral(t, k)); break;
          case MsdMethod::closed: x.msd.push_back(msd_increment(d0.memory_of(k), d0.tau0, 0.0, t)); break;
        }
      }
      if (o.tamsd) x.tamsd.push_back(tamsd(d0.memory_of(k), d0.tau0, o.tamsd_measurement_time, t));
    }
    if (o.d_ratio) x.D_ratio = level.diffusion_at(rates, x.T).D_ratio;  // D_k(t)/D_1(t)
    out.push_back(std::move(x));
  }
  return out;
}

}  // namespace

double scene_time_unit(const model::Scene& s) {
  if (!s.time_unit_mg) return 1.0;
  const CollisionRates rates = scene_rates(s, s.mixture, s.restitution);
  return mg_time_unit(s.mixture, scene_contact_values(s),
                      initial_temperatures(s.initial, rates)[0]);
}

void rescale_time_columns(model::Table& table, double factor) {
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::string& name = table.columns[c];
    if (name == "t" || name == "lag" || name == "t_s" || name == "t_s_err" || name == "t_s_paper")
      for (auto& row : table.rows) row[c] *= factor;
  }
}

namespace {

// The scene's choice of χ_ij (Enskog or dilute) for a mixture of it (a sweep point's may differ).
std::vector<std::vector<double>> contact_values_of(const model::Scene& s, const model::Mixture& mix) {
  return s.enskog ? model::enskog_contact_values(mix) : model::dilute_contact_values(mix.size());
}

}  // namespace

std::vector<std::vector<double>> scene_contact_values(const model::Scene& s) { return contact_values_of(s, s.mixture); }

CollisionRates scene_rates(const model::Scene& s, const model::Mixture& mix, const model::Restitution& law) {
  return CollisionRates(mix, law, contact_values_of(s, mix), moment_method(s.theory.moments));
}

namespace {

// Every curve of a scene at one level, in natural time units. tables: the Galerkin pair tables shared with the scene's
// other levels (null: none shared).
Table level_table(const model::Scene& s, const TheoryLevel& level, SolverStats& stats, std::shared_ptr<GalerkinPairTables> tables = nullptr) {
  if (s.theory.sweep) return sweep_table(s, level);
  if (s.observables.distribution_settled) return distribution_table(s, level);
  const CollisionRates rates = scene_rates(s, s.mixture, s.restitution);
  return time_table(s, s.theory.tracer ? tracer_samples(s, rates, level) : history_samples(s, rates, level, stats, std::move(tables)));
}

// Appends the value columns of a lower level's table (same rows) as `<column>_<suffix>`.
void append_level_columns(Table& t, const Table& lower, const std::string& suffix) {
  for (std::size_t c = 1; c < lower.columns.size(); ++c) {
    const std::string& name = lower.columns[c];
    if (name == "species" || name == "lag" || name.ends_with("_maxwell")) continue;
    t.columns.push_back(name + "_" + suffix);
    for (std::size_t r = 0; r < t.rows.size(); ++r) t.rows[r].push_back(lower.rows[r][c]);
  }
}

bool corrected_from(const model::Scene& s, const std::string& lower) {
  return std::any_of(s.compare.begin(), s.compare.end(), [&](const model::CompareQuantity& q) {
    return std::find(q.correction_from.begin(), q.correction_from.end(), lower) != q.correction_from.end();
  });
}

// The scene with its times in natural units (MG time unit: compute in natural units, report t, lag and
// t_s in units of t0).
model::Scene in_natural_units(const model::Scene& scene, double unit) {
  model::Scene scaled = scene;
  for (double& t : scaled.times) t *= unit;
  scaled.observables.tamsd_measurement_time *= unit;
  return scaled;
}

}  // namespace

model::Scene load_scene(const std::string& path) { return model::load_scene(path, level_rules()); }
model::Scene load_scene_text(const std::string& text, const std::string& path) { return model::load_scene_text(text, path, level_rules()); }

bool theory_uses_rtol(const model::Scene& s) {
  if (s.theory.sweep) {
    // A D-ratio sweep's increments are histories in time (a sweep point is the scene without its sweep), unless its
    // level gives them in closed form from the settled memory (kinetic-converged-hcs).
    model::Scene point = s;
    point.theory.sweep.reset();
    return s.observables.d_ratio && make_theory_level(s.theory.level)->msd_method(point) != MsdMethod::closed;
  }
  return !s.observables.distribution_settled;
}

TheoryResult run_level(const model::Scene& scene, const std::string& level) {
  const auto start = std::chrono::steady_clock::now();
  TheoryResult r;
  const double unit = scene_time_unit(scene);
  r.table = level_table(in_natural_units(scene, unit), *make_theory_level(level), r.stats);
  if (unit != 1.0) rescale_time_columns(r.table, 1.0 / unit);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

TheoryResult run_theory(const model::Scene& scene, std::shared_ptr<GalerkinPairTables> tables) {
  if (scene.theory.level_is_auto()) return run_theory(with_level_chosen(scene), tables);
  const auto start = std::chrono::steady_clock::now();
  TheoryResult r;
  const double unit = scene_time_unit(scene);
  const model::Scene scaled = in_natural_units(scene, unit);
  const model::Scene& s = scaled;
  const LevelCatalogue& catalogue = level_catalogue();
  const LevelDescriptor& judged = catalogue.find(s.theory.level);
  const auto level = judged.make();
  // The judged level and a companion that solve the same Galerkin problem build its pair tables once.
  if (!tables) tables = std::make_shared<GalerkinPairTables>();
  r.table = level_table(s, *level, r.stats, tables);
  for (const auto& d : catalogue.levels())  // the papers' curves beside the judged level's
    if (d->reported_beside_others && d.get() != &judged) {
      SolverStats paper_stats;
      append_level_columns(r.table, level_table(s, *d->make(), paper_stats), d->name);
    }
  // The companions a model error is measured from, in the catalogue's order of corrections.
  for (const CorrectionMeaning& correction : catalogue.corrections()) {
    const LevelCompanion* c = judged.companion(correction.name);
    if (c == nullptr || !corrected_from(s, correction.name)) continue;
    const LevelDescriptor& companion = catalogue.find(c->level);
    if (companion.reported_beside_others) continue;  // its columns are there already
    SolverStats companion_stats;
    append_level_columns(r.table, level_table(s, *companion.make(), companion_stats, tables), correction.name);
  }
  if (unit != 1.0) rescale_time_columns(r.table, 1.0 / unit);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace granmix::theory
