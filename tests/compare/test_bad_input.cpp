// Every kind of bad scene input, through the command line: one message naming file, line and key,
// exit code 2, and no output written (docs/architecture.md §4).
#include <catch2/catch.hpp>
#include <filesystem>

#include "run_cli.hpp"

using namespace granmix;

namespace {

const std::string good = R"([scene]
name = "bad"
[mixture]
species = [{ mass = 1, diameter = 1, density = 0.1 }, { mass = 100, diameter = 4.64, density = 0.1 }]
[collisions]
restitution = 0.5
[initial]
temperatures = "equal"
[time]
end = 1e3
points = 5
[observables]
msd = true
[theory]
msd = "eq17"
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

// The good scene judged against DSMC, its msd's model error taken from `lower` (TOML text).
std::string judged(const std::string& lower) {
  return good + "[dsmc]\nquick = { particles = 100, replicas = 8 }\npaper = { particles = 100, replicas = 8 }\n[compare]\n" +
         "quantities = [{ name = \"msd\", correction_from = " + lower + ", relative = 0, why = \"w\" }]\n";
}

struct Case {
  const char* what;
  std::string text;
  const char* expect;  // "line: key" part of the message
};

}  // namespace

TEST_CASE("the good scene runs (the bad ones below differ from it in one place)", "[compare]") {
  const auto d = test::fresh_dir("good");
  test::write_file(d / "s.toml", good);
  const auto r = test::run_granmix("theory " + (d / "s.toml").string() + " --out " + (d / "out").string());
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK(std::filesystem::exists(d / "out" / "bad" / "theory.tsv"));
}

TEST_CASE("bad scenes are refused with file:line: key - exit 2 - nothing written", "[compare]") {
  const std::vector<Case> cases = {
      {"unknown key", replace(good, "points = 5", "points = 5\npoint = 3"), ":12: time.point: unknown key"},
      {"unknown table", good + "[dsmcx]\nx = 1\n", ":16: dsmcx: unknown key"},
      {"wrong type", replace(good, "restitution = 0.5", "restitution = \"half\""), ":6: collisions.restitution"},
      {"out of range", replace(good, "restitution = 0.5", "restitution = 1.5"), ":6: collisions.restitution: value 1.5 out of range"},
      {"negative mass", replace(good, "mass = 100", "mass = -100"), ":4: mixture.species[2].mass"},
      {"missing mass", replace(good, "mass = 100, ", ""), ":4: mixture.species[2].mass: missing"},
      {"missing table", replace(good, "[observables]\nmsd = true\n", ""), "observables: missing"},
      {"bad choice", replace(good, "msd = \"eq17\"", "msd = \"eq18\""), ":15: theory.msd: unknown value \"eq18\""},
      {"bad initial", replace(good, "\"equal\"", "\"warm\""), ":8: initial.temperatures: unknown value"},
      {"wrong list length", replace(good, "\"equal\"", "[1.0]"), ":8: initial.temperatures: list has 1 values for 2 species"},
      {"matrix not symmetric", replace(good, "restitution = 0.5", "restitution = [[0.5, 0.6], [0.7, 0.5]]"),
       ":6: collisions.restitution: matrix is not symmetric"},
      {"bad name", replace(good, "name = \"bad\"", "name = \"a/b\""), ":2: scene.name: not usable as a folder name"},
      {"end time out of range", replace(good, "end = 1e3", "end = -1"), ":10: time.end: value -1 out of range"},
      {"float where integer", replace(good, "points = 5", "points = 5.5"), ":11: time.points: expected an integer"},
      {"no observable", replace(good, "msd = true", "msd = false"), "observables"},
      {"closed form needs settled start", replace(good, "msd = \"eq17\"", "msd = \"closed\""), "theory: msd = \"closed\" holds for a settled start only"},

      {"toml syntax", replace(good, "points = 5", "points = = 5"), ":11:"},
      {"viscoelastic out of range", replace(good, "restitution = 0.5", "restitution = { viscoelastic = 50 }"),
       ":6: collisions.restitution.viscoelastic: value 50 out of range"},
      {"both mixture forms", replace(good, "[collisions]", "power_law = { n1 = 0.1, theta = 3, n1_particles = 10 }\n[collisions]"),
       "mixture.species: give exactly one of"},
      {"mg time unit typo", replace(good, "points = 5", "points = 5\nunit = \"seconds\""), ":12: time.unit: unknown value \"seconds\""},
      {"unknown lower level", judged("\"sonine2\""), ":20: compare.quantities[1].correction_from: unknown value \"sonine2\""},
      {"lower level twice", judged("[\"paper\", \"paper\"]"), ":20: compare.quantities[1].correction_from: \"paper\" given twice"},
      {"no lower levels", judged("[]"), "compare.quantities[1].correction_from: empty array"},
      {"model error cap out of range", replace(judged("\"paper\""), "relative = 0,", "relative = 0, model_error_max = 0,"),
       ":20: compare.quantities[1].model_error_max: value 0 out of range"},
      {"model error cap without a computed model error", replace(replace(judged("\"paper\""), "correction_from = \"paper\", ", ""),
                                                                 "relative = 0,", "relative = 0, model_error_max = 0.03,"),
       ":20: compare.quantities[1].model_error_max: caps a computed model error, but this quantity has none"},
      {"lower level of another level", replace(judged("[\"paper\", \"sonine1\"]"), "msd = \"eq17\"", "level = \"paper\""),
       "compare.correction_from: \"paper\" is a lower level of the kinetic levels, but theory.level is \"paper\""},
      {"kinetic companion of the kinetic level itself", replace(judged("\"kinetic\""), "msd = \"eq17\"", "level = \"kinetic\""),
       "compare.correction_from: \"kinetic\" is the kinetic level under a kinetic-cooling3 or kinetic-converged level, but theory.level is \"kinetic\""},
      {"next order of the order-3 level itself", replace(judged("\"cooling3\""), "msd = \"eq17\"", "level = \"kinetic-cooling3\""),
       "compare.correction_from: \"cooling3\" is the next Sonine order of the first-Sonine temperatures and HCS, but theory.level is \"kinetic-cooling3\""},
      {"the temperatures' next order on an MSD", replace(judged("\"cooling4\""), "msd = \"eq17\"", "level = \"kinetic-cooling3\""),
       "compare.correction_from: \"cooling4\" is the next Sonine order of the order-3 temperatures, but the quantity is \"msd\" at theory.level \"kinetic-cooling3\""},
      {"a truncation of the converged level under another", replace(judged("\"sonine4\""), "msd = \"eq17\"", "level = \"kinetic-converged\""),
       "compare.correction_from: \"sonine4\" is one truncation of the kinetic-converged-cooling3 level, but theory.level is \"kinetic-converged\""},
      {"the speed-grid history under a viscoelastic law",
       replace(replace(judged("\"grid\""), "msd = \"eq17\"", "level = \"kinetic-converged-cooling3\""), "restitution = 0.5", "restitution = { viscoelastic = 0.1 }"),
       "compare.correction_from: \"grid\" is the speed-grid temperature history, which needs a constant restitution coefficient and no sweep"},
      {"the speed-grid level under a viscoelastic law",
       replace(replace(judged("\"a2\""), "msd = \"eq17\"", "level = \"kinetic-converged-grid\""), "restitution = 0.5", "restitution = { viscoelastic = 0.1 }"),
       "theory: level \"kinetic-converged-grid\" integrates every species' density in time, which needs a constant restitution coefficient"},
      {"a part of the speed-grid level's model error under another level", replace(judged("\"a2\""), "msd = \"eq17\"", "level = \"kinetic-converged-cooling3\""),
       "compare.correction_from: \"a2\" is one computed part of the kinetic-converged-grid level's model error, but theory.level is \"kinetic-converged-cooling3\""},
      {"the converged tracer problem's basis under a Sonine level", replace(judged("\"basis\""), "msd = \"eq17\"", "level = \"kinetic-cooling3\""),
       "compare.correction_from: \"basis\" is the tracer problem's basis companion of a converged level, but theory.level is \"kinetic-cooling3\""},
      {"a part of the settled distributions' model error beside a history", replace(judged("\"rule\""), "msd = \"eq17\"", "level = \"kinetic-hcs-converged\""),
       "compare.correction_from: \"rule\" is one computed part of the kinetic-hcs-converged level's settled distributions, but theory.level is \"kinetic-hcs-converged\" without observables.distribution"},
      {"the distributions' grid error on an MSD", replace(replace(judged("\"paper\""), "correction_from = \"paper\"", "error_column = \"phi_error\""), "msd = \"eq17\"", "level = \"kinetic-hcs-converged\""),
       "compare.error_column: \"phi_error\" is the grid error kinetic-hcs-converged computes for its settled distributions, but the quantity is \"msd\" at theory.level \"kinetic-hcs-converged\""},
      {"unknown error column", replace(judged("\"paper\""), "correction_from = \"paper\"", "error_column = \"msd_error\""),
       ":20: compare.quantities[1].error_column: unknown value \"msd_error\""},
      {"an error column the level does not compute",
       replace(replace(judged("\"paper\""), "correction_from = \"paper\"", "error_column = \"D_ratio_error\""), "msd = \"eq17\"", "level = \"paper\""),
       "compare.error_column: \"D_ratio_error\" is the model error the level kinetic-converged-hcs computes for its D ratios, but the quantity is \"msd\" at theory.level \"paper\""},
      {"a companion with level auto", replace(judged("\"cooling3\""), "msd = \"eq17\"", "level = \"auto\""),
       "compare.correction_from: names what one level computes, but theory.level is \"auto\""},
  };
  for (const Case& c : cases) {
    const auto d = test::fresh_dir("bad");
    test::write_file(d / "scene.toml", c.text);
    const auto r = test::run_granmix("theory " + (d / "scene.toml").string() + " --out " + (d / "out").string());
    INFO(c.what << ":\n" << r.output);
    CHECK(r.code == 2);
    CHECK(r.output.find((d / "scene.toml").string()) != std::string::npos);  // names the file
    CHECK(r.output.find(c.expect) != std::string::npos);
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);  // one line
    CHECK(!std::filesystem::exists(d / "out"));                      // nothing written
  }
}

TEST_CASE("missing scene file and unknown options exit 2", "[compare]") {
  CHECK(test::run_granmix("theory /nonexistent/scene.toml").code == 2);
  CHECK(test::run_granmix("theory " + test::scene_path("bo1-fig02.toml") + " --bogus").code == 2);
  CHECK(test::run_granmix("frobnicate").code == 2);
}

TEST_CASE("a solver failure at one sweep point exits 3 naming the solver and the point - nothing written", "[compare]") {
  // m₂/m₁ = 10⁴, n₂ = 0.001, ε = 0.3: the rare heavy species runs away (it holds 99.8% of the energy and moves 2.4× as
  // fast as species 1, whose speed grid its kicks leave: the operator is singular): a clear error naming that state and
  // the levels that compute the mixture, not a number.
  const auto d = test::fresh_dir("sweep-failure");
  test::write_file(d / "s.toml", "[scene]\nname = \"s\"\n[mixture]\nspecies = [{ mass = 1, diameter = 1, density = 0.1 }, "
                                 "{ mass = 10000, diameter = 1, density = 0.001 }]\n[collisions]\nrestitution = 0.5\n"
                                 "[observables]\nd_ratio = true\n[theory]\nlevel = \"kinetic-converged-hcs\"\n"
                                 "sweep = { parameter = \"eps\", from = 0.3, to = 0.7, points = 2 }\n");
  const auto r = test::run_granmix("theory " + (d / "s.toml").string() + " --out " + (d / "out").string());
  INFO(r.output);
  CHECK(r.code == 3);
  CHECK(r.output.find("converged HCS") != std::string::npos);
  // The state where the operator turns singular: the heavy species runs away with the energy.
  CHECK(r.output.find("species 2 moves 2.71x as fast and holds 99.9% of the energy") != std::string::npos);
  CHECK(r.output.find("level kinetic or kinetic-converged computes this mixture") != std::string::npos);
  CHECK(r.output.find("(at the sweep point eps = 0.3)") != std::string::npos);
  CHECK(!std::filesystem::exists(d / "out" / "s" / "theory.tsv"));
}
