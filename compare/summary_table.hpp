#pragma once
// The per-quantity summary lines of `granmix compare` and `granmix validate` (docs/architecture.md §3): scene,
// quantity, max rel, max z, tolerance, pass, theory seconds (error estimate), DSMC seconds,
// collisions per second; and summary.tsv / summary.json for a validation run.
#include <filesystem>
#include <string>
#include <vector>

#include "confirmation.hpp"
#include "scene_compare.hpp"
#include "scheduler.hpp"

namespace granmix::compare {

std::string summary_header();
std::string summary_lines(const SceneOutcome& o);
// Also units.tsv: every DSMC unit (one replica) with its estimated and actual collisions, CPU seconds
// and rank, the input of `granmix bench schedule`; summary.json records ranks, threads, CPU seconds. Each quantity's
// `verdict` (and the top-level "pass") counts its confirmation, if one ran (confirmation.hpp; null: none).
void write_summary(const std::filesystem::path& out, const std::vector<SceneOutcome>& all, const std::vector<std::string>& errors,
                   const scheduler::GatheredReplicas& run, const Confirmation* confirmation = nullptr);

}  // namespace granmix::compare
