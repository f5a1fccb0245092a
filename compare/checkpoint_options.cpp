#include "checkpoint_options.hpp"

#include "dsmc/checkpoint_files.hpp"
#include "granmix_version.hpp"
#include "interrupts.hpp"

namespace granmix::compare {

void add_checkpoint_flags(CLI::App* cmd, CheckpointFlags& f) {
  auto* c = cmd->add_option("--checkpoint", f.checkpoint,
                            "write snapshots of the replicas in flight to DIR (and resume from the ones there)");
  auto* r = cmd->add_option("--restart", f.restart, "resume from the checkpoint folder DIR (must exist) and keep checkpointing there");
  c->excludes(r);
  cmd->add_option("--checkpoint-every", f.every_seconds, "seconds of wall time between a replica's snapshots (0: at every refresh point)")
      ->check(CLI::Range(0.0, 1e9))
      ->capture_default_str();
}

std::shared_ptr<dsmc::Checkpointing> start_checkpointing(const CheckpointFlags& f, const std::vector<model::Scene>& scenes,
                                                         const dsmc::RunOptions& options) {
  if (f.checkpoint.empty() && f.restart.empty()) return nullptr;
  auto c = std::make_shared<dsmc::Checkpointing>();
  c->dir = f.restart.empty() ? f.checkpoint : f.restart;
  c->every_seconds = f.every_seconds;
  c->granmix_version = std::string(version) + " (" + git_sha + ")";
  dsmc::prepare_checkpoint_folder(*c, !f.restart.empty());
  std::vector<dsmc::DsmcSetup> plan;
  for (const model::Scene& s : scenes)
    for (auto& setup : dsmc::plan_scene_dsmc(s, options)) plan.push_back(std::move(setup));
  dsmc::verify_checkpoint_folder(*c, plan);
  static dsmc::StopRequest stop;  // one per process: the signal watcher keeps a pointer to it
  c->stop = &stop;
  interrupts::set_stop_request(&stop, c->dir);
  return c;
}

std::vector<model::Scene> loadable_scenes(const std::vector<std::string>& files) {
  std::vector<model::Scene> scenes;
  for (const auto& f : files) {
    try {
      scenes.push_back(model::load_scene(f));
    } catch (const std::exception&) {  // reported when validate reaches the scene
    }
  }
  return scenes;
}

}  // namespace granmix::compare
