#pragma once
// The DSMC curves a scene asks for (docs/architecture.md §4): T, msd, c, gamma and collisions with their
// standard errors over replicas, in the long form of theory.tsv (species 0: ⟨T⟩, total MSD,
// γ = T_1/T_2, collisions per particle of the whole system).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ensemble.hpp"
#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::dsmc {

struct DsmcRun {
  model::Table table;
  model::Table distribution;  // t, species, v, phi, phi_err per sample time (empty unless asked; settled: in table)
  DsmcResult result;
  DsmcSetup setup;
};

// How a scene's DSMC runs: fidelity "quick" or "paper" (particles, replicas of the scene's [dsmc]),
// master seed, threads; replicas already computed by other
// MPI ranks (source), checkpointing and a host's abandoning stop (dsmc/stop_request.hpp), all optional.
struct RunOptions {
  std::string fidelity = "quick";
  std::uint64_t seed = 1;
  int threads = 0;
  const ReplicaSource* source = nullptr;
  const Checkpointing* checkpoint = nullptr;
  const StopRequest* stop = nullptr;
};

// With one replica every error column is NaN: one run has no spread.
DsmcRun run_scene_dsmc(const model::Scene& scene, const RunOptions& options);
// The same before that rule (the tables as the ensemble reduces them).
DsmcRun run_scene_dsmc_tables(const model::Scene& scene, const RunOptions& options);

// What a run at this fidelity does that the scene's numbers do not say: the quick settings standing in for a missing
// [dsmc] paper table; a particle total the split by density does not hit exactly (the count the run uses).
std::vector<std::string> run_notes(const model::Scene& scene, const std::string& fidelity);

// Sweep scenes: one settled-state run per value in dsmc.at; rows (x, species) with D_ratio, gamma,
// c and their errors, in the long form of the theory sweep table.
DsmcRun run_sweep_dsmc(const model::Scene& scene, const RunOptions& options);

// Every ensemble the scene's DSMC runs (one, or one per sweep point and the n* = 0 reference), set up
// exactly as run_scene_dsmc sets them up: the units of work a scheduler hands out before the run.
std::vector<DsmcSetup> plan_scene_dsmc(const model::Scene& scene, const RunOptions& options);

}  // namespace granmix::dsmc
