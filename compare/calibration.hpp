#pragma once
// `granmix validate --seeds A-B` (docs/validation.md, "Held-out calibration"): the suite judged at seeds that no design
// decision used, and per compared quantity how often its points fall outside their bound against how often the bound
// allows. The statistical part alone, z·σ with R replicas, is exceeded by chance with probability
// p = P(|t_{R−1}| > z) per point (docs/judging.md §6); the model error only adds room. The points of one seed are
// correlated (a replica's MSD or temperature carries its deviation on to every later time), so the count of points
// outside is over-dispersed and no Poisson bound holds for it; the count of seeds that fail does: by Šidák's inequality
// a seed of n judged points fails with probability at most q = 1 − (1 − p)^n whatever their correlation. A quantity
// is `consistent` when its failed seeds stay within the 99.9% binomial quantile of (seeds, q), `TOO MANY` otherwise:
// its model error underestimated, its error bars too small, or too few replicas — a cause to find, never a seed to drop.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_compare.hpp"

namespace granmix::compare {

struct SeedRun {
  std::uint64_t seed = 0;
  std::vector<SceneOutcome> scenes;
  std::vector<std::string> errors;
};

struct CalibrationRow {
  std::string scene, quantity;
  std::size_t replicas = 0, seeds = 0, seeds_failed = 0, points = 0, outside = 0;
  double z = 4.0;
  double chance = 0.0;           // p = P(|t_{R−1}| > z): a point's chance to fall outside on statistics alone
  double allowed = 0.0;          // the 99.9% Poisson quantile of p·points: the points outside if they were independent
  double seed_chance = 0.0;      // q = 1 − (1 − p)^(points/seeds): the most a seed fails by chance (Šidák)
  double seeds_allowed = 0.0;    // the 99.9% binomial quantile of (seeds, q)
  double ratio_median = 0.0, ratio_p90 = 0.0, ratio_max = 0.0;  // |deviation|/bound over every judged point
  bool consistent() const { return double(seeds_failed) <= seeds_allowed; }
};

// One row per scene:quantity judged in any run, in the runs' order.
std::vector<CalibrationRow> calibrate(const std::vector<SeedRun>& runs);
// calibration.tsv (after the provenance header) and calibration.json; the lines validate prints.
std::string calibration_tsv(const std::vector<CalibrationRow>& rows);
nlohmann::ordered_json calibration_json(const std::vector<SeedRun>& runs, const std::vector<CalibrationRow>& rows);
std::string calibration_summary(const std::vector<SeedRun>& runs, const std::vector<CalibrationRow>& rows);

// "101-120" or "7": the seeds, each in [0, 2^53]; throws InputError naming --seeds otherwise.
std::vector<std::uint64_t> parse_seed_range(const std::string& text);

}  // namespace granmix::compare
