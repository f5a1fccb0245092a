#pragma once
// One scene compared end to end (docs/architecture.md §3): theory (and its error estimate from a rerun at
// 100× tighter tolerance), DSMC, deviations, report.json and the figure, written to a temporary
// folder beside DIR/<scene> and renamed into place only when complete.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "deviations.hpp"
#include "dsmc/scene_dsmc.hpp"
#include "model/scene.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::compare {

struct SceneOutcome {
  std::string scene;
  bool pass = false;
  bool compared = false;  // the scene has [compare] quantities
  std::vector<QuantityResult> quantities;
  double theory_seconds = 0.0, theory_error = 0.0, dsmc_seconds = 0.0;
  double collisions = 0.0, collisions_per_second = 0.0, acceptance = 0.0;
  std::size_t particles = 0, replicas = 0;
  std::string figure;
  // What the reader of the verdict must know: too few replicas for z, a particle total the split does not hit,
  // the quick settings standing in for paper, old outputs moved aside (report.json "warnings").
  std::vector<std::string> warnings;
};

// What compare_scene computes, before anything is written: the theory (and its error estimate), the DSMC (when the
// scene has [dsmc]), the deviations and each compared quantity's summary; the outcome without its figure. The Python
// module's granmix.compare.
struct SceneEvaluation {
  theory::TheoryResult theory;
  dsmc::DsmcRun dsmc;  // no table without [dsmc]
  std::vector<Deviation> deviations;
  SceneOutcome outcome;
};
SceneEvaluation evaluate_scene(const model::Scene& scene, const dsmc::RunOptions& run);

// report.json of a scene (docs/architecture.md §4).
nlohmann::ordered_json report_json(const model::Scene& scene, const SceneOutcome& outcome, std::uint64_t seed, const std::string& fidelity);
// [compare] needs DSMC: refused (exit 2) by the commands that judge; `theory` reads such a scene without [dsmc].
void require_dsmc_for_compare(const model::Scene& scene);

// run: fidelity, seed, threads and, under MPI or with checkpoints, where replicas come from.
SceneOutcome compare_scene(const model::Scene& scene, const std::filesystem::path& out, const dsmc::RunOptions& run);

}  // namespace granmix::compare
