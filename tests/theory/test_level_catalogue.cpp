// The level catalogue (theory/levels/level_catalogue.hpp): every list of levels is derived from one declaration per
// level, so a level declared once appears in the factory, the help and errors, `granmix levels` and the scene checks.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <string>

#include "model/errors.hpp"
#include "model/observable_catalogue.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"

using namespace granmix;
using namespace granmix::theory;

namespace {

std::string toy_scene(const std::string& theory_table) {
  return R"([scene]
name = "toy"
[mixture]
species = [{ mass = 1, diameter = 1, density = 0.1 }, { mass = 4, diameter = 1, density = 0.1 }]
[collisions]
restitution = 0.8
[observables]
temperatures = true
[time]
end = 1
points = 3
)" + theory_table;
}

}  // namespace

TEST_CASE("a toy level declared once appears in the factory, the allowed values, granmix levels and the scene checks", "[theory]") {
  LevelDescriptor toy;
  toy.name = "toy-level";
  toy.family = "toy";
  toy.summary = "the paper level under another name (a test of the catalogue)";
  toy.applies = "no tracer form";
  toy.cost = "none";
  toy.scene_may_choose = true;
  toy.conditions.push_back({.refuses_tracer = true, .what = "level \"toy-level\" has no tracer form", .allowed = "theory.tracer = false"});
  toy.companions.push_back({"cooling3", "kinetic-cooling3", "the temperatures at Sonine order 3", {}});
  toy.construct = [] { return find_level("paper").construct(); };
  REQUIRE_THROWS_AS(find_level("toy-level"), std::invalid_argument);
  level_catalogue().add(toy);

  // The factory: an object that knows its declaration.
  const auto level = make_theory_level("toy-level");
  CHECK(std::string(level->name()) == "toy-level");
  CHECK(&level->descriptor() == &find_level("toy-level"));
  // The allowed values of errors and of `granmix theory --level`'s help (both are names()).
  CHECK_THAT(level_catalogue().names(), Catch::Contains("toy-level"));
  try {
    find_level("no-such-level");
    FAIL("an unknown level must be refused");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("toy-level") && Catch::Contains("kinetic-converged-grid"));
  }
  // granmix levels, text and Markdown (docs/levels.md's table).
  CHECK_THAT(level_listing(false, false), Catch::Contains("toy-level") && Catch::Contains("the paper level under another name"));
  CHECK_THAT(level_listing(false, true), Catch::Contains("| `toy-level` | toy |"));
  // The scene checks: chosen, its condition enforced with its own words, its companion allowed, others refused.
  const model::Scene s = load_scene_text(toy_scene("[theory]\nlevel = \"toy-level\"\n"), "toy.toml");
  CHECK(s.theory.level == "toy-level");
  CHECK_THROWS_WITH(load_scene_text(toy_scene("[theory]\nlevel = \"toy-level\"\ntracer = true\n"), "toy.toml"),
                    Catch::Contains("level \"toy-level\" has no tracer form"));
  const std::string compare = "[dsmc]\nquick = { particles = 1000, replicas = 2 }\npaper = { particles = 1000, replicas = 2 }\n[compare]\nquantities = [{ name = \"T\", ";
  CHECK_NOTHROW(load_scene_text(toy_scene("[theory]\nlevel = \"toy-level\"\n" + compare + "correction_from = \"cooling3\", why = \"w\" }]\n"), "toy.toml"));
  CHECK_THROWS_WITH(load_scene_text(toy_scene("[theory]\nlevel = \"toy-level\"\n" + compare + "correction_from = \"sonine1\", why = \"w\" }]\n"), "toy.toml"),
                    Catch::Contains("\"sonine1\" is the first-Sonine D of the kinetic level, but theory.level is \"toy-level\""));
  // And its curves: the paper level's, under its own name.
  const model::Table a = run_level(s, "toy-level").table, b = run_level(s, "paper").table;
  REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i)
    for (std::size_t j = 0; j < a.rows[i].size(); ++j) CHECK((a.rows[i][j] == b.rows[i][j] || (std::isnan(a.rows[i][j]) && std::isnan(b.rows[i][j]))));
}

TEST_CASE("every companion names a declared level, and the scene levels' companions are the ones the scenes judge with (regression pin)", "[theory]") {
  const LevelCatalogue& c = level_catalogue();
  std::map<std::string, std::set<std::string>> offered;
  for (const auto& d : c.levels())
    for (const LevelCompanion& k : d->companions) {
      INFO(d->name << " -> " << k.correction);
      CHECK(c.lookup(k.level) != nullptr);
      CHECK(k.level != d->name);
      if (d->scene_may_choose) offered[d->name].insert(k.correction + "=" + k.level);
    }
  // Regression pin: the companions of the levels a scene may choose, as the scene files rely on them.
  const std::map<std::string, std::set<std::string>> pinned = {
      {"paper", {"cooling3=kinetic-cooling3"}},
      {"kinetic", {"paper=paper", "sonine1=kinetic-sonine1", "cooling3=kinetic-cooling3"}},
      {"kinetic-cooling3", {"paper=paper", "sonine1=kinetic-cooling3-sonine1", "kinetic=kinetic", "cooling4=kinetic-cooling4"}},
      {"kinetic-cooling3-shaped", {"paper=paper", "kinetic=kinetic"}},
      {"kinetic-converged",
       {"paper=paper", "kinetic=kinetic", "cooling3=kinetic-converged-cooling3", "reshaped=kinetic-converged-reshaped"}},
      {"kinetic-converged-cooling3",
       {"paper=paper", "kinetic=kinetic", "sonine4=kinetic-cooling3", "converged=kinetic-converged", "reshaped=kinetic-converged-cooling3-reshaped",
        "cooling4=kinetic-converged-cooling4", "grid=kinetic-converged-grid", "basis=kinetic-converged-cooling3-basis10"}},
      {"kinetic-converged-hcs", {"paper=paper", "kinetic=kinetic"}},
      {"kinetic-converged-grid", {"paper=paper", "kinetic=kinetic", "a2=kinetic-converged-grid-a2", "basis=kinetic-converged-grid-basis10"}},
      {"kinetic-hcs-converged",
       {"paper=paper", "knots=kinetic-hcs-converged-knots", "rule=kinetic-hcs-converged-rule", "partners=kinetic-hcs-converged-partners",
        "domain=kinetic-hcs-converged-domain"}},
  };
  for (const auto& [level, companions] : pinned) {
    INFO(level);
    CHECK(offered[level] == companions);
  }
  // Synonyms find their level: D to Sonine order 4 is the kinetic level's own.
  CHECK(&find_level("kinetic-sonine4") == &find_level("kinetic"));
  CHECK(&find_level("kinetic-cooling3-sonine4") == &find_level("kinetic-cooling3"));
}

TEST_CASE("the observables' catalogue: each quantity declared by one observable, and the scene checks allow exactly those", "[theory]") {
  std::set<std::string> seen;
  for (const model::ObservableDescriptor& d : model::observable_catalogue())
    for (const std::string& q : d.quantities) {
      INFO(q);
      CHECK(seen.insert(q).second);  // one owner per column
    }
  CHECK(seen.size() == model::observable_quantities().size());
  const std::string scene = toy_scene("[dsmc]\nquick = { particles = 1000, replicas = 2 }\npaper = { particles = 1000, replicas = 2 }\n[compare]\n");
  // A name the catalogue does not declare is refused, and the message lists every declared one.
  try {
    load_scene_text(scene + "quantities = [{ name = \"pressure\", why = \"w\" }]\n", "toy.toml");
    FAIL("an undeclared quantity must be refused");
  } catch (const InputError& e) {
    for (const std::string& q : model::observable_quantities()) CHECK_THAT(e.what(), Catch::Contains("\"" + q + "\""));
  }
  // Every declared name is allowed (the scene asks for temperatures only: the check of names comes first).
  CHECK_NOTHROW(load_scene_text(scene + "quantities = [{ name = \"T\", why = \"w\" }]\n", "toy.toml"));
  // The listing names every key.
  for (const std::string& k : model::observable_keys()) CHECK_THAT(model::observable_listing(true), Catch::Contains("`" + k + "`"));
}
