#include "scene_compare.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dsmc/scene_dsmc.hpp"
#include "frozen_model_errors.hpp"
#include "gnuplot_figure.hpp"
#include "html_report.hpp"
#include "provenance.hpp"
#include "model/sha256.hpp"
#include "theory/grid/galerkin_decay.hpp"
#include "theory/scene_theory.hpp"
#include "interrupts.hpp"
#include "model/errors.hpp"
#include "scene_folder.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

namespace {

// Largest relative difference between two theory tables of the same shape (value columns only).
double max_relative_difference(const model::Table& a, const model::Table& b) {
  double worst = 0.0;
  for (std::size_t r = 0; r < std::min(a.rows.size(), b.rows.size()); ++r)
    for (std::size_t c = 0; c < a.columns.size(); ++c) {
      if (c == 0 || a.columns[c] == "species") continue;  // the location: t, v* or the swept value
      const double x = a.rows[r][c], y = b.rows[r][c];
      if (std::isfinite(x) && std::isfinite(y) && x != 0.0) worst = std::max(worst, std::abs(y / x - 1.0));
    }
  return worst;
}

}  // namespace

SceneEvaluation evaluate_scene(const model::Scene& s, const dsmc::RunOptions& opt) {
  SceneEvaluation e;
  SceneOutcome& o = e.outcome;
  o.scene = s.name;
  const auto tables = std::make_shared<theory::GalerkinPairTables>();  // the converged levels' pair tables, built once
  e.theory = theory::run_theory(s, tables);
  o.theory_seconds = e.theory.seconds;
  if (theory::theory_uses_rtol(s)) {  // error estimate: the same scene at 100× tighter tolerance (speed against error: docs/performance.md), on the same tables
    model::Scene tight = s;
    tight.theory.rtol = std::max(1e-14, s.theory.rtol / 100.0);
    o.theory_error = max_relative_difference(e.theory.table, theory::run_theory(tight, tables).table);
  }
  if (s.dsmc.present) {
    e.dsmc = dsmc::run_scene_dsmc(s, opt);
    o.dsmc_seconds = e.dsmc.result.seconds, o.collisions = double(e.dsmc.result.accepted);
    o.collisions_per_second = e.dsmc.result.collisions_per_second(), o.acceptance = e.dsmc.result.acceptance();
    o.particles = e.dsmc.result.particles, o.replicas = e.dsmc.result.replicas;
  }
  o.compared = !s.compare.empty() && s.dsmc.present;
  o.pass = true;
  if (o.compared) {
    const std::optional<FrozenModelErrors> frozen = load_frozen_model_errors(s);  // compare/scenes/: the reviewed bounds
    e.deviations = deviations(e.theory.table, e.dsmc.table, s.compare, frozen ? &*frozen : nullptr);
    o.quantities = summarise(e.deviations, s.compare);
    for (auto& q : o.quantities) {
      o.pass = o.pass && q.pass();
      if (!q.not_judged.empty()) q.max_z = NAN;
    }
    // docs/judging.md §6: with R replicas z is Student's t with R − 1 degrees of freedom; below 8 a |z| = 4 bound is
    // exceeded by chance in 3% of points and more, and a single replica has no error bar at all.
    if (o.replicas == 1)
      o.warnings.push_back("1 replica: no error bar, no z: every compared quantity is not judged (and does not pass); "
                           "z needs >= " + std::to_string(replicas_for_z) + " replicas to mean anything (docs/judging.md §6)");
    else if (o.replicas < replicas_for_z)
      o.warnings.push_back(std::to_string(o.replicas) + " replicas: z needs >= " + std::to_string(replicas_for_z) +
                           " replicas to mean anything (docs/judging.md §6); the verdicts below are weak");
  }
  return e;
}

nlohmann::ordered_json report_json(const model::Scene& s, const SceneOutcome& o, std::uint64_t seed, const std::string& fidelity) {
  nlohmann::ordered_json j;
  j["scene"] = s.name;
  j["source"] = s.source;
  j["title"] = s.title;
  j["level"] = s.theory.level;
  if (!s.theory.level_choice.empty()) j["level_choice"] = s.theory.level_choice;
  j["pass"] = o.pass;
  j["quantities"] = nlohmann::ordered_json::object();
  for (const auto& q : o.quantities) {
    j["quantities"][label(q.spec)] = {{"max_rel", q.max_rel},
                                    {"max_z", q.max_z},
                                    {"max_model_error", q.max_model_error},
                                    {"tolerance", tolerance_json(q.spec)},
                                    {"points", q.points},
                                    {"judged", q.judged},
                                    {"failed", q.failed},
                                    {"unresolved", q.unresolved},
                                    {"why", q.spec.why}};
    if (!q.not_judged.empty()) j["quantities"][label(q.spec)]["not_judged"] = q.not_judged;
    if (std::isfinite(q.max_paper_rel)) j["quantities"][label(q.spec)]["paper_max_rel"] = q.max_paper_rel;
  }
  j["theory_seconds"] = o.theory_seconds;
  j["theory_error"] = o.theory_error;
  j["dsmc_seconds"] = o.dsmc_seconds;
  j["collisions"] = o.collisions;
  j["collisions_per_second"] = o.collisions_per_second;
  j["acceptance"] = o.acceptance;
  j["particles"] = o.particles;
  j["replicas"] = o.replicas;
  j["seed"] = seed;
  j["fidelity"] = fidelity;
  j["figure"] = o.figure;
  j["warnings"] = o.warnings;
  return j;
}

void require_dsmc_for_compare(const model::Scene& s) {
  if (!s.compare.empty() && !s.dsmc.present)
    throw InputError(s.file + ": compare: judging needs a [dsmc] table (allowed: [dsmc] with quick = { particles = N, replicas = R })");
}

SceneOutcome compare_scene(const model::Scene& s, const std::filesystem::path& out, const dsmc::RunOptions& opt) {
  const std::string& fidelity = opt.fidelity;
  const std::uint64_t seed = opt.seed;
  SceneOutcome o;
  require_dsmc_for_compare(s);
  // theory.tsv and dsmc.tsv of one scene file only: a folder of another's outputs is moved aside first.
  std::vector<std::string> before;
  if (auto moved = set_aside_other_scene(out, s.name, model::sha256_hex(s.text))) before.push_back(*moved);
  for (const std::string& n : dsmc::run_notes(s, fidelity)) before.push_back(n);
  const std::filesystem::path tmp = out / ("." + s.name + ".tmp-" + std::to_string(getpid()));
  {
    interrupts::WriteGuard g;  // an interrupt removes the staging folder, never leaves it half made
    std::filesystem::create_directories(out);
    std::filesystem::remove_all(tmp);
    std::filesystem::create_directories(tmp);
    interrupts::set_staging(tmp);
  }
  try {
    const SceneEvaluation e = evaluate_scene(s, opt);
    o = e.outcome;
    o.warnings.insert(o.warnings.begin(), before.begin(), before.end());
    Provenance p;
    p.scene_name = s.name, p.scene_file = s.file, p.scene_sha256 = model::sha256_hex(s.text), p.command = command_line();
    p.level_choice = s.theory.level_choice;
    write_atomically(tmp / "theory.tsv", format_tsv(provenance_header(p), e.theory.table));
    if (s.dsmc.present) {
      Provenance pd = p;
      pd.seed = std::to_string(seed) + " (replica r uses stream (seed, r))", pd.fidelity = fidelity;
      write_atomically(tmp / "dsmc.tsv", format_tsv(provenance_header(pd), e.dsmc.table));
      if (!e.dsmc.distribution.rows.empty()) write_atomically(tmp / "distribution.tsv", format_tsv(provenance_header(pd), e.dsmc.distribution));
    }
    if (o.compared) {
      Provenance pd = p;
      pd.seed = std::to_string(seed), pd.fidelity = fidelity;
      write_atomically(tmp / "deviations.tsv", format_deviations(provenance_header(pd), e.theory.table.columns.front(), e.deviations));
    }
    interrupts::WriteGuard g;  // figure, report and rename: finished together or not at all
    o.figure = write_figure(tmp, s, e.theory.table, s.dsmc.present ? &e.dsmc.table : nullptr, e.deviations).message;
    write_atomically(tmp / "report.json", report_json(s, o, seed, fidelity).dump(2) + "\n");
    write_scene_html_report(tmp);  // the scene's own page (index.html), from its report.json
    std::filesystem::remove_all(out / s.name);
    std::filesystem::rename(tmp, out / s.name);  // the scene folder appears complete or not at all
    interrupts::set_staging({});
  } catch (...) {
    interrupts::WriteGuard g;
    interrupts::set_staging({});
    std::filesystem::remove_all(tmp);
    throw;
  }
  return o;
}

}  // namespace granmix::compare
