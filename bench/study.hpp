#pragma once
// Speed-against-error studies of `granmix bench STUDY` (docs/architecture.md §3, docs/performance.md). A study computes a
// table (numbers only, long form with a `series` column) and says how to plot it; compare/
// command_bench.cpp writes the TSV with provenance, the gnuplot figure and the JSON lines.
// Speed is measured here, never asserted in tests.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "model/table.hpp"

namespace granmix::bench {

struct StudyFigure {
  std::string x, y, xlabel, ylabel;
  bool logx = false, logy = false;
  std::vector<std::string> series;  // label of series 0, 1, …
  std::vector<std::string> extra;   // further gnuplot plot terms (guide lines)
};

struct StudyResult {
  std::string name;
  model::Table table;   // first columns: series, then the study's own
  StudyFigure figure;
  std::vector<std::string> json;     // one JSON object per line (--json)
  std::vector<std::string> summary;  // lines for the terminal: targets and what was measured
  std::vector<std::pair<std::string, model::Table>> tables;  // further tables: DIR/bench/<study>/<name>.tsv
};

// `granmix bench selectors` on chosen cases only (docs/performance.md, "Timing one case"): each set field narrows the
// cases or overrides one of their settings.
struct CaseFilter {
  std::string system;     // a system ("exp691", "binary", "powerlaw-100") or its family ("powerlaw"); empty: any
  std::string selector;   // a pair selector (dsmc::to_string of the method: "lowrank", "direct", "bird", …); empty: any
  double particles = 0;   // > 0: the cases whose particle count lies within a factor 1.5 of it
  double t_end = 0;       // > 0: every case runs to this time instead of its own
  double eps = -1;        // in [0, 1]: every case with this restitution instead of its system's
  bool any() const { return !system.empty() || !selector.empty() || particles > 0 || t_end > 0 || eps >= 0; }
};

struct StudyOptions {
  int repeats = 3;     // medians of this many runs (the machine is noisy)
  bool quick = false;  // smaller systems: a smoke run for tests and CI
  std::uint64_t seed = 1;
  std::function<void(const std::string&)> progress;  // one line per finished case
  std::filesystem::path units_file = "out/units.tsv";  // schedule: measured units of a validate run
  std::filesystem::path scenes_folder;                 // schedule: the scenes whose paper fidelity is simulated
  CaseFilter filter;                                   // selectors: the cases to run
};

StudyResult selectors_study(const StudyOptions& o);
StudyResult theory_study(const StudyOptions& o);
StudyResult dsmc_error_study(const StudyOptions& o);
StudyResult methods_study(const StudyOptions& o);
StudyResult gaps_study(const StudyOptions& o);  // causes of the theory–DSMC gaps
StudyResult schedule_study(const StudyOptions& o);  // makespan on 1–256 ranks from measured units
StudyResult checkpoint_study(const StudyOptions& o);  // snapshot bytes and seconds

// Study names in the order `granmix bench` runs them.
const std::vector<std::string>& study_names();
StudyResult run_study(const std::string& name, const StudyOptions& o);

}  // namespace granmix::bench
