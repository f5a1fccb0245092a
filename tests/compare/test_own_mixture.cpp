// One's own mixture (docs/quickstart.md): what is forgiven where it is safe (whole-number floats as counts, a total
// density with fractions, an optional [dsmc] paper table, an optional why outside the paper scenes), what is said
// instead of done silently (the particle total the split gives, too few replicas, outputs moved aside), what is
// refused with a hint (typos, a bad --seed), and the default comparison of a scene without [compare].
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "compare/deviations.hpp"
#include "run_cli.hpp"

using namespace granmix;

namespace {

// A own_small ternary of the fractions form: runs `compare` in about a second.
const std::string own_small = R"([scene]
name = "own"
[mixture]
density = 0.05
fraction = [1, 1, 2]
species = [{ mass = 1, diameter = 1 }, { mass = 4, diameter = 1.3 }, { mass = 20, diameter = 2 }]
[collisions]
restitution = 0.7
[time]
end = 2
points = 4
spacing = "linear"
[observables]
temperatures = true
[dsmc]
quick = { particles = 400, replicas = 8 }
)";

std::string own_replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

std::string own_read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The data lines of a table (its '#' provenance lines dropped).
std::string own_data_lines(const std::filesystem::path& p) {
  std::istringstream in(own_read(p));
  std::string line, out;
  while (std::getline(in, line))
    if (line.empty() || line.front() != '#') out += line + "\n";
  return out;
}

struct OwnRun {
  std::filesystem::path dir;
  test::CliResult r;
};

OwnRun own_run(const std::string& name, const std::string& command, const std::string& text, const std::string& extra = "") {
  OwnRun x{test::fresh_dir(name), {}};
  test::write_file(x.dir / "s.toml", text);
  x.r = test::run_granmix(command + " " + (x.dir / "s.toml").string() + " --out " + (x.dir / "out").string() + " " + extra);
  return x;
}

bool own_has(const std::string& output, const std::string& text) { return output.find(text) != std::string::npos; }

}  // namespace

TEST_CASE("own mixture: a whole-number float is a count - 1.5 is refused naming the value", "[compare]") {
  const auto ok = own_run("float-count", "theory", own_replace(own_small, "points = 4", "points = 4e0"));
  INFO(ok.r.output);
  CHECK(ok.r.code == 0);
  CHECK(own_has(ok.r.output, "16 rows"));  // 4 times x (3 species + species 0)
  const auto bad = own_run("float-count-bad", "theory", own_replace(own_small, "points = 4", "points = 1.5"));
  INFO(bad.r.output);
  CHECK(bad.r.code == 2);
  CHECK(own_has(bad.r.output, ":11: time.points: expected an integer, found 1.5 (not a whole number) (allowed: an integer in [1, 100000])"));
  CHECK(!std::filesystem::exists(bad.dir / "out"));
  const auto big = own_run("float-count-range", "theory", own_replace(own_small, "points = 4", "points = 2.5e5"));
  CHECK(big.r.code == 2);
  CHECK(own_has(big.r.output, "time.points: value 250000 out of range"));
}

TEST_CASE("own mixture: particles = 2e2 runs 200 particles - a total the split by density misses is stated", "[compare][dsmc]") {
  // 1:1:2 of 400 splits exactly; 1:1:1 of 200 gives 67 + 67 + 67 = 201.
  const auto exact = own_run("split-exact", "dsmc", own_replace(own_small, "particles = 400", "particles = 4e2"));
  INFO(exact.r.output);
  CHECK(exact.r.code == 0);
  CHECK(own_has(exact.r.output, "400 particles x 8 replicas"));
  CHECK(!own_has(exact.r.output, "warning"));
  const auto odd = own_run("split-rounded", "dsmc", own_replace(own_replace(own_small, "fraction = [1, 1, 2]", "fraction = [1, 1, 1]"), "particles = 400", "particles = 200"));
  INFO(odd.r.output);
  CHECK(odd.r.code == 0);
  CHECK(own_has(odd.r.output, "201 particles x 8 replicas"));
  CHECK(own_has(odd.r.output, "warning: dsmc.quick.particles = 200 split over the species by density (each count rounded) gives 201 particles; the run uses 201"));
}

TEST_CASE("own mixture: the fractions form gives the same mixture as the densities written out", "[compare]") {
  const auto fractions = own_run("fractions", "theory", own_small);
  const auto written = own_run("fractions-written", "theory",
                           own_replace(own_replace(own_small, "density = 0.05\nfraction = [1, 1, 2]\n", ""),
                                   "species = [{ mass = 1, diameter = 1 }, { mass = 4, diameter = 1.3 }, { mass = 20, diameter = 2 }]",
                                   "species = [{ mass = 1, diameter = 1, density = 0.0125 }, { mass = 4, diameter = 1.3, density = 0.0125 }, "
                                   "{ mass = 20, diameter = 2, density = 0.025 }]"));
  INFO(fractions.r.output << written.r.output);
  REQUIRE(fractions.r.code == 0);
  REQUIRE(written.r.code == 0);
  CHECK(own_data_lines(fractions.dir / "out" / "own" / "theory.tsv") == own_data_lines(written.dir / "out" / "own" / "theory.tsv"));
  // Without fraction the species share the total equally.
  const auto equal = own_run("fractions-equal", "theory", own_replace(own_small, "fraction = [1, 1, 2]\n", ""));
  CHECK(equal.r.code == 0);
}

TEST_CASE("own mixture: the fractions form's mistakes are refused naming the key - exit 2", "[compare]") {
  struct Case {
    std::string text, expect;
  };
  const std::vector<Case> cases = {
      {own_replace(own_small, "density = 0.05\n", ""), ":4: mixture.fraction: needs the total number density beside it"},
      {own_replace(own_small, "fraction = [1, 1, 2]", "fraction = [1, 2]"), ":5: mixture.fraction: 2 values for 3 species (allowed: one fraction > 0 per species)"},
      {own_replace(own_small, "fraction = [1, 1, 2]", "fraction = [1, 0, 2]"), "mixture.fraction: value 0 must be positive"},
      {own_replace(own_small, "{ mass = 4, diameter = 1.3 }", "{ mass = 4, diameter = 1.3, density = 0.1 }"),
       "mixture.species[2].density: given here and as the total [mixture] density"},
  };
  for (const Case& c : cases) {
    const auto x = own_run("fractions-bad", "theory", c.text);
    INFO(c.expect << "\n" << x.r.output);
    CHECK(x.r.code == 2);
    CHECK(own_has(x.r.output, c.expect));
    CHECK(!std::filesystem::exists(x.dir / "out"));
  }
}

TEST_CASE("own mixture: a typo is named - unknown keys and the required key it hides", "[compare]") {
  struct Case {
    std::string text, expect;
  };
  const std::vector<Case> cases = {
      {own_replace(own_small, "restitution = 0.7", "restitutoin = 0.7"),
       "collisions.restitution: missing; found unknown key \"restitutoin\": did you mean \"restitution\"?"},
      {own_replace(own_small, "spacing = \"linear\"", "spacng = \"linear\""), ":12: time.spacng: unknown key; did you mean \"spacing\"?"},
      {own_replace(own_small, "[dsmc]", "[dsmcc]"), "dsmcc: unknown key; did you mean \"dsmc\"?"},
      {own_replace(own_small, "particles = 400", "partcles = 400"),
       "dsmc.quick.particles: missing; found unknown key \"partcles\": did you mean \"particles\"?"},
      {own_replace(own_small, "temperatures = true", "temperature = true\nmsd = true"), "observables.temperature: unknown key; did you mean \"temperatures\"?"},
      {own_replace(own_small, "[observables]", "[observable]"), "observables: missing; found unknown key \"observable\": did you mean \"observables\"?"},
      {own_replace(own_small, "end = 2", "end = 2\nfoo = 1"), "time.foo: unknown key (allowed:"},  // nothing near: no guess
  };
  for (const Case& c : cases) {
    const auto x = own_run("typo", "theory", c.text);
    INFO(c.expect << "\n" << x.r.output);
    CHECK(x.r.code == 2);
    CHECK(own_has(x.r.output, c.expect));
    CHECK(std::count(x.r.output.begin(), x.r.output.end(), '\n') == 1);
    CHECK(!std::filesystem::exists(x.dir / "out"));
  }
}

TEST_CASE("own mixture: without [dsmc] paper, --fidelity paper runs the quick settings and says so", "[compare][dsmc]") {
  const auto x = own_run("no-paper", "dsmc", own_small, "--fidelity paper");
  INFO(x.r.output);
  CHECK(x.r.code == 0);
  CHECK(own_has(x.r.output, "warning: [dsmc] has no paper table: --fidelity paper runs the quick settings (400 particles x 8 replicas)"));
  const auto quick = own_run("no-paper-quick", "dsmc", own_small);
  CHECK(!own_has(quick.r.output, "no paper table"));
}

TEST_CASE("own mixture: theory never needs [dsmc] - compare refuses [compare] without it - exit 2", "[compare]") {
  const std::string no_dsmc = own_replace(own_small, "[dsmc]\nquick = { particles = 400, replicas = 8 }\n",
                                      "[compare]\nquantities = [{ name = \"T\" }]\n");
  const auto t = own_run("no-dsmc-theory", "theory", no_dsmc);
  INFO(t.r.output);
  CHECK(t.r.code == 0);
  const auto c = own_run("no-dsmc-compare", "compare", no_dsmc);
  INFO(c.r.output);
  CHECK(c.r.code == 2);
  CHECK(own_has(c.r.output, "s.toml: compare: judging needs a [dsmc] table (allowed: [dsmc] with quick = { particles = N, replicas = R })"));
  CHECK(!std::filesystem::exists(c.dir / "out" / "own"));
}

TEST_CASE("own mixture: why is optional outside compare/scenes, generated when absent", "[compare][dsmc]") {
  const auto x = own_run("no-why", "compare", own_small + "[compare]\nquantities = [{ name = \"T\", relative = 0.05, z = 4 }]\n");
  INFO(x.r.output);
  CHECK(x.r.code <= 1);
  const auto rep = nlohmann::json::parse(std::ifstream(x.dir / "out" / "own" / "report.json"));
  CHECK(rep["quantities"]["T"]["why"].get<std::string>() == "no why given in the scene: model error relative = 0.05, z = 4");
}

TEST_CASE("own mixture: why stays required in compare/scenes/ - exit 2 naming the key", "[compare]") {
  const auto d = test::fresh_dir("paper-why");
  std::filesystem::create_directories(d / "compare" / "scenes");
  const auto scene = d / "compare" / "scenes" / "s.toml";
  test::write_file(scene, own_small + "[compare]\nquantities = [{ name = \"T\", relative = 0.05, z = 4 }]\n");
  const auto r = test::run_granmix("compare " + scene.string() + " --out " + (d / "out").string());
  INFO(r.output);
  CHECK(r.code == 2);
  CHECK(own_has(r.output, "s.toml:18: compare.quantities[1].why: missing (allowed: a string)"));
  CHECK(!std::filesystem::exists(d / "out" / "own"));
}

TEST_CASE("honest statistics: fewer than 8 replicas warn in the output and in report.json", "[compare][dsmc]") {
  const auto x = own_run("few-replicas", "compare", own_replace(own_small, "replicas = 8", "replicas = 4"));
  INFO(x.r.output);
  CHECK(x.r.code <= 1);
  CHECK(own_has(x.r.output, "warning: 4 replicas: z needs >= 8 replicas to mean anything (docs/judging.md §6)"));
  const auto rep = nlohmann::json::parse(std::ifstream(x.dir / "out" / "own" / "report.json"));
  REQUIRE(rep["warnings"].size() == 1);
  CHECK(own_has(rep["warnings"][0].get<std::string>(), "z needs >= 8 replicas"));
  const auto enough = own_run("enough-replicas", "compare", own_small);
  const auto rep8 = nlohmann::json::parse(std::ifstream(enough.dir / "out" / "own" / "report.json"));
  CHECK(rep8["warnings"].empty());
}

TEST_CASE("honest statistics: validate's summary.json carries each scene's warnings", "[compare][dsmc]") {
  const auto d = test::fresh_dir("validate-warnings");
  std::filesystem::create_directories(d / "scenes");
  test::write_file(d / "scenes" / "own.toml", own_replace(own_small, "replicas = 8", "replicas = 4"));
  const auto r = test::run_granmix("validate --scenes " + (d / "scenes").string() + " --out " + (d / "out").string());
  INFO(r.output);
  CHECK(r.code <= 1);
  CHECK(own_has(r.output, "warning: 4 replicas: z needs >= 8 replicas"));
  const auto summary = nlohmann::json::parse(std::ifstream(d / "out" / "summary.json"));
  REQUIRE(summary["scenes"].size() == 1);
  REQUIRE(summary["scenes"][0]["warnings"].size() == 1);
  CHECK(own_has(summary["scenes"][0]["warnings"][0].get<std::string>(), "z needs >= 8 replicas"));
}

TEST_CASE("honest statistics: one replica - errors nan, not judged, never a pass with z = inf", "[compare][dsmc]") {
  const auto x = own_run("one-replica", "compare", own_replace(own_small, "replicas = 8", "replicas = 1"));
  INFO(x.r.output);
  CHECK(x.r.code == 1);  // no verdict is no pass
  CHECK(own_has(x.r.output, "T: not judged: no DSMC error bar (1 replica)"));
  CHECK(own_has(x.r.output, "warning: 1 replica: no error bar, no z"));
  const auto rep = nlohmann::json::parse(std::ifstream(x.dir / "out" / "own" / "report.json"));
  CHECK(rep["pass"] == false);
  CHECK(rep["quantities"]["T"]["judged"] == 0);
  CHECK(rep["quantities"]["T"]["max_z"].is_null());
  CHECK(rep["quantities"]["T"]["not_judged"] == "no DSMC error bar (1 replica)");
  CHECK(own_has(own_read(x.dir / "out" / "own" / "dsmc.tsv"), "\tnan"));
  CHECK(!own_has(own_read(x.dir / "out" / "own" / "deviations.tsv"), "inf"));
}

TEST_CASE("honest statistics: a DSMC error at rounding level does not make z 1e10", "[compare]") {
  model::Table theory, dsmc;
  theory.columns = {"t", "species", "T"};
  theory.rows = {{1.0, 1, 1.0}};
  dsmc.columns = {"t", "species", "T", "T_err"};
  dsmc.rows = {{1.0, 1, 1.0 + 4e-16, 0.0}};  // replicas that agree to the last digits
  model::CompareQuantity q;
  q.name = "T", q.theory = "T", q.relative = 0.0, q.z = 4.0;
  const auto d = compare::deviations(theory, dsmc, {q});
  REQUIRE(d.size() == 1);
  CHECK(std::isfinite(d[0].z));
  CHECK(std::abs(d[0].z) < 1.0);  // the error floored at 1e-12 relative
  CHECK(d[0].pass);
  dsmc.rows = {{1.0, 1, 1.0 + 4e-16, NAN}};  // one replica: no error bar
  const auto none = compare::deviations(theory, dsmc, {q});
  REQUIRE(none.size() == 1);
  CHECK(!none[0].judged);
  CHECK(std::isnan(none[0].z));
}

TEST_CASE("honest statistics: --seed outside [0, 2^53] is refused naming the range - exit 2", "[compare]") {
  const std::string scene = test::scene_path("bo1-fig02.toml");
  for (const char* seed : {"-1", "9007199254740993", "abc", "1.5"})
    for (const char* command : {"dsmc", "compare", "validate"}) {
      const auto d = test::fresh_dir("seed");
      const std::string args = std::string(command) + (std::string(command) == "validate" ? "" : " " + scene) + " --seed " + seed + " --out " + (d / "out").string();
      const auto r = test::run_granmix(args);
      INFO(args << "\n" << r.output);
      CHECK(r.code == 2);
      CHECK(own_has(r.output, "--seed"));
      CHECK(own_has(r.output, "(allowed: an integer in [0, 9007199254740992] = [0, 2^53]"));
      CHECK(!std::filesystem::exists(d / "out"));
    }
  const auto b = test::run_granmix("bench schedule --seed -1");
  CHECK(b.code == 2);
}

TEST_CASE("outputs cannot mix: another scene file's folder is moved aside, with a warning naming both", "[compare][dsmc]") {
  const auto d = test::fresh_dir("mix-outputs");
  test::write_file(d / "a.toml", own_small);
  const std::string out = (d / "out").string();
  REQUIRE(test::run_granmix("dsmc " + (d / "a.toml").string() + " --out " + out).code == 0);
  REQUIRE(test::run_granmix("theory " + (d / "a.toml").string() + " --out " + out).code == 0);  // same scene: kept together
  CHECK(std::filesystem::exists(d / "out" / "own" / "dsmc.tsv"));
  // The same [scene] name, another file (edited): its theory must not sit beside the old dsmc.tsv.
  test::write_file(d / "b.toml", own_replace(own_small, "restitution = 0.7", "restitution = 0.8"));
  const auto r = test::run_granmix("theory " + (d / "b.toml").string() + " --out " + out);
  INFO(r.output);
  CHECK(r.code == 0);
  CHECK(own_has(r.output, "warning: " + out + "/own/ held outputs of another scene file ("));
  CHECK(own_has(r.output, "moved to " + out + "/own.previous-"));
  CHECK(!std::filesystem::exists(d / "out" / "own" / "dsmc.tsv"));
  CHECK(std::filesystem::exists(d / "out" / "own" / "theory.tsv"));
  std::size_t previous = 0;
  for (const auto& e : std::filesystem::directory_iterator(d / "out"))
    if (e.path().filename().string().rfind("own.previous-", 0) == 0) {
      ++previous;
      CHECK(std::filesystem::exists(e.path() / "dsmc.tsv"));
      CHECK(std::filesystem::exists(e.path() / "theory.tsv"));
    }
  CHECK(previous == 1);
  // compare of the edited scene: judged on its own theory and DSMC; report.json carries the move when there is one.
  const auto c = test::run_granmix("compare " + (d / "a.toml").string() + " --out " + out);
  INFO(c.output);
  CHECK(own_has(c.output, "held outputs of another scene file"));
  const auto rep = nlohmann::json::parse(std::ifstream(d / "out" / "own" / "report.json"));
  CHECK(own_has(rep["warnings"][0].get<std::string>(), "moved to"));
}

TEST_CASE("default comparison: without [compare] every asked quantity is judged against the level's companions at z = 4", "[compare][dsmc]") {
  const auto x = own_run("default-compare", "compare", own_replace(own_small, "temperatures = true", "temperatures = true\nmsd = true") +
                                                        "[theory]\nlevel = \"kinetic\"\n");
  INFO(x.r.output);
  CHECK(x.r.code <= 1);
  const auto rep = nlohmann::json::parse(std::ifstream(x.dir / "out" / "own" / "report.json"));
  for (const char* q : {"T", "msd"}) {
    INFO(q);
    REQUIRE(rep["quantities"].contains(q));
    CHECK(rep["quantities"][q]["tolerance"]["z"] == 4.0);
    CHECK(rep["quantities"][q]["tolerance"]["relative"] == 0.0);
    CHECK(own_has(rep["quantities"][q]["why"].get<std::string>(), "default comparison (the scene has no [compare])"));
    CHECK(own_has(rep["quantities"][q]["tolerance"]["correction_from"].dump(), "paper"));
  }
  CHECK(std::filesystem::exists(x.dir / "out" / "own" / "deviations.tsv"));
}

TEST_CASE("examples: each of examples/ runs granmix compare at quick fidelity in under 30 s and passes", "[compare][dsmc]") {
  for (const char* name : {"ternary", "power_law", "enskog_binary", "settled_sweep"}) {
    const auto d = test::fresh_dir(std::string("example-") + name);
    const std::string scene = std::string(GRANMIX_SOURCE_DIR) + "/examples/" + name + ".toml";
    const auto start = std::chrono::steady_clock::now();
    const auto r = test::run_granmix("compare " + scene + " --out " + (d / "out").string() + " --threads 1");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    INFO(name << " (" << seconds << " s):\n" << r.output);
    CHECK(r.code == 0);
    CHECK(seconds < 30.0);
    CHECK(!own_has(r.output, "warning"));
  }
}

TEST_CASE("own mixture: a fresh scene of fractions, without level, [compare] or [dsmc] paper, is judged with its level chosen and said", "[compare][dsmc]") {
  // own_small with 4 replicas: the level chosen by auto, a default comparison, a warning for the replicas.
  const auto x = own_run("fresh-user", "compare", own_replace(own_small, "replicas = 8", "replicas = 4"));
  INFO(x.r.output);
  CHECK(x.r.code <= 1);
  CHECK(own_has(x.r.output, "level: auto chose "));
  CHECK(own_has(x.r.output, "warning: 4 replicas: z needs >= 8 replicas"));
  const auto rep = nlohmann::json::parse(std::ifstream(x.dir / "out" / "own" / "report.json"));
  CHECK(rep["level"] != "auto");
  CHECK(own_has(rep["level_choice"].get<std::string>(), "auto chose " + rep["level"].get<std::string>()));
  REQUIRE(rep["quantities"].contains("T"));
  CHECK(own_has(rep["quantities"]["T"]["why"].get<std::string>(), "level " + rep["level"].get<std::string>()));
  CHECK(own_has(own_read(x.dir / "out" / "own" / "theory.tsv"), "# level: auto chose "));
  // its own page: the verdict, the level and why, the warning, the rule as compare/deviations.cpp applies it (a sum)
  const std::string page = own_read(x.dir / "out" / "own" / "index.html");
  CHECK(own_has(page, "auto chose "));
  CHECK(own_has(page, "4 replicas: z needs"));
  CHECK(own_has(page, "≤ model error · |theory| + z · dsmc_err"));
  CHECK(!own_has(page, "max(relative"));
  CHECK(own_has(page, "href=\"theory.tsv\""));
}

TEST_CASE("own mixture: a scene read from standard input with - gives the file's tables", "[compare][dsmc]") {
  const auto file = own_run("stdin-file", "compare", own_small);
  const auto d = test::fresh_dir("stdin-pipe");
  test::write_file(d / "in.toml", own_small);
  const auto piped = test::run_granmix("compare - --out " + (d / "out").string() + " < " + (d / "in.toml").string());
  INFO(piped.output);
  CHECK(piped.code == file.r.code);
  for (const char* f : {"theory.tsv", "dsmc.tsv", "deviations.tsv"}) CHECK(own_data_lines(d / "out" / "own" / f) == own_data_lines(file.dir / "out" / "own" / f));
  CHECK(own_has(own_read(d / "out" / "own" / "theory.tsv"), "file: <stdin>"));
  const auto empty = test::run_granmix("theory - --out " + (d / "empty").string() + " < /dev/null");
  CHECK(empty.code == 2);
  CHECK(own_has(empty.output, "<stdin>: the scene given as - is empty"));
  CHECK(!std::filesystem::exists(d / "empty"));
}

TEST_CASE("own mixture: a judged quantity the scene does not measure, or whose range holds no sample time, is refused at load - exit 2", "[compare]") {
  const std::string judged_msd = own_small + "[compare]\nquantities = [{ name = \"msd\" }]\n";
  const auto unmeasured = own_run("unmatched-observable", "compare", judged_msd);
  INFO(unmeasured.r.output);
  CHECK(unmeasured.r.code == 2);
  CHECK(own_has(unmeasured.r.output, "compare: quantity \"msd\" is judged, but [observables] does not ask for it (allowed: observables.msd = true"));
  CHECK(!std::filesystem::exists(unmeasured.dir / "out"));
  const auto late = own_run("unmatched-range", "compare", own_small + "[compare]\nquantities = [{ name = \"T\", t_min = 5 }]\n");
  INFO(late.r.output);
  CHECK(late.r.code == 2);
  CHECK(own_has(late.r.output, "compare: quantity \"T\" judges t >= 5, which holds none of the sample times"));
  CHECK(!std::filesystem::exists(late.dir / "out"));
}

TEST_CASE("progress: one long replica reports its share of the collisions while it runs on a terminal, and a pipe gets none unless asked", "[compare][dsmc]") {
  if (std::system("command -v script > /dev/null 2>&1") != 0) {
    WARN("no `script` (util-linux) to give the run a terminal: skipped");
    return;
  }
  const auto d = test::fresh_dir("progress");
  test::write_file(d / "big.toml", own_replace(own_replace(own_small, "particles = 400, replicas = 8", "particles = 1e6, replicas = 1"), "end = 2", "end = 30"));
  // script gives granmix a terminal; the line is rewritten with \r at most once a second
  const std::string cmd = "script -qc '" + std::string(GRANMIX_EXE) + " dsmc " + (d / "big.toml").string() + " --out " + (d / "out").string() +
                          " --threads 1' /dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  std::string out;
  for (int ch; (ch = std::fgetc(p)) != EOF;) out += char(ch);
  CHECK(pclose(p) == 0);
  INFO(out);
  // a line of the replica in flight (0 of 1 units done) with a share above 0 and below 100%
  bool in_flight = false;
  for (std::size_t at = 0; (at = out.find("DSMC: 0/1 units, ", at)) != std::string::npos; ++at) {
    const int share = std::atoi(out.c_str() + at + 17);
    in_flight = in_flight || (share > 0 && share < 100);
  }
  CHECK(in_flight);
  CHECK(own_has(out, "DSMC: 1/1 units, 100% of the estimated collisions"));
  // off a terminal (here a pipe) the run is quiet unless GRANMIX_PROGRESS=1 asks
  const std::string small = " dsmc " + (d / "small.toml").string() + " --out " + (d / "out2").string();
  test::write_file(d / "small.toml", own_small);
  CHECK(!own_has(test::run_granmix(small).output, "of the estimated collisions"));
  const std::string asked = "GRANMIX_PROGRESS=1 " + std::string(GRANMIX_EXE) + small + " 2>&1";
  FILE* q = popen(asked.c_str(), "r");
  REQUIRE(q != nullptr);
  std::string lines;
  for (int ch; (ch = std::fgetc(q)) != EOF;) lines += char(ch);
  CHECK(pclose(q) == 0);
  CHECK(own_has(lines, "DSMC: 8/8 units, 100% of the estimated collisions"));
}
