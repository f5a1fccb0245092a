#include "summary_table.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "confirmation.hpp"
#include "provenance.hpp"
#include "deviations.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

std::string summary_header() {
  return fmt::format("{:<24} {:<18} {:>9} {:>8} {:>20} {:<5} {:>9} {:>18} {:>9} {:>12}\n", "scene", "quantity", "max rel", "max z", "tolerance",
                     "pass", "paper rel", "theory s (error)", "DSMC s", "collisions/s");
}

std::string summary_lines(const SceneOutcome& o) {
  const std::string theory = fmt::format("{:.3f} ({:.0e})", o.theory_seconds, o.theory_error);
  const std::string cps = o.collisions_per_second > 0 ? fmt::format("{:.3g}", o.collisions_per_second) : "-";
  const std::string dsmc = o.dsmc_seconds > 0 ? fmt::format("{:.2f}", o.dsmc_seconds) : "-";
  if (o.quantities.empty()) {
    std::string s = fmt::format("{:<24} {:<18} {:>9} {:>8} {:>20} {:<5} {:>9} {:>18} {:>9} {:>12}\n", o.scene, "-", "-", "-", "theory only",
                                o.pass ? "yes" : "NO", "-", theory, dsmc, cps);
    for (const auto& w : o.warnings) s += fmt::format("{:<24} warning: {}\n", "", w);
    return s;
  }
  std::string s;
  for (const auto& q : o.quantities)
    s += fmt::format("{:<24} {:<18} {:>9.4f} {:>8.2f} {:>20} {:<5} {:>9.4f} {:>18} {:>9} {:>12}\n", o.scene, label(q.spec), q.max_rel, q.max_z,
                     tolerance_text(q.spec), q.pass() ? "yes" : "NO", q.max_paper_rel, theory, dsmc, cps);
  for (const auto& q : o.quantities)
    if (q.unresolved > 0)  // failed whatever DSMC says: the theory's own bound is wider than the level resolves
      s += fmt::format("{:<24} {}: {} of {} judged points unresolved: model error up to {:.4g}, above model_error_max = {:g}\n", "", label(q.spec),
                       q.unresolved, q.judged, q.max_model_error, q.spec.model_error_max);
  for (const auto& q : o.quantities)
    if (!q.not_judged.empty()) s += fmt::format("{:<24} {}: not judged: {}\n", "", label(q.spec), q.not_judged);
  for (const auto& w : o.warnings) s += fmt::format("{:<24} warning: {}\n", "", w);
  return s;
}

void write_summary(const std::filesystem::path& out, const std::vector<SceneOutcome>& all, const std::vector<std::string>& errors,
                   const scheduler::GatheredReplicas& run, const Confirmation* confirmation) {
  std::string tsv = "# granmix validate summary (" + utc_now_iso8601() + ")\n";
  tsv += "scene\tquantity\tmax_rel\tmax_z\trelative_tol\tz_tol\tpass\ttheory_seconds\ttheory_error\tdsmc_seconds\tcollisions_per_second\tabsolute_tol\t"
         "paper_max_rel\tunresolved\tverdict\n";
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& o : all) {
    nlohmann::ordered_json scene = {{"scene", o.scene}, {"pass", o.pass}, {"theory_seconds", o.theory_seconds},
                                    {"theory_error", o.theory_error}, {"dsmc_seconds", o.dsmc_seconds},
                                    {"collisions_per_second", o.collisions_per_second}, {"quantities", nlohmann::ordered_json::object()},
                                    {"warnings", o.warnings}};
    if (o.quantities.empty())
      tsv += fmt::format("{}\t-\tnan\tnan\tnan\tnan\t{}\t{}\t{}\t{}\t{}\tnan\tnan\t0\t{}\n", o.scene, int(o.pass), o.theory_seconds,
                         o.theory_error, o.dsmc_seconds, o.collisions_per_second, o.pass ? "pass" : "FAIL");
    for (const auto& q : o.quantities) {
      const std::string v = verdict(o.scene, q, confirmation);
      tsv += fmt::format("{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\n", o.scene, label(q.spec), q.max_rel, q.max_z,
                         q.spec.relative, q.spec.z, int(q.pass()), o.theory_seconds, o.theory_error, o.dsmc_seconds, o.collisions_per_second,
                         q.spec.absolute, q.max_paper_rel, q.unresolved, v);
      scene["quantities"][label(q.spec)] = {{"max_rel", q.max_rel}, {"max_z", q.max_z}, {"tolerance", tolerance_json(q.spec)},
                                          {"pass", q.pass()}, {"unresolved", q.unresolved}, {"verdict", v}};
      if (std::isfinite(q.max_paper_rel)) scene["quantities"][label(q.spec)]["paper_max_rel"] = q.max_paper_rel;
    }
    j.push_back(scene);
  }
  nlohmann::ordered_json confirmed = nullptr;  // no confirmation ran
  if (confirmation && (!confirmation->scenes.empty() || !confirmation->errors.empty())) {
    confirmed = {{"seed", confirmation->seed}, {"replica_factor", confirmation->factor}, {"folder", "confirmation"},
                 {"scenes", nlohmann::ordered_json::array()}, {"errors", confirmation->errors}};
    for (const auto& o : confirmation->scenes) confirmed["scenes"].push_back(o.scene);
  }
  nlohmann::ordered_json summary = {{"pass", passes(all, errors, confirmation)},
                                    {"scenes", j},
                                    {"confirmation", confirmed},
                                    {"errors", errors},
                                    {"ranks", run.ranks},
                                    {"threads", run.threads},
                                    {"cpu_seconds", run.cpu_seconds},
                                    {"dsmc_wall_seconds", run.wall_seconds},
                                    {"dsmc_units", run.units.size()}};
  std::string units = "# granmix validate: DSMC units, longest estimate first (" + utc_now_iso8601() + ")\n";
  units += "unit\treplica\testimated_collisions\tcollisions\tseconds\trank\n";
  for (const auto& u : run.units)
    units += fmt::format("{}\t{}\t{:.6g}\t{}\t{:.6g}\t{}\n", u.key, u.replica, u.estimated_collisions, u.collisions, u.seconds, u.rank);
  write_atomically(out / "units.tsv", units);
  write_atomically(out / "summary.tsv", tsv);
  write_atomically(out / "summary.json", summary.dump(2) + "\n");
}

}  // namespace granmix::compare
