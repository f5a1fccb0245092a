#pragma once
// The catalogue of theory levels: every level declares itself once, in the file that implements it (SPARTA's styles,
// Cantera's factories), and every list of levels is derived from here — the factory, the companions a scene may judge
// with, the allowed values in errors, `granmix theory --level`'s help, `granmix levels`, the table of docs/levels.md
// and the scene checks' plain-data view (model/level_rules.hpp). docs/architecture.md §8 "Add a theory level".
//
// A companion is the level with one part changed (a `correction`: the family's variant with that part changed, named
// by the family's own naming rule); the difference between the two is a computed model error (docs/judging.md).
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "model/level_rules.hpp"
#include "theory/levels/theory_level.hpp"

namespace granmix::theory {

// What a level is made of, part by part (docs/levels.md's table; `granmix levels --parts`).
struct LevelParts {
  std::string cooling;        // the temperatures in time
  std::string diffusion;      // the velocity decay and D_k
  std::string hcs;            // the settled (homogeneous cooling) state
  std::string tracer;         // the binary tracer limit in time
  std::string distributions;  // the settled distributions Φ_k(v*)
};

struct LevelCompanion {
  std::string correction;  // the scene's correction_from value; theory.tsv's columns <quantity>_<correction>
  std::string level;       // the companion level's name
  std::string changes;     // the part changed, in words
  std::vector<std::string> quantities;  // the quantities it may judge (empty: any)
  bool needs_tracer = false, needs_settled_distribution = false, needs_history_with_constant_restitution = false;
};

struct LevelDescriptor {
  std::string name;
  std::string family;   // paper, kinetic, converged, hcs-converged (one section of docs/levels.md each)
  std::string summary;  // one line
  LevelParts parts;
  std::string applies;  // where it applies, in words (granmix levels)
  std::string cost;     // its typical cost, measured (granmix levels)
  bool scene_may_choose = false;  // otherwise a companion or a study level (`granmix theory --level`)
  // The papers' own theory: its curves go beside every other level's in theory.tsv (`<column>_paper`, "paper rel").
  bool reported_beside_others = false;
  std::vector<std::string> synonyms;  // other names that find it (kinetic-sonine4 = kinetic)
  // level = "auto" (theory/level_choice.hpp, docs/levels.md "Choosing a level"): its rung on the ladder, cheapest
  // first (0: never tried), and the most species for which its cost stays within the choice's budget (seconds).
  int auto_step = 0;
  std::size_t auto_max_species = 0;
  std::vector<model::LevelCondition> conditions;
  std::vector<LevelCompanion> companions;
  std::vector<model::ErrorColumnRule> error_columns;
  std::function<std::unique_ptr<TheoryLevel>()> construct;
  // A new object of this level (one per thread: a level keeps memos), knowing its descriptor.
  std::unique_ptr<TheoryLevel> make() const;
  const LevelCompanion* companion(std::string_view correction) const;
};

// The meaning of a correction name, whichever level offers it (the scene checks' messages).
struct CorrectionMeaning {
  std::string name, what;
};

class LevelCatalogue {
 public:
  // Declares a level (its name unique; its companions must name declared levels by the time one is looked up).
  void add(LevelDescriptor d);
  void add_correction(CorrectionMeaning c);
  // Throws std::invalid_argument naming the allowed levels.
  const LevelDescriptor& find(std::string_view name) const;
  const LevelDescriptor* lookup(std::string_view name) const;
  const std::vector<std::unique_ptr<LevelDescriptor>>& levels() const { return levels_; }
  const std::vector<CorrectionMeaning>& corrections() const { return corrections_; }
  std::string default_level() const { return "paper"; }
  // Every level's name, joined for messages and help ("paper, kinetic, …").
  std::string names() const;
  // The plain-data view the scene checks take (model::load_scene).
  const model::LevelRules& rules() const;

 private:
  std::vector<std::unique_ptr<LevelDescriptor>> levels_;
  std::vector<CorrectionMeaning> corrections_;
  mutable std::unique_ptr<model::LevelRules> rules_;
};

// The one catalogue, filled on first use by the families' declarations (level_families.hpp).
LevelCatalogue& level_catalogue();
inline const model::LevelRules& level_rules() { return level_catalogue().rules(); }
inline const LevelDescriptor& find_level(std::string_view name) { return level_catalogue().find(name); }
inline std::unique_ptr<TheoryLevel> make_theory_level(std::string_view name) { return find_level(name).make(); }

// `granmix levels`: one row per level (name, family, summary, applicability, cost; `all`: the companion and study
// levels too), as an aligned text table or Markdown (docs/levels.md's table).
std::string level_listing(bool all, bool markdown);

}  // namespace granmix::theory
