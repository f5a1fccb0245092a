#pragma once
// `[theory] level = "auto"` (docs/levels.md, "Choosing a level"): the cheapest level whose computed model error meets
// the scene's target — "model only what a scene needs" (docs/architecture.md §1). The levels are tried up the ladder
// their catalogue entries declare (auto_step, cheapest first), each only where it accepts the scene and within its
// cost budget (auto_max_species); a level's model error for a quantity is the one the default comparison judges with
// (the largest difference to its companions, model/model_error.hpp), and a quantity without a companion at that level
// has none, so the level does not meet the target. The choice depends on the scene alone: the same on every machine.
#include <string>
#include <vector>

#include "model/scene.hpp"

namespace granmix::theory {

struct LevelTried {
  std::string level;
  std::string skipped;  // why the level was not run (empty: it ran)
  // Per quantity of the default comparison: its name and the largest model error over the judged rows (NaN: the
  // level computes none for it).
  std::vector<std::pair<std::string, double>> errors;
  double worst = 0.0;   // the largest of them (NaN if any is NaN)
  double seconds = 0.0;
  bool meets = false;
};

struct LevelChoice {
  std::string level;                // the level chosen
  std::vector<LevelTried> tried;    // cheapest first, up to the one chosen
  std::string why;                  // one line: which level, its model error against the target, what was tried
};

// The choice for a scene with level = "auto" (throws std::logic_error for any other scene). When no level on the
// ladder meets the target, the one with the smallest model error is chosen and `why` says the target was not met.
LevelChoice choose_level(const model::Scene& scene);

// The scene with its level chosen: unchanged unless its level is "auto"; otherwise its level set, level_choice
// filled with the choice's `why` and, without [compare], the default comparison of the chosen level.
model::Scene with_level_chosen(const model::Scene& scene);

}  // namespace granmix::theory
