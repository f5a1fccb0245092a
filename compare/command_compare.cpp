// granmix compare SCENE.toml [--out DIR] [--fidelity quick|paper] [--seed S] [--threads N]
// granmix validate [--fidelity quick|paper] [--out DIR] [--scenes DIR] [--seed S] [--threads N] (also DIR/index.html)
// Both also [--checkpoint DIR | --restart DIR] [--checkpoint-every SECONDS] (checkpoint_options.hpp).
// (docs/architecture.md §3). Exit 0 if every compared quantity passes, 1 otherwise, 2 for bad input.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "checkpoint_options.hpp"
#include "commands.hpp"
#include "interrupts.hpp"
#include "html_report.hpp"
#include "model/errors.hpp"
#include "scene_compare.hpp"
#include "scheduler.hpp"
#include "summary_table.hpp"
#include "theory/level_choice.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::compare {

namespace {

struct RunOptions {
  std::string out = "out", fidelity = "quick", scenes;
  std::uint64_t seed = 1;
  int threads = 0;
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

std::function<int()> add_validate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("validate", "every scene: compare, then summary.tsv and summary.json");
  auto o = std::make_shared<RunOptions>();
  add_run_options(cmd, *o);
  cmd->add_option("--scenes", o->scenes, "scene folder (default compare/scenes)");
  return [o]() {
    interrupts::install();
    interrupts::require_writable_folder(o->out);
    const std::filesystem::path dir = o->scenes.empty() ? default_scene_folder() : std::filesystem::path(o->scenes);
    if (!std::filesystem::is_directory(dir)) throw InputError("validate: no scene folder " + dir.string() + " (allowed: a folder of *.toml)");
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".toml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    // Every scene loaded and its DSMC planned first, so that all replicas of all scenes are one pool of
    // units for the scheduler (threads and MPI ranks); one broken scene fails the run but not the others.
    std::vector<model::Scene> scenes;
    std::vector<std::string> errors;
    std::vector<dsmc::DsmcSetup> setups;
    auto report_error = [&](const std::filesystem::path& f, const std::exception& e) {
      errors.push_back(f.filename().string() + ": " + e.what());
      if (scheduler::root()) std::printf("%-24s ERROR %s\n", f.stem().c_str(), e.what());
    };
    for (const auto& f : files) {
      try {
        model::Scene s = theory::with_level_chosen(theory::load_scene(f.string()));
        require_dsmc_for_compare(s);
        for (auto& d : dsmc::plan_scene_dsmc(s, run_options(*o))) setups.push_back(std::move(d));
        scenes.push_back(std::move(s));
      } catch (const std::exception& e) {
        report_error(f, e);
      }
    }
    o->checkpointing = start_checkpointing(o->checkpoint, setups);
    const scheduler::GatheredReplicas replicas = scheduler::run_units(setups, o->threads);
    if (!scheduler::root()) return 0;  // rank 0 writes every file
    dsmc::RunOptions run = run_options(*o);
    run.source = &replicas;
    std::vector<SceneOutcome> all;
    std::printf("%s", summary_header().c_str());
    for (const auto& s : scenes) {
      try {
        all.push_back(compare_scene(s, o->out, run));
        std::printf("%s", summary_lines(all.back()).c_str());
      } catch (const std::exception& e) {
        report_error(s.file, e);
      }
      std::fflush(stdout);
      interrupts::set_finished(std::to_string(all.size()) + " of " + std::to_string(files.size()) + " scenes written to " + o->out +
                               "/, no summary");
    }
    {
      interrupts::WriteGuard g;  // summary.tsv, summary.json and index.html together
      write_summary(o->out, all, errors, replicas);
      write_html_report(o->out);
    }
    const bool pass = errors.empty() && std::all_of(all.begin(), all.end(), [](const auto& s) { return s.pass; });
    std::printf("validate (%s): %zu scenes, %s -> %s/summary.tsv, summary.json\n", o->fidelity.c_str(), files.size(),
                pass ? "all pass" : "FAILURES", o->out.c_str());
    return pass ? 0 : 1;
  };
}

}  // namespace granmix::compare
