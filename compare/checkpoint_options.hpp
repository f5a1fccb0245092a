#pragma once
// --checkpoint DIR, --checkpoint-every SECONDS and --restart DIR of `granmix dsmc|compare|validate`
// (docs/user-guide.md): the folder is prepared and every file in it checked against the planned runs before
// anything is computed or written (exit 2 naming the file otherwise), and a SIGINT/SIGTERM then makes
// every replica in flight write a last snapshot before the run ends (compare/interrupts.hpp).
#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include "dsmc/ensemble.hpp"
#include "dsmc/scene_dsmc.hpp"

namespace granmix::compare {

struct CheckpointFlags {
  std::string checkpoint, restart;  // at most one
  double every_seconds = 600.0;
};

void add_checkpoint_flags(CLI::App* cmd, CheckpointFlags& f);

// Checkpointing for a run of the planned ensembles (plan_scene_dsmc of its scenes), or none without
// the flags; every set-up of the plan then points to it. InputError if the folder cannot be written
// or holds a file that is not of this run.
std::shared_ptr<dsmc::Checkpointing> start_checkpointing(const CheckpointFlags& f, std::vector<dsmc::DsmcSetup>& plan);

}  // namespace granmix::compare
