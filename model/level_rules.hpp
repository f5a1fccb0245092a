#pragma once
// What a scene's checks need to know of the theory levels, as plain data (docs/levels.md). The levels live in
// theory/levels/ and declare themselves once in its catalogue (theory/levels/level_catalogue.hpp), which fills this
// view; model/ names no level itself. load_scene() takes it, so a level added to the catalogue is allowed, refused and
// explained by the scene checks without a change here.
#include <string>
#include <string_view>
#include <vector>

namespace granmix::model {

struct Scene;

// A kind of scene a level refuses: the scene violates the condition when any of its set properties fails.
struct LevelCondition {
  bool needs_sweep = false;                     // the level is a sweep's settled state (no history in time)
  bool needs_history = false;                   // the level integrates in time (no sweep)
  bool needs_constant_restitution = false;      // in every scene
  bool constant_restitution_in_sweeps = false;  // in a sweep only
  bool refuses_tracer = false;                  // no tracer form
  std::string what, allowed;                    // the refusal: why, and what the scene may write instead
  bool violated_by(const Scene& s) const;
};

// A companion: the judged level with one part changed; correction_from = `correction` judges with the difference.
struct CompanionRule {
  std::string correction, level;
  std::vector<std::string> quantities;  // the quantities it may judge (empty: any)
  bool needs_tracer = false;            // the part changed is the tracer form's
  bool needs_settled_distribution = false;
  bool needs_history_with_constant_restitution = false;
};

// A column of theory.tsv that holds the level's own computed model error of some quantities.
struct ErrorColumnRule {
  std::string column, what;
  std::vector<std::string> quantities;
};

struct LevelRule {
  std::string name;
  bool scene_may_choose = false;
  std::vector<LevelCondition> conditions;
  std::vector<CompanionRule> companions;
  std::vector<ErrorColumnRule> error_columns;
  const CompanionRule* companion(std::string_view correction) const;
};

// A correction name means one thing whichever level offers it.
struct CorrectionRule {
  std::string name, what;
};

// A step of `level = "auto"`'s ladder (docs/levels.md, "Choosing a level"): a level tried there, cheapest first, and
// the most species for which it stays within the choice's cost budget.
struct AutoStep {
  std::string level;
  std::size_t max_species = 0;
};

struct LevelRules {
  static constexpr std::string_view auto_level = "auto";  // a scene's `[theory] level = "auto"`: chosen by theory/level_choice.hpp
  std::vector<LevelRule> levels;
  std::vector<AutoStep> auto_ladder;       // cheapest first
  std::vector<CorrectionRule> corrections;  // every correction some level offers
  std::string default_level;                // a paper scene without `[theory] level` (a user's scene: "auto")
  const LevelRule* find(std::string_view name) const;
  const CorrectionRule* correction(std::string_view name) const;
  std::vector<std::string> scene_levels() const;    // the names a scene may choose
  std::vector<std::string> error_columns() const;   // every error column some level computes
  std::vector<std::string> offering(std::string_view correction) const;  // the levels a scene may choose that offer it
};

}  // namespace granmix::model
