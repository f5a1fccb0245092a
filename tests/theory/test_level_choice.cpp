// `[theory] level = "auto"` (theory/level_choice.hpp, docs/levels.md "Choosing a level"): the cheapest rung of the
// ladder whose own truncations' model error meets the target, within the cost budget, the same on every run.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "model/errors.hpp"
#include "theory/level_choice.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"

using namespace granmix;
using namespace granmix::theory;

namespace {

// The quick start's ternary (examples/ternary.toml) without a level: masses 1/4/20, σ 1/1.3/2, ε = 0.7.
std::string ternary(const std::string& theory_table = "", const std::string& restitution = "0.7") {
  return R"([scene]
name = "auto-ternary"
[mixture]
density = 0.05
fraction = [1, 1, 1]
species = [{ mass = 1, diameter = 1 }, { mass = 4, diameter = 1.3 }, { mass = 20, diameter = 2 }]
[collisions]
restitution = )" + restitution + R"(
[observables]
temperatures = true
msd = true
[time]
start = 10
end = 1e3
points = 8
spacing = "log"
[dsmc]
quick = { particles = 3000, replicas = 16 }
)" + theory_table;
}

int rung(const std::string& level) {
  return find_level(level).auto_step;
}

}  // namespace

TEST_CASE("a user scene without a level is auto, a paper scene without one takes the catalogue default", "[theory]") {
  CHECK(load_scene_text(ternary(), "my/ternary.toml").theory.level == "auto");
  CHECK(load_scene_text(ternary(), "compare/scenes/x.toml").theory.level == level_catalogue().default_level());
  CHECK(load_scene_text(ternary("[theory]\nlevel = \"kinetic\"\n"), "my/ternary.toml").theory.level == "kinetic");
}

TEST_CASE("auto picks the cheapest rung that meets the target, and every cheaper rung tried misses it", "[theory][slow]") {
  for (const double target : {0.03, 0.005, 1e-4}) {
    const model::Scene s = load_scene_text(ternary("[theory]\nauto_target = " + std::to_string(target) + "\n"), "my/ternary.toml");
    const LevelChoice c = choose_level(s);
    INFO("target " << target << ": " << c.why);
    REQUIRE(!c.tried.empty());
    const LevelTried& chosen = *std::find_if(c.tried.begin(), c.tried.end(), [&](const LevelTried& t) { return t.level == c.level; });
    for (const LevelTried& t : c.tried) {
      if (&t == &chosen || !t.skipped.empty()) continue;
      // a rung tried before the chosen one missed the target; one with a smaller error would have been chosen
      CHECK((std::isnan(t.worst) || t.worst > target));
      if (!std::isnan(t.worst) && !std::isnan(chosen.worst)) CHECK(t.worst >= chosen.worst);
    }
    if (chosen.meets) {
      CHECK(chosen.worst <= target);
      CHECK(&chosen == &c.tried.back());  // the ladder stops at the first rung that meets it
      CHECK(c.why.find("meets the target") != std::string::npos);
    } else {
      CHECK(c.why.find("no level within the cost budget meets the target") != std::string::npos);
    }
  }
  // Regression pins of this ternary's choice (docs/levels.md, "Choosing a level"): at 3% the paper level (T 1.3%, MSD
  // 2.7% from its companion kinetic-cooling3), at 2% the kinetic level (T 0.42%, MSD 2%).
  const LevelChoice c = choose_level(load_scene_text(ternary(), "my/ternary.toml"));
  CHECK(c.level == "paper");
  CHECK(choose_level(load_scene_text(ternary("[theory]\nauto_target = 0.02\n"), "my/ternary.toml")).level == "kinetic");
  // A target no rung meets: the smallest error wins, and the choice climbs to a costlier rung than at 3%.
  const LevelChoice strict = choose_level(load_scene_text(ternary("[theory]\nauto_target = 1e-4\n"), "my/ternary.toml"));
  CHECK(rung(strict.level) > rung(c.level));
  // The same scene, the same choice and words (no timing enters it).
  CHECK(choose_level(load_scene_text(ternary(), "my/ternary.toml")).why == c.why);
}

TEST_CASE("auto tries only the rungs that accept the scene and fit the cost budget", "[theory][slow]") {
  // A viscoelastic ternary: the speed-grid level (constant restitution only) is never run.
  const model::Scene visco = load_scene_text(ternary("[theory]\nauto_target = 1e-4\n",
                                                     "{ viscoelastic = 0.05, form = \"exact\" }"),
                                             "my/visco.toml");
  const LevelChoice c = choose_level(visco);
  for (const LevelTried& t : c.tried)
    if (t.level == "kinetic-converged-grid") CHECK(!t.skipped.empty());
  // Every rung's budget is a species count: each skips a mixture larger than its budget, with the reason.
  for (const model::AutoStep& step : level_rules().auto_ladder) {
    INFO(step.level);
    CHECK(step.max_species >= 10);
    CHECK(rung(step.level) > 0);
  }
}

TEST_CASE("auto refuses what names one level's companions, and auto_target belongs to auto", "[theory]") {
  const std::string compare = "[compare]\nquantities = [{ name = \"T\", correction_from = [\"paper\"], z = 4, why = \"x\" }]\n";
  try {
    load_scene_text(ternary() + compare, "my/ternary.toml");
    FAIL("accepted correction_from with level auto");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("correction_from") != std::string::npos);
    CHECK(std::string(e.what()).find("\"auto\"") != std::string::npos);
  }
  CHECK_THROWS_AS(load_scene_text(ternary("[theory]\nlevel = \"kinetic\"\nauto_target = 0.01\n"), "my/ternary.toml"), InputError);
  CHECK_THROWS_AS(load_scene_text(ternary("[theory]\nauto_target = 0.9\n"), "my/ternary.toml"), InputError);
}

TEST_CASE("a scene with its level chosen carries the choice and the chosen level's default comparison", "[theory]") {
  const model::Scene s = with_level_chosen(load_scene_text(ternary("[theory]\nauto_target = 0.02\n"), "my/ternary.toml"));
  CHECK(s.theory.level == "kinetic");
  CHECK(s.theory.level_choice.find("auto chose kinetic") == 0);
  REQUIRE(s.compare.size() == 2);  // T and msd, judged with every companion of the level (docs/judging.md)
  CHECK(!s.compare[0].correction_from.empty());
  // run_theory of an unchosen auto scene gives the chosen level's table
  const model::Scene unchosen = load_scene_text(ternary("[theory]\nauto_target = 0.02\n"), "my/ternary.toml");
  CHECK(run_theory(unchosen).table.rows == run_theory(s).table.rows);
}
