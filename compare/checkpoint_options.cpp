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

std::shared_ptr<dsmc::Checkpointing> start_checkpointing(const CheckpointFlags& f, std::vector<dsmc::DsmcSetup>& plan) {
  if (f.checkpoint.empty() && f.restart.empty()) return nullptr;
  auto c = std::make_shared<dsmc::Checkpointing>();
  c->dir = f.restart.empty() ? f.checkpoint : f.restart;
  c->every_seconds = f.every_seconds;
  c->granmix_version = std::string(version) + " (" + git_sha + ")";
  dsmc::prepare_checkpoint_folder(*c, !f.restart.empty());
  dsmc::verify_checkpoint_folder(*c, plan);
  static dsmc::StopRequest stop;  // one per process: the signal watcher keeps a pointer to it
  c->stop = &stop;
  interrupts::set_stop_request(&stop, c->dir);
  for (auto& setup : plan) setup.checkpoint = c.get();
  return c;
}

}  // namespace granmix::compare
