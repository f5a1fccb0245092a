// granmix compare SCENE.toml [--out DIR] [--fidelity quick|paper] [--seed S] [--threads N]
// granmix validate [--fidelity quick|paper] [--out DIR] [--scenes DIR] [--seed S [--confirm N] | --seeds A-B] [--threads N] (also DIR/index.html)
// Both also [--checkpoint DIR | --restart DIR] [--checkpoint-every SECONDS] (checkpoint_options.hpp).
// (docs/architecture.md §3). Exit 0 if every compared quantity passes, 1 otherwise, 2 for bad input.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "checkpoint_options.hpp"
#include "frozen_model_errors.hpp"
#include "commands.hpp"
#include "interrupts.hpp"
#include "html_report.hpp"
#include "model/errors.hpp"
#include "scene_compare.hpp"
#include "scheduler.hpp"
#include "summary_table.hpp"
#include "calibration.hpp"
#include "confirmation.hpp"
#include "provenance.hpp"
#include "tsv_writer.hpp"
#include "theory/level_choice.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::compare {

namespace {

struct RunOptions {
  std::string out = "out", fidelity = "quick", scenes;
  std::uint64_t seed = 1;
  int threads = 0;
  std::size_t confirm = default_confirmation_factor;  // validate: a failing scene's replicas at its confirmation (0: none)
  CheckpointFlags checkpoint;
  std::shared_ptr<dsmc::Checkpointing> checkpointing;  // from the flags, once the scenes are known
};

void add_run_options(CLI::App* cmd, RunOptions& o) {
  cmd->add_option("--out", o.out, "output folder")->capture_default_str();
  cmd->add_option("--fidelity", o.fidelity, "quick or paper")->check(CLI::IsMember({"quick", "paper"}))->capture_default_str();
  cmd->add_option("--seed", o.seed, "master seed")->check(seed_range())->capture_default_str();
  cmd->add_option("--threads", o.threads, "threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
  add_checkpoint_flags(cmd, o.checkpoint);
}

dsmc::RunOptions run_options(const RunOptions& o) {
  dsmc::RunOptions r;
  r.fidelity = o.fidelity, r.seed = o.seed, r.threads = o.threads;
  r.checkpoint = o.checkpointing.get();
  return r;
}

}  // namespace

std::filesystem::path default_scene_folder() {
  if (std::filesystem::is_directory("compare/scenes")) return "compare/scenes";
  return std::filesystem::path(GRANMIX_SOURCE_DIR) / "compare" / "scenes";
}

std::function<int()> add_compare_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("compare", "theory and DSMC of a scene, deviations, report.json and the figure");
  auto o = std::make_shared<RunOptions>();
  auto scene = std::make_shared<std::string>();
  cmd->add_option("scene", *scene, "scene file (TOML); - reads it from standard input")->required();
  add_run_options(cmd, *o);
  return [o, scene]() {
    interrupts::install();
    interrupts::require_writable_folder(o->out);
    const model::Scene s = theory::with_level_chosen(theory::load_scene(*scene));
    if (!s.theory.level_choice.empty() && scheduler::root()) std::printf("level: %s\n", s.theory.level_choice.c_str()), std::fflush(stdout);
    require_dsmc_for_compare(s);
    load_frozen_model_errors(s);  // a scene of compare/scenes/ without its reviewed bounds is refused before the DSMC
    std::vector<dsmc::DsmcSetup> plan = dsmc::plan_scene_dsmc(s, run_options(*o));
    o->checkpointing = start_checkpointing(o->checkpoint, plan);
    const scheduler::GatheredReplicas replicas = scheduler::run_units(plan, o->threads);
    if (!scheduler::root()) return 0;  // rank 0 writes every file
    dsmc::RunOptions run = run_options(*o);
    run.source = &replicas;
    const SceneOutcome r = compare_scene(s, o->out, run);
    std::printf("%s%s", summary_header().c_str(), summary_lines(r).c_str());
    std::printf("-> %s/%s/ (index.html; %s)\n", o->out.c_str(), s.name.c_str(), r.figure.c_str());
    return r.pass ? 0 : 1;
  };
}

namespace {

std::vector<std::filesystem::path> scene_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

struct Validation {
  SeedRun run;
  scheduler::GatheredReplicas replicas;
  std::map<std::string, std::filesystem::path> file_of;  // scene name -> its file
};

// One validation of the scene `files` at `seed` into `out`, each with `replica_factor` times its replicas (1 but for
// a confirmation): every scene loaded and its DSMC planned first, so that all replicas of all scenes are one pool of
// units for the scheduler (threads and MPI ranks); one broken scene fails the run but not the others. Writes each
// scene's folder; the caller writes the summary. On a worker rank, nothing.
Validation validate_once(RunOptions& o, const std::vector<std::filesystem::path>& files, const std::filesystem::path& out,
                         std::uint64_t seed, std::size_t replica_factor) {
  o.seed = seed;
  Validation v;
  SeedRun& run = v.run;
  run.seed = seed;
  std::vector<model::Scene> scenes;
  std::vector<dsmc::DsmcSetup> setups;
  auto report_error = [&](const std::filesystem::path& f, const std::exception& e) {
    run.errors.push_back(f.filename().string() + ": " + e.what());
    if (scheduler::root()) std::printf("%-24s ERROR %s\n", f.stem().c_str(), e.what());
  };
  for (const auto& f : files) {
    try {
      model::Scene s = with_more_replicas(theory::with_level_chosen(theory::load_scene(f.string())), replica_factor);
      require_dsmc_for_compare(s);
      load_frozen_model_errors(s);
      for (auto& d : dsmc::plan_scene_dsmc(s, run_options(o))) setups.push_back(std::move(d));
      v.file_of[s.name] = f;
      scenes.push_back(std::move(s));
    } catch (const std::exception& e) {
      report_error(f, e);
    }
  }
  o.checkpointing = start_checkpointing(o.checkpoint, setups);
  v.replicas = scheduler::run_units(setups, o.threads);
  if (!scheduler::root()) return v;  // rank 0 writes every file
  dsmc::RunOptions opt = run_options(o);
  opt.source = &v.replicas;
  std::printf("%s", summary_header().c_str());
  for (const auto& s : scenes) {
    try {
      run.scenes.push_back(compare_scene(s, out, opt));
      std::printf("%s", summary_lines(run.scenes.back()).c_str());
    } catch (const std::exception& e) {
      report_error(s.file, e);
    }
    std::fflush(stdout);
    interrupts::set_finished(std::to_string(run.scenes.size()) + " of " + std::to_string(files.size()) + " scenes written to " + out.string() +
                             "/, no summary");
  }
  return v;
}

void write_validation(const std::filesystem::path& out, const Validation& v, const Confirmation* confirmation) {
  interrupts::WriteGuard g;  // summary.tsv, summary.json and index.html together
  write_summary(out, v.run.scenes, v.run.errors, v.replicas, confirmation);
  write_html_report(out);
}

// The scenes of `first` that failed on their points' statistics, measured again at the confirmation seed with
// o.confirm times their replicas into OUT/confirmation/ (confirmation.hpp). Every rank takes part in the DSMC.
Confirmation confirm(const RunOptions& o, const Validation& first) {
  Confirmation c;
  c.seed = confirmation_seed(first.run.seed), c.factor = o.confirm;
  std::string listed;
  if (scheduler::root())
    for (const std::string& name : scenes_to_confirm(first.run.scenes)) listed += first.file_of.at(name).string() + "\n";
  listed = scheduler::share_from_root(listed);
  std::vector<std::filesystem::path> files;
  for (std::size_t a = 0, b; (b = listed.find('\n', a)) != std::string::npos; a = b + 1) files.emplace_back(listed.substr(a, b - a));
  if (files.empty()) return c;
  const std::filesystem::path out = std::filesystem::path(o.out) / "confirmation";
  if (scheduler::root())
    std::printf("confirmation: %zu scene%s failed on their points' statistics at seed %llu; measured again at seed %llu with %zux the "
                "replicas -> %s/\n",
                files.size(), files.size() == 1 ? "" : "s", static_cast<unsigned long long>(first.run.seed),
                static_cast<unsigned long long>(c.seed), c.factor, out.string().c_str()),
        std::fflush(stdout);
  RunOptions again = o;
  again.checkpoint = {}, again.checkpointing = nullptr;  // snapshots belong to the first run
  Validation v = validate_once(again, files, out, c.seed, c.factor);
  if (!scheduler::root()) return c;
  write_validation(out, v, nullptr);
  c.scenes = std::move(v.run.scenes), c.errors = std::move(v.run.errors);
  return c;
}

// "all pass" or "FAILURES", and the quantities whose failure a confirmation did not repeat.
std::string verdict_line(const SeedRun& run, const Confirmation& c) {
  std::string line = passes(run.scenes, run.errors, &c) ? "all pass" : "FAILURES";
  std::string chance;
  std::size_t n = 0;
  for (const SceneOutcome& s : run.scenes)
    for (const QuantityResult& q : s.quantities)
      if (verdict(s.scene, q, &c) == "chance") chance += (n++ ? ", " : "") + s.scene + " " + label(q.spec);
  if (n)
    line += fmt::format(" ({} quantit{} failed at seed {} by chance, passing at seed {} with {}x the replicas: {})", n, n == 1 ? "y" : "ies",
                        run.seed, c.seed, c.factor, chance);
  return line;
}

}  // namespace

std::function<int()> add_validate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("validate", "every scene: compare, then summary.tsv and summary.json");
  auto o = std::make_shared<RunOptions>();
  auto seeds = std::make_shared<std::string>();
  add_run_options(cmd, *o);
  cmd->add_option("--scenes", o->scenes, "scene folder (default compare/scenes)");
  cmd->add_option("--seeds", *seeds,
                  "A-B: held-out calibration, the suite at each seed into DIR/seed-S/, then DIR/calibration.tsv and .json "
                  "(docs/validation.md, \"Held-out calibration\")")
      ->excludes(cmd->get_option("--seed"));
  cmd->add_option("--confirm", o->confirm,
                  "N: a scene failing on its points' statistics runs again at another seed with N times the replicas, and a "
                  "quantity fails when it fails both times (docs/judging.md §2.1); 0 or 1: none")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  return [o, seeds, cmd]() {
    interrupts::install();
    interrupts::require_writable_folder(o->out);
    const std::filesystem::path dir = o->scenes.empty() ? default_scene_folder() : std::filesystem::path(o->scenes);
    if (!std::filesystem::is_directory(dir)) throw InputError("validate: no scene folder " + dir.string() + " (allowed: a folder of *.toml)");
    if (seeds->empty()) {
      const Validation first = validate_once(*o, scene_files(dir), o->out, o->seed, 1);
      const Confirmation c = o->confirm > 1 ? confirm(*o, first) : Confirmation{};
      if (!scheduler::root()) return 0;
      write_validation(o->out, first, &c);
      const bool pass = passes(first.run.scenes, first.run.errors, &c);
      std::printf("validate (%s): %zu scenes, %s -> %s/summary.tsv, summary.json\n", o->fidelity.c_str(),
                  first.run.scenes.size() + first.run.errors.size(), verdict_line(first.run, c).c_str(), o->out.c_str());
      return pass ? 0 : 1;
    }
    if (cmd->get_option("--confirm")->count() > 0)
      throw InputError("--confirm belongs to a single seed: --seeds measures how often the first judgement fails (allowed: --seed S --confirm N)");
    const std::vector<std::uint64_t> list = parse_seed_range(*seeds);
    if (!o->checkpoint.checkpoint.empty() || !o->checkpoint.restart.empty()) throw InputError("--seeds: checkpoints belong to one run (allowed: --seeds without --checkpoint/--restart)");
    std::vector<SeedRun> runs;
    const std::vector<std::filesystem::path> files = scene_files(dir);
    for (const std::uint64_t seed : list) {
      if (scheduler::root()) std::printf("validate --seeds: seed %llu (%zu of %zu)\n", static_cast<unsigned long long>(seed), runs.size() + 1, list.size());
      const std::filesystem::path out = std::filesystem::path(o->out) / ("seed-" + std::to_string(seed));
      Validation v = validate_once(*o, files, out, seed, 1);
      if (scheduler::root()) write_validation(out, v, nullptr);
      runs.push_back(std::move(v.run));
    }
    if (!scheduler::root()) return 0;
    const std::vector<CalibrationRow> rows = calibrate(runs);
    Provenance p;
    p.scene_name = "calibration", p.scene_file = dir.string(), p.scene_sha256 = "-", p.command = command_line();
    p.seed = *seeds, p.fidelity = o->fidelity;
    write_atomically(std::filesystem::path(o->out) / "calibration.tsv", provenance_header(p) + calibration_tsv(rows));
    write_atomically(std::filesystem::path(o->out) / "calibration.json", calibration_json(runs, rows).dump(2) + "\n");
    std::printf("%s-> %s/calibration.tsv, calibration.json\n", calibration_summary(runs, rows).c_str(), o->out.c_str());
    return std::all_of(rows.begin(), rows.end(), [](const CalibrationRow& r) { return r.consistent(); }) ? 0 : 1;
  };
}

}  // namespace granmix::compare
