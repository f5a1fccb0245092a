// `granmix bench schedule`: the makespan of the validation on 1 to 256 ranks, simulated
// from measured unit costs. The input is units.tsv of a `granmix validate` run (every DSMC unit — one
// replica — with its estimated and actual collisions and CPU seconds). Quick fidelity is simulated
// from the measured seconds themselves; paper fidelity (`make figures`) from them scaled per ensemble
// by the ratio of estimated collisions (paper/quick: the particle ratio, the times are the same),
// since running `make figures` to measure it costs what the simulation is meant to predict.
// The simulation is the scheduler's own policy: units in the order of their estimated collisions,
// each to the first free slot (rank × thread). The longest unit bounds any makespan: one replica is
// one Markov chain and is never split.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <queue>
#include <sstream>

#include "dsmc/scene_dsmc.hpp"
#include "dsmc/unit_cost.hpp"
#include "model/errors.hpp"
#include "study.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::bench {

namespace {

struct MeasuredUnit {
  std::string key;
  double estimated = 0.0, collisions = 0.0, seconds = 0.0;
};

std::vector<MeasuredUnit> read_units(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in)
    throw InputError("bench schedule: no " + file.string() +
                     " (allowed: the units.tsv of a `granmix validate` run; `make validate` writes out/units.tsv)");
  std::vector<MeasuredUnit> units;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#' || line.rfind("unit\t", 0) == 0) continue;
    std::istringstream f(line);
    MeasuredUnit u;
    std::size_t replica = 0;
    int rank = 0;
    if (!(f >> u.key >> replica >> u.estimated >> u.collisions >> u.seconds >> rank) || u.seconds < 0.0)
      throw InputError(file.string() + ":" + std::to_string(n) + ": not a units.tsv row (unit, replica, estimated_collisions, "
                       "collisions, seconds, rank)");
    units.push_back(u);
  }
  if (units.empty()) throw InputError(file.string() + ": no units (allowed: the units.tsv of a granmix validate run)");
  return units;
}

// Makespan of list scheduling: each cost, in the given order, to the slot that frees first.
double makespan(const std::vector<double>& costs, std::size_t slots) {
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (std::size_t s = 0; s < slots; ++s) free_at.push(0.0);
  double end = 0.0;
  for (double c : costs) {
    const double t = free_at.top() + c;
    free_at.pop();
    free_at.push(t);
    end = std::max(end, t);
  }
  return end;
}

struct Workload {
  std::string name;
  std::vector<std::pair<double, double>> units;  // (estimated collisions: the scheduler's order, seconds)
  std::string longest;                            // the ensemble of the longest unit
};

// Paper-fidelity units of every scene: per ensemble, the quick run's measured seconds per collision
// times the paper run's collisions (its estimate, corrected by the quick run's measured/estimated).
Workload paper_workload(const std::filesystem::path& scenes, const std::map<std::string, std::pair<double, double>>& measured) {
  Workload w{"paper (simulated from quick)", {}, {}};
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(scenes))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  double longest = 0.0;
  for (const auto& f : files) {
    const model::Scene s = theory::load_scene(f.string());
    dsmc::RunOptions quick, paper;
    paper.fidelity = "paper";
    const auto q = dsmc::plan_scene_dsmc(s, quick), p = dsmc::plan_scene_dsmc(s, paper);
    for (std::size_t i = 0; i < q.size() && i < p.size(); ++i) {
      const auto it = measured.find(q[i].unit_key);
      if (it == measured.end()) continue;  // not in the measured run (another scene folder or seed)
      const double ep = dsmc::estimated_collisions(p[i]);
      const auto [seconds_per_collision, measured_over_estimate] = it->second;
      const double seconds = seconds_per_collision * ep * measured_over_estimate;
      for (std::size_t r = 0; r < p[i].replicas; ++r) w.units.push_back({ep, seconds});
      if (seconds > longest) longest = seconds, w.longest = p[i].unit_key;
    }
  }
  return w;
}

}  // namespace

StudyResult schedule_study(const StudyOptions& o) {
  const std::vector<MeasuredUnit> units = read_units(o.units_file);
  // Per ensemble (unit key): seconds per collision and measured/estimated collisions.
  std::map<std::string, std::pair<double, double>> measured;
  {
    std::map<std::string, std::array<double, 3>> sum;  // seconds, collisions, estimated
    for (const auto& u : units) sum[u.key][0] += u.seconds, sum[u.key][1] += u.collisions, sum[u.key][2] += u.estimated;
    for (const auto& [k, s] : sum) measured[k] = {s[1] > 0 ? s[0] / s[1] : 0.0, s[2] > 0 ? s[1] / s[2] : 1.0};
  }
  Workload quick{"quick (measured)", {}, {}};
  double longest = 0.0;
  for (const auto& u : units) {
    quick.units.push_back({u.estimated, u.seconds});
    if (u.seconds > longest) longest = u.seconds, quick.longest = u.key;
  }
  std::vector<Workload> loads = {quick, paper_workload(o.scenes_folder, measured)};

  StudyResult r;
  r.name = "schedule";
  r.table.columns = {"series", "slots", "makespan_s", "lower_bound_s", "efficiency", "total_cpu_s", "longest_unit_s"};
  r.figure = {"slots", "makespan_s", "slots (ranks x threads)", "makespan (s)", true, true, {}, {}};
  const std::vector<std::size_t> slot_counts = {1, 2, 4, 8, 16, 32, 64, 128, 256};
  for (std::size_t series = 0; series < loads.size(); ++series) {
    Workload& w = loads[series];
    r.figure.series.push_back(w.name);
    std::stable_sort(w.units.begin(), w.units.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<double> costs;
    double total = 0.0, top = 0.0;
    for (const auto& u : w.units) costs.push_back(u.second), total += u.second, top = std::max(top, u.second);
    for (std::size_t P : slot_counts) {
      const double m = makespan(costs, P), bound = std::max(total / double(P), top);
      r.table.rows.push_back({double(series), double(P), m, bound, total / (double(P) * m), total, top});
      r.json.push_back(fmt::format(R"({{"study": "schedule", "workload": "{}", "slots": {}, "makespan_s": {:.4g}, "lower_bound_s": {:.4g}, )"
                                   R"("efficiency": {:.3f}, "total_cpu_s": {:.4g}, "longest_unit_s": {:.4g}, "longest_unit": "{}"}})",
                                   w.name, P, m, bound, total / (double(P) * m), total, top, w.longest));
      if (P == 2 || P == 16 || P == 64 || P == 256)
        r.summary.push_back(fmt::format("{}: {} slots: makespan {:.1f} s (bound {:.1f} s, efficiency {:.2f})", w.name, P, m, bound,
                                        total / (double(P) * m)));
    }
    r.summary.push_back(fmt::format("{}: {} units, {:.1f} CPU s; longest unit {:.1f} s ({}) bounds every makespan — one replica is "
                                    "one Markov chain; more replicas of fewer particles, or a spatially decomposed DSMC, would split it",
                                    w.name, costs.size(), total, top, w.longest));
  }
  return r;
}

}  // namespace granmix::bench
