#include "theory/level_choice.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "model/model_error.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"

namespace granmix::theory {

namespace {

std::string percent(double x) { return std::isnan(x) ? std::string("none computed") : fmt::format("{:.2g}%", 100.0 * x); }

// The default comparison of the scene at `level`, keeping the companions that measure the level's own truncations:
// not those that are the paper level or a rung below on the ladder (`below`). Their distance to the level is the sum of
// the corrections the level has already made, as large for every level above them: counted, it would make each rung's
// error no smaller than the rung below's.
std::vector<model::CompareQuantity> own_truncations(const model::Scene& s, const model::LevelRules& rules, const std::vector<std::string>& below) {
  const model::LevelRule& rule = *rules.find(s.theory.level);
  std::vector<model::CompareQuantity> quantities = model::default_comparison(s, rules);
  for (model::CompareQuantity& q : quantities)
    std::erase_if(q.correction_from, [&](const std::string& c) {
      const model::CompanionRule* companion = rule.companion(c);
      return companion && std::find(below.begin(), below.end(), companion->level) != below.end();
    });
  return quantities;
}

// One rung of the ladder: the scene at that level, judged by its own truncations' companions.
LevelTried try_level(const model::Scene& scene, const model::AutoStep& step, const model::LevelRules& rules, const std::vector<std::string>& below) {
  LevelTried t;
  t.level = step.level;
  model::Scene s = scene;
  s.theory.level = step.level;
  for (const model::LevelCondition& c : rules.find(step.level)->conditions)
    if (c.violated_by(s)) return t.skipped = c.what, t;
  if (s.mixture.size() > step.max_species)
    return t.skipped = fmt::format("{} species, above its cost budget of {}", s.mixture.size(), step.max_species), t;
  s.compare = own_truncations(s, rules, below);
  const auto start = std::chrono::steady_clock::now();
  const model::Table table = run_theory(s).table;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const model::CompareQuantity& q : s.compare) {
    // A quantity the level predicts and has such companions for: the largest model error over its rows; otherwise
    // none (the default comparison's fixed `relative` is a guess, not a computed error).
    const bool computed = !q.correction_from.empty() && model::ModelError(q, table).predicted() >= 0;
    const double e = computed ? model::max_model_error(q, table) : NAN;
    t.errors.emplace_back(q.name, e);
    t.worst = std::isnan(e) || std::isnan(t.worst) ? NAN : std::max(t.worst, e);
  }
  t.meets = !t.errors.empty() && !std::isnan(t.worst) && t.worst <= s.theory.auto_target;
  return t;
}

std::string errors_text(const LevelTried& t) {
  std::string out;
  for (const auto& [name, e] : t.errors) out += (out.empty() ? "" : ", ") + name + " " + percent(e);
  return out;
}

}  // namespace

LevelChoice choose_level(const model::Scene& scene) {
  if (!scene.theory.level_is_auto()) throw std::logic_error("choose_level: the scene's level is " + scene.theory.level + ", not auto");
  const model::LevelRules& rules = level_rules();
  std::vector<std::string> below;  // the paper level, then each rung once passed
  for (const auto& d : level_catalogue().levels())
    if (d->reported_beside_others) below.push_back(d->name);
  LevelChoice c;
  for (const model::AutoStep& step : rules.auto_ladder) {
    c.tried.push_back(try_level(scene, step, rules, below));
    if (c.tried.back().meets) break;
    below.push_back(step.level);
  }
  // The one that meets the target (the last tried), else the smallest model error, else the cheapest that ran.
  const LevelTried* best = nullptr;
  for (const LevelTried& t : c.tried)
    if (t.skipped.empty() && !std::isnan(t.worst) && !t.errors.empty() && (!best || t.worst < best->worst)) best = &t;
  for (const LevelTried& t : c.tried)
    if (!best && t.skipped.empty()) best = &t;
  if (!best) throw std::logic_error("choose_level: no level of the auto ladder accepts scene " + scene.name);
  c.level = best->level;
  std::string others;
  for (const LevelTried& t : c.tried)
    if (&t != best) others += fmt::format("; {}: {}", t.level, t.skipped.empty() ? errors_text(t) : "not tried, " + t.skipped);
  const std::string target = percent(scene.theory.auto_target);
  c.why = best->meets ? fmt::format("auto chose {}, the cheapest level whose computed model error ({}) meets the target {}{}", c.level,
                                    errors_text(*best), target, others)
                      : fmt::format("auto chose {}: no level within the cost budget meets the target {}; {} has the smallest model error "
                                    "({}){}",
                                    c.level, target, c.level, errors_text(*best), others);
  return c;
}

model::Scene with_level_chosen(const model::Scene& scene) {
  if (!scene.theory.level_is_auto()) return scene;
  const LevelChoice c = choose_level(scene);
  model::Scene s = scene;
  s.theory.level = c.level;
  s.theory.level_choice = c.why;
  if (s.compare_generated) s.compare = model::default_comparison(s, level_rules());
  return s;
}

}  // namespace granmix::theory
