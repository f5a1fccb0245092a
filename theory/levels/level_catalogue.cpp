#include "theory/levels/level_catalogue.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "theory/levels/level_families.hpp"

namespace granmix::theory {

std::unique_ptr<TheoryLevel> LevelDescriptor::make() const {
  std::unique_ptr<TheoryLevel> level = construct();
  level->descriptor_ = this;
  return level;
}

const LevelCompanion* LevelDescriptor::companion(std::string_view correction) const {
  for (const LevelCompanion& c : companions)
    if (c.correction == correction) return &c;
  return nullptr;
}

void LevelCatalogue::add(LevelDescriptor d) {
  if (lookup(d.name)) throw std::logic_error("level catalogue: '" + d.name + "' declared twice");
  levels_.push_back(std::make_unique<LevelDescriptor>(std::move(d)));
  rules_.reset();
}

void LevelCatalogue::add_correction(CorrectionMeaning c) {
  corrections_.push_back(std::move(c));
  rules_.reset();
}

const LevelDescriptor* LevelCatalogue::lookup(std::string_view name) const {
  for (const auto& d : levels_)
    if (d->name == name || std::find(d->synonyms.begin(), d->synonyms.end(), name) != d->synonyms.end()) return d.get();
  return nullptr;
}

const LevelDescriptor& LevelCatalogue::find(std::string_view name) const {
  if (const LevelDescriptor* d = lookup(name)) return *d;
  throw std::invalid_argument("theory level '" + std::string(name) + "' (allowed: " + names() + ")");
}

std::string LevelCatalogue::names() const {
  std::string out;
  for (const auto& d : levels_) out += (out.empty() ? "" : ", ") + d->name;
  return out;
}

const model::LevelRules& LevelCatalogue::rules() const {
  if (rules_) return *rules_;
  auto r = std::make_unique<model::LevelRules>();
  r->default_level = default_level();
  for (const CorrectionMeaning& c : corrections_) r->corrections.push_back({c.name, c.what});
  for (const auto& d : levels_) {
    model::LevelRule l{d->name, d->scene_may_choose, d->conditions, {}, d->error_columns};
    for (const LevelCompanion& c : d->companions) {
      if (!r->correction(c.correction))
        throw std::logic_error("level catalogue: " + d->name + "'s companion '" + c.correction + "' has no declared meaning");
      if (!lookup(c.level)) throw std::logic_error("level catalogue: " + d->name + "'s companion '" + c.correction + "' names no level: " + c.level);
      l.companions.push_back({c.correction, c.level, c.quantities, c.needs_tracer, c.needs_settled_distribution, c.needs_history_with_constant_restitution});
    }
    r->levels.push_back(std::move(l));
  }
  std::vector<const LevelDescriptor*> ladder;
  for (const auto& d : levels_)
    if (d->auto_step > 0) ladder.push_back(d.get());
  std::stable_sort(ladder.begin(), ladder.end(), [](const LevelDescriptor* a, const LevelDescriptor* b) { return a->auto_step < b->auto_step; });
  for (const LevelDescriptor* d : ladder) r->auto_ladder.push_back({d->name, d->auto_max_species});
  rules_ = std::move(r);
  return *rules_;
}

LevelCatalogue& level_catalogue() {
  static LevelCatalogue catalogue = [] {
    LevelCatalogue c;
    // What each correction means, whichever level offers it; this order is theory.tsv's order of companion columns.
    c.add_correction({"paper", "a lower level of the kinetic levels"});
    c.add_correction({"sonine1", "the first-Sonine D of the kinetic level"});
    c.add_correction({"kinetic", "the kinetic level under a kinetic-cooling3 or kinetic-converged level"});
    c.add_correction({"cooling3", "the next Sonine order of the first-Sonine temperatures and HCS"});
    c.add_correction({"converged", "one truncation of the kinetic-converged-cooling3 level"});
    c.add_correction({"sonine4", "one truncation of the kinetic-converged-cooling3 level"});
    c.add_correction({"reshaped", "the gas's reshaping by the intruders in the tracer form of a kinetic-converged level"});
    c.add_correction({"cooling4", "the next Sonine order of the order-3 temperatures"});
    c.add_correction({"grid", "the speed-grid temperature history"});
    c.add_correction({"a2", "one computed part of the kinetic-converged-grid level's model error"});
    c.add_correction({"basis", "the tracer problem's basis companion of a converged level"});
    for (const char* part : {"knots", "rule", "partners", "domain"})
      c.add_correction({part, "one computed part of the kinetic-hcs-converged level's settled distributions"});
    declare_paper_levels(c);
    declare_kinetic_levels(c);
    declare_converged_levels(c);
    declare_hcs_converged_levels(c);
    return c;
  }();
  return catalogue;
}

std::string level_listing(bool all, bool markdown) {
  std::vector<const LevelDescriptor*> shown;
  for (const auto& d : level_catalogue().levels())
    if (all || d->scene_may_choose) shown.push_back(d.get());
  std::string out;
  auto companions = [](const LevelDescriptor& d) {
    std::string s;
    for (const LevelCompanion& c : d.companions) s += (s.empty() ? "" : ", ") + c.correction;
    return s.empty() ? std::string("-") : s;
  };
  if (markdown) {
    out += "| level | family | what it is | where it applies | typical cost | companions (correction_from) |\n";
    out += "|---|---|---|---|---|---|\n";
    for (const LevelDescriptor* d : shown)
      out += fmt::format("| `{}`{} | {} | {} | {} | {} | {} |\n", d->name, d->scene_may_choose ? "" : " (companion/study)", d->family, d->summary,
                         d->applies, d->cost, companions(*d));
    return out;
  }
  std::size_t width = 5;
  for (const LevelDescriptor* d : shown) width = std::max(width, d->name.size());
  out += fmt::format("{:<{}}  {:<13}  {}\n", "level", width, "family", "what it is / where it applies / typical cost / companions");
  for (const LevelDescriptor* d : shown) {
    out += fmt::format("{:<{}}  {:<13}  {}{}\n", d->name, width, d->family, d->summary, d->scene_may_choose ? "" : " [companion/study level]");
    out += fmt::format("{:<{}}  {:<13}  applies: {}\n", "", width, "", d->applies);
    out += fmt::format("{:<{}}  {:<13}  cost: {}; companions: {}\n", "", width, "", d->cost, companions(*d));
  }
  return out;
}

}  // namespace granmix::theory
