// The scheduler (compare/scheduler.hpp): DSMC units of every scene over threads and MPI ranks give
// the same bytes as one process; units go longest first by an estimate that tracks the real cost.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

#include "compare/run_cli.hpp"
#include "compare/scheduler.hpp"
#include "compare/tsv_reader.hpp"
#include "dsmc/scene_dsmc.hpp"
#include "model/scene.hpp"
#include "theory/scene_theory.hpp"

using namespace granmix;

TEST_CASE("scheduler, one process: records independent of threads, longest first, estimates within 25% of the collisions",
          "[compare][dsmc][slow]") {
  const model::Scene s = theory::load_scene(test::scene_path("bo1-fig05.toml"));  // a sweep: 3 ensembles x 8 replicas
  dsmc::RunOptions run;
  const auto setups = dsmc::plan_scene_dsmc(s, run);
  REQUIRE(setups.size() == 3);
  const auto one = compare::scheduler::run_units(setups, 1), two = compare::scheduler::run_units(setups, 2);
  REQUIRE(one.units.size() == 24);
  CHECK(two.threads == 2);
  for (const auto& [key, rec] : one.records) {
    const dsmc::ReplicaRecord* other = two.find(key.first, key.second);
    REQUIRE(other != nullptr);
    CHECK(rec.T == other->T);
    CHECK(rec.msd == other->msd);
    CHECK(rec.accepted == other->accepted);
  }
  for (std::size_t i = 1; i < one.units.size(); ++i) CHECK(one.units[i - 1].estimated_collisions >= one.units[i].estimated_collisions);
  // The estimate (Haff's law from the initial rates) orders the work; measured here within 4% for
  // these settled runs, bound 25%: a wrong rate (a factor 2 in ν or ξ) breaks it.
  for (const auto& u : one.units) CHECK(std::abs(u.estimated_collisions / u.collisions - 1.0) < 0.25);
  // The tables built from gathered replicas are those of a run that computes its own.
  run.source = &one;
  const dsmc::DsmcRun gathered = dsmc::run_scene_dsmc(s, run);
  run.source = nullptr;
  run.threads = 2;
  const dsmc::DsmcRun own = dsmc::run_scene_dsmc(s, run);
  REQUIRE(gathered.table.rows.size() == own.table.rows.size());
  for (std::size_t i = 0; i < own.table.rows.size(); ++i)  // bit for bit, nan (species-1 ratio rows) included
    CHECK(std::memcmp(gathered.table.rows[i].data(), own.table.rows[i].data(), own.table.rows[i].size() * sizeof(double)) == 0);
}

#ifdef GRANMIX_MPIEXEC
namespace {
using test::run_mpi;

nlohmann::json without_timings(nlohmann::json j) {
  for (const char* k : {"theory_seconds", "dsmc_seconds", "collisions_per_second"}) j.erase(k);
  return j;
}
}  // namespace

TEST_CASE("mpirun -n 3 granmix validate and compare: every TSV and report identical to one process - work spread over the ranks",
          "[compare][dsmc]") {
  const auto d = test::fresh_dir("mpi-validate");
  std::filesystem::create_directories(d / "scenes");
  for (const char* f : {"bo1-fig05.toml", "mg-fig01.toml"}) std::filesystem::copy(test::scene_path(f), d / "scenes" / f);
  const auto serial = test::run_granmix("validate --scenes " + (d / "scenes").string() + " --out " + (d / "serial").string());
  const auto mpi = run_mpi(3, "validate --scenes " + (d / "scenes").string() + " --out " + (d / "mpi").string());
  INFO(serial.output << mpi.output);
  REQUIRE(serial.code == 0);
  REQUIRE(mpi.code == 0);
  for (const char* scene : {"bo1-fig05", "mg-fig01"}) {
    for (const char* f : {"theory.tsv", "dsmc.tsv", "deviations.tsv"}) {
      INFO(scene << "/" << f);
      const std::string a = test::data_lines(d / "serial" / scene / f);
      CHECK(!a.empty());
      CHECK(a == test::data_lines(d / "mpi" / scene / f));
    }
    const auto a = nlohmann::json::parse(std::ifstream(d / "serial" / scene / "report.json"));
    const auto b = nlohmann::json::parse(std::ifstream(d / "mpi" / scene / "report.json"));
    CHECK(without_timings(a) == without_timings(b));
  }
  // granmix compare of one scene under MPI: the same tables as the serial validation wrote.
  const auto one = run_mpi(3, "compare " + (d / "scenes" / "bo1-fig05.toml").string() + " --out " + (d / "mpi-compare").string());
  INFO(one.output);
  CHECK(one.code == 0);
  for (const char* f : {"dsmc.tsv", "deviations.tsv"})
    CHECK(test::data_lines(d / "serial" / "bo1-fig05" / f) == test::data_lines(d / "mpi-compare" / "bo1-fig05" / f));
  const auto summary = nlohmann::json::parse(std::ifstream(d / "mpi" / "summary.json"));
  CHECK(summary["ranks"] == 3);
  CHECK(summary["dsmc_units"] == 56);  // bo1-fig05: 3 points x 8 quick replicas; mg-fig01: 32
  // Units ran on more than one rank (the rank column of units.tsv).
  std::ifstream units(d / "mpi" / "units.tsv");
  std::set<std::string> used;
  for (std::string line; std::getline(units, line);)
    if (line.rfind("#", 0) != 0 && line.rfind("unit\t", 0) != 0) used.insert(line.substr(line.rfind('\t') + 1));
  CHECK(used.size() >= 2);
}

TEST_CASE("mpirun -n 2 granmix dsmc with one thread per rank: the bytes of one process with two threads", "[compare][dsmc]") {
  const auto d = test::fresh_dir("mpi-dsmc");
  const std::string scene = test::scene_path("bo1-fig02.toml");
  const auto a = test::run_granmix("dsmc " + scene + " --out " + (d / "a").string() + " --threads 2 --seed 5");
  const auto b = run_mpi(2, "dsmc " + scene + " --out " + (d / "b").string() + " --threads 1 --seed 5");
  INFO(a.output << b.output);
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  CHECK(b.output.find("2 rank(s) x 1 thread(s)") != std::string::npos);
  CHECK(test::data_lines(d / "a" / "bo1-fig02" / "dsmc.tsv") == test::data_lines(d / "b" / "bo1-fig02" / "dsmc.tsv"));
}
#endif
