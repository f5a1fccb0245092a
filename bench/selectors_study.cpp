// Study `selectors`: accepted collisions per second, trial pairs per second and acceptance
// of every pair selector on the systems of bench/systems.hpp, one replica on one thread, the median
// of `repeats` runs. The reference systems (v2 Table 1: 691 species, t = 10; the binary 1:100) run to
// the paper's t = 10; the others to a time a pilot run says holds about 1e6 collisions (Bird and the
// time-step scheme a tenth of that: their cost per collision is what is measured, not the physics).
// Where the hardware counters exist (bench/cycle_counter.hpp) each case also gets cycles and
// instructions per trial (of the whole run_ensemble call: set-up included, a few % at 1e5 particles).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "cycle_counter.hpp"
#include "dsmc/particles.hpp"
#include "model/errors.hpp"
#include "study.hpp"
#include "systems.hpp"

namespace granmix::bench {

namespace {

struct Case {
  BenchSystem system;
  dsmc::Method method;
  double t_end;  // 0: from a pilot run
  std::string family;
};

double pilot_time(const BenchSystem& b, double collisions, std::uint64_t seed) {
  dsmc::DsmcSetup s = b.setup;
  s.method = dsmc::Method::automatic, s.replicas = 1, s.threads = 1, s.seed = seed;
  double t = 1e-3;
  for (;;) {
    s.times = {t};
    const dsmc::DsmcResult r = dsmc::run_ensemble(s);
    if (r.accepted >= 2000 || t > 1e6) return t * collisions / double(std::max<std::uint64_t>(r.accepted, 1));
    t *= 10.0;
  }
}

std::size_t particles_of(const dsmc::DsmcSetup& s) {
  std::size_t n = 0;
  for (std::size_t c : s.counts) n += c;
  return n;
}

// The cases the filter keeps, with its overrides applied; none kept is an input error naming what exists.
std::vector<Case> filtered(std::vector<Case> cases, const CaseFilter& f) {
  if (!f.any()) return cases;
  std::vector<std::string> systems, selectors;
  auto note = [](std::vector<std::string>& v, const std::string& s) {
    if (std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
  };
  std::vector<Case> kept;
  for (Case& c : cases) {
    note(systems, c.system.name), note(selectors, dsmc::to_string(c.method));
    const double n = double(particles_of(c.system.setup));
    if (!f.system.empty() && f.system != c.system.name && f.system != c.family) continue;
    if (!f.selector.empty() && f.selector != dsmc::to_string(c.method)) continue;
    if (f.particles > 0 && (n < f.particles / 1.5 || n > f.particles * 1.5)) continue;
    if (f.t_end > 0) c.t_end = f.t_end;
    if (f.eps >= 0) c.system.setup.law = model::Restitution::constant(c.system.setup.mixture.size(), f.eps);
    kept.push_back(std::move(c));
  }
  if (kept.empty()) {
    auto join = [](const std::vector<std::string>& v) {
      std::string s;
      for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
      return s;
    };
    throw InputError(fmt::format("bench selectors: no case matches --system '{}' --selector '{}' --particles {:g} (allowed: systems {}; their "
                                 "families one, binary, ternary, exp691, powerlaw, exponential; selectors {}; particles 1e4 with --quick, "
                                 "else 1e5 and 1e6)",
                                 f.system, f.selector, f.particles, join(systems), join(selectors)));
  }
  return kept;
}

}  // namespace

StudyResult selectors_study(const StudyOptions& o) {
  using dsmc::Method;
  const std::size_t N = o.quick ? 10000 : 100000;
  const double budget = o.quick ? 1e5 : 1e6;
  std::vector<Case> cases;
  auto add = [&](const BenchSystem& b, std::vector<Method> methods, double t_end, const std::string& family) {
    for (Method m : methods) cases.push_back({b, m, t_end, family});
  };
  add(one_species(N), {Method::direct, Method::lowrank, Method::bird, Method::timestep}, 0.0, "one");
  add(binary_1_100(N), {Method::direct, Method::lowrank, Method::bird, Method::bird_global, Method::timestep}, 10.0, "binary");
  add(ternary(N), {Method::direct, Method::lowrank, Method::bird}, 0.0, "ternary");
  add(exponential_691(o.quick ? 99.9 : 999.0), {Method::lowrank, Method::bird, Method::bird_global}, 10.0, "exp691");
  for (const char* shape : {"powerlaw", "exponential"})
    for (std::size_t M : {10, 100, 1000, 10000}) {
      if (o.quick && M > 1000) continue;
      std::vector<Method> m = {Method::lowrank};
      if (M <= 10) m.push_back(Method::direct);
      if (M <= 1000) m.push_back(Method::bird);  // beyond, Bird's acceptance (~σ²/σ²_max) makes a run take minutes
      add(polydisperse(shape, M, N), m, 0.0, shape);
    }
  if (!o.quick) {  // 1e6 particles: the second reference point, and 1e5 species
    add(exponential_691(9990.0), {Method::lowrank}, 10.0, "exp691");
    add(exponential_691(9990.0), {Method::bird}, 10.0, "exp691");
    add(exponential_691(9990.0), {Method::bird_global}, 1.0, "exp691");  // t = 10 would take it ~15 min per run
    add(binary_1_100(10 * N), {Method::direct, Method::lowrank}, 0.0, "binary");
    for (const char* shape : {"powerlaw", "exponential"}) add(polydisperse(shape, 100000, 10 * N), {Method::lowrank}, 0.0, shape);
  }

  cases = filtered(std::move(cases), o.filter);

  StudyResult out;
  out.name = "selectors";
  out.table.columns = {"series",  "species",    "particles",        "collisions",      "trials",           "seconds",
                       "collisions_per_second", "trials_per_second", "acceptance", "ns_per_collision", "bytes_per_particle", "t_end",
                       "ns_per_trial"};
  CycleCounter counter;
  if (counter.available()) out.table.columns.insert(out.table.columns.end(), {"cycles_per_trial", "instructions_per_trial"});
  std::vector<std::string>& labels = out.figure.series;
  struct Measured {
    std::string method, system;
    std::size_t particles;
    double cps, ns;
  };
  std::vector<Measured> measured;
  for (const Case& c : cases) {
    dsmc::DsmcSetup s = c.system.setup;
    const std::size_t particles = particles_of(s);
    const bool slow = c.method == Method::bird || c.method == Method::bird_global || c.method == Method::timestep;
    const double t_end = c.t_end > 0.0 ? c.t_end : pilot_time(c.system, slow ? budget / 10.0 : budget, o.seed);
    s.method = c.method, s.times = {t_end}, s.replicas = 1, s.threads = 1, s.seed = o.seed;
    struct Run {
      dsmc::DsmcResult result;
      CycleCounter::Counts counts;
    };
    std::vector<Run> runs;
    for (int r = 0; r < std::max(1, o.repeats); ++r) {
      counter.start();
      dsmc::DsmcResult result = dsmc::run_ensemble(s);
      runs.push_back({std::move(result), counter.stop()});
    }
    std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.result.seconds < b.result.seconds; });
    const dsmc::DsmcResult& r = runs[runs.size() / 2].result;
    const CycleCounter::Counts& counts = runs[runs.size() / 2].counts;
    const std::string label = fmt::format("{} {} N={:.0e}", dsmc::to_string(c.method), c.family, double(particles));
    auto it = std::find(labels.begin(), labels.end(), label);
    if (it == labels.end()) it = labels.insert(labels.end(), label);
    const double series = double(it - labels.begin()), cps = r.collisions_per_second();
    const double tps = r.seconds > 0 ? double(r.trials) / r.seconds : 0.0;
    const double ns = r.accepted ? 1e9 * r.seconds / double(r.accepted) : 0.0;
    const double ns_trial = r.trials ? 1e9 * r.seconds / double(r.trials) : 0.0;
    const double bytes = double(dsmc::Particles::bytes_per_particle(false));
    // NaN where a counter call failed in this run (its columns exist because the counters opened).
    const double trials = double(std::max<std::uint64_t>(r.trials, 1)), nan = std::numeric_limits<double>::quiet_NaN();
    const double cycles = counts.valid ? double(counts.cycles) / trials : nan, instructions = counts.valid ? double(counts.instructions) / trials : nan;
    std::vector<double> row = {series, double(r.species), double(particles), double(r.accepted), double(r.trials), r.seconds, cps, tps,
                               r.acceptance(), ns, bytes, t_end, ns_trial};
    if (out.table.columns.size() > row.size()) row.insert(row.end(), {cycles, instructions});
    out.table.rows.push_back(row);
    const std::string counted =
        out.table.columns.size() > 13 && counts.valid
            ? fmt::format(", \"cycles_per_trial\": {:.1f}, \"instructions_per_trial\": {:.1f}", cycles, instructions)
            : "";
    out.json.push_back(fmt::format(
        "{{\"selector\": \"{}\", \"system\": \"{}\", \"species\": {}, \"particles\": {}, \"collisions\": {}, \"trials\": {}, "
        "\"seconds\": {:.6f}, \"collisions_per_second\": {:.1f}, \"acceptance\": {:.6g}, \"trials_per_second\": {:.1f}, "
        "\"ns_per_collision\": {:.2f}, \"bytes_per_particle\": {}, \"t_end\": {:.6g}, \"ns_per_trial\": {:.2f}{}}}",
        dsmc::to_string(c.method), c.system.name, r.species, particles, r.accepted, r.trials, r.seconds, cps, r.acceptance(), tps, ns,
        bytes, t_end, ns_trial, counted));
    measured.push_back({dsmc::to_string(c.method), c.system.name, particles, cps, ns});
    if (o.progress)
      o.progress(fmt::format("{:<11} {:<18} {:>7} species {:>8} particles: {:>10.4g} collisions/s, acceptance {:.3f}, {:.1f} ns/collision, "
                             "{:.1f} ns/trial{}",
                             dsmc::to_string(c.method), c.system.name, r.species, particles, cps, r.acceptance(), ns, ns_trial,
                             counts.valid ? fmt::format(", {:.0f} cycles/trial", cycles) : std::string()));
  }
  auto find = [&](const std::string& m, const std::string& sys, std::size_t minp, std::size_t maxp) -> const Measured* {
    for (const auto& x : measured)
      if (x.method == m && x.system == sys && x.particles >= minp && x.particles <= maxp) return &x;
    return nullptr;
  };
  // Targets; reference: the paper authors' code on this machine class (docs/performance.md).
  const Measured *lr5 = find("lowrank", "exp691", 50000, 200000), *lr6 = find("lowrank", "exp691", 500000, 2000000),
                 *bd5 = find("bird", "exp691", 50000, 200000), *bg5 = find("bird-global", "exp691", 50000, 200000),
                 *bin = find("direct", "binary", 50000, 200000);
  if (lr5) out.summary.push_back(fmt::format("691 species, 1e5 particles, low-rank: {:.3g} M collisions/s (target 4.7, reference 1.57)", lr5->cps / 1e6));
  if (lr6) out.summary.push_back(fmt::format("691 species, 1e6 particles, low-rank: {:.3g} M collisions/s (target 1.95, reference 0.65)", lr6->cps / 1e6));
  if (bd5) out.summary.push_back(fmt::format("691 species, 1e5 particles, Bird: {:.3g} M collisions/s (target 0.15, reference 0.153 DSMCup)", bd5->cps / 1e6));
  if (lr5 && bd5) out.summary.push_back(fmt::format("691 species, 1e5 particles: low-rank / Bird = {:.1f}", lr5->cps / bd5->cps));
  if (lr5 && bg5)
    out.summary.push_back(fmt::format("691 species, 1e5 particles: low-rank / Bird with one global bound = {:.1f} (bird-global {:.3g} M/s)",
                                      lr5->cps / bg5->cps, bg5->cps / 1e6));
  if (bin) out.summary.push_back(fmt::format("binary 1:100, 1e5 particles, direct: {:.3g} M collisions/s (target 5.9, reference 1.96)", bin->cps / 1e6));
  for (const char* shape : {"powerlaw", "exponential"}) {
    const Measured *a = find("lowrank", std::string(shape) + "-10", 0, ~std::size_t(0)), *b = find("lowrank", std::string(shape) + "-10000", 0, ~std::size_t(0));
    if (a && b)
      out.summary.push_back(fmt::format("low-rank cost per collision, {} M = 10 -> 1e4: x{:.2f} (log M grows x4)", shape, b->ns / a->ns));
  }
  out.figure = {"species", "collisions_per_second", "species M", "accepted collisions per second (one thread)", true, true, labels, {}};
  out.summary.push_back(fmt::format("memory: {} bytes per particle ({} with MSD displacements); targets 40 and 64",
                                    dsmc::Particles::bytes_per_particle(false), dsmc::Particles::bytes_per_particle(true)));
  return out;
}

}  // namespace granmix::bench
