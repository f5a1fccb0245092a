// granmix dsmc SCENE.toml [--out DIR] [--fidelity quick|paper] [--seed S] [--threads N]
//   [--checkpoint DIR | --restart DIR] [--checkpoint-every SECONDS]
//   -> DIR/<scene>/dsmc.tsv with mean and standard-error columns (docs/architecture.md §3–4), and an
//   end-of-run summary on stdout; a progress line on stderr (compare/scheduler.hpp).
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "checkpoint_options.hpp"
#include "commands.hpp"
#include "dsmc/scene_dsmc.hpp"
#include "interrupts.hpp"
#include "model/scene.hpp"
#include "provenance.hpp"
#include "scene_folder.hpp"
#include "scheduler.hpp"
#include "model/sha256.hpp"
#include "tsv_writer.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::compare {

namespace {

struct DsmcOptions {
  std::string scene, out = "out", fidelity = "quick";
  std::uint64_t seed = 1;
  int threads = 0;
  CheckpointFlags checkpoint;
};

int run(const DsmcOptions& o) {
  interrupts::install();
  interrupts::require_writable_folder(o.out);
  const model::Scene s = theory::load_scene(o.scene);
  dsmc::RunOptions opt;
  opt.fidelity = o.fidelity, opt.seed = o.seed, opt.threads = o.threads;
  std::vector<dsmc::DsmcSetup> plan = dsmc::plan_scene_dsmc(s, opt);
  const auto checkpointing = start_checkpointing(o.checkpoint, plan);
  opt.checkpoint = checkpointing.get();
  const scheduler::GatheredReplicas replicas = scheduler::run_units(plan, o.threads);
  if (!scheduler::root()) return 0;  // rank 0 writes every file
  opt.source = &replicas;
  const dsmc::DsmcRun run = dsmc::run_scene_dsmc(s, opt);
  Provenance p;
  p.scene_name = s.name, p.scene_file = s.file, p.scene_sha256 = model::sha256_hex(s.text), p.command = command_line();
  p.seed = std::to_string(o.seed) + " (replica r uses stream (seed, r))";
  p.fidelity = o.fidelity;
  const std::filesystem::path file = std::filesystem::path(o.out) / s.name / "dsmc.tsv";
  std::vector<std::string> notes;
  if (auto moved = set_aside_other_scene(o.out, s.name, p.scene_sha256)) notes.push_back(*moved);  // never beside another scene's tables
  for (const std::string& n : dsmc::run_notes(s, o.fidelity)) notes.push_back(n);
  {
    interrupts::WriteGuard g;  // both files or neither
    write_atomically(file, format_tsv(provenance_header(p), run.table));
    if (!run.distribution.rows.empty())
      write_atomically(file.parent_path() / "distribution.tsv", format_tsv(provenance_header(p), run.distribution));
  }
  const dsmc::DsmcResult& r = run.result;
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("%s: %zu rows -> %s\n", s.name.c_str(), run.table.rows.size(), file.c_str());
  std::printf("  method %s, %zu species, %zu particles x %zu replicas, %llu collisions, %llu trial pairs\n",
              dsmc::to_string(r.method), r.species, r.particles, r.replicas, static_cast<unsigned long long>(r.accepted),
              static_cast<unsigned long long>(r.trials));
  // Each replica's phases by a steady clock, summed over replicas: its CPU time on an idle core, more on a loaded one.
  std::printf("  replica time by phase: set-up %.2f s, event loop (select + collide) %.2f s, sampling %.2f s\n", r.seconds_setup,
              r.seconds_loop, r.seconds_sample);
  std::printf("  acceptance %.3f, %.3g collisions/s per replica-second, wall %.2f s on %d rank(s) x %d thread(s), peak memory %.1f MB\n",
              r.acceptance(), r.collisions_per_second(), replicas.wall_seconds, replicas.ranks, replicas.threads, ru.ru_maxrss / 1024.0);
  if (r.replicas == 1) notes.push_back("1 replica: the error columns are nan (no spread to estimate them from)");
  for (const std::string& n : notes) std::printf("warning: %s\n", n.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_dsmc_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("dsmc", "event-driven DSMC of a scene -> DIR/<scene>/dsmc.tsv");
  auto o = std::make_shared<DsmcOptions>();
  cmd->add_option("scene", o->scene, "scene file (TOML); - reads it from standard input")->required();
  cmd->add_option("--out", o->out, "output folder")->capture_default_str();
  cmd->add_option("--fidelity", o->fidelity, "quick or paper (particles, replicas of the scene's [dsmc])")
      ->check(CLI::IsMember({"quick", "paper"}))
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "master seed")->check(seed_range())->capture_default_str();
  cmd->add_option("--threads", o->threads, "threads (0: all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
  add_checkpoint_flags(cmd, o->checkpoint);
  return [o]() { return run(*o); };
}

}  // namespace granmix::compare
