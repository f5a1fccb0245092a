#include "level_rules.hpp"

#include <algorithm>

#include "scene.hpp"

namespace granmix::model {

bool LevelCondition::violated_by(const Scene& s) const {
  const bool sweep = s.theory.sweep.has_value(), viscoelastic = s.restitution.is_viscoelastic();
  return (needs_sweep && !sweep) || (needs_history && sweep) || (needs_constant_restitution && viscoelastic) ||
         (constant_restitution_in_sweeps && sweep && viscoelastic) || (refuses_tracer && s.theory.tracer);
}

const CompanionRule* LevelRule::companion(std::string_view correction) const {
  for (const CompanionRule& c : companions)
    if (c.correction == correction) return &c;
  return nullptr;
}

const LevelRule* LevelRules::find(std::string_view name) const {
  for (const LevelRule& l : levels)
    if (l.name == name) return &l;
  return nullptr;
}

const CorrectionRule* LevelRules::correction(std::string_view name) const {
  for (const CorrectionRule& c : corrections)
    if (c.name == name) return &c;
  return nullptr;
}

std::vector<std::string> LevelRules::scene_levels() const {
  std::vector<std::string> out;
  for (const LevelRule& l : levels)
    if (l.scene_may_choose) out.push_back(l.name);
  return out;
}

std::vector<std::string> LevelRules::error_columns() const {
  std::vector<std::string> out;
  for (const LevelRule& l : levels)
    for (const ErrorColumnRule& e : l.error_columns)
      if (std::find(out.begin(), out.end(), e.column) == out.end()) out.push_back(e.column);
  return out;
}

std::vector<std::string> LevelRules::offering(std::string_view correction) const {
  std::vector<std::string> out;
  for (const LevelRule& l : levels)
    if (l.scene_may_choose && l.companion(correction)) out.push_back(l.name);
  return out;
}

}  // namespace granmix::model
