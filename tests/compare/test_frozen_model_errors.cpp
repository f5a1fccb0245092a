// Frozen model errors (compare/frozen_model_errors.hpp, docs/judging.md "Frozen model errors"): the bounds of the paper
// scenes come from a reviewed table, so a bug in the judged level moves its curve, not its bound, and the drift check
// sees the bug in the live computation.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "compare/deviations.hpp"
#include "compare/frozen_model_errors.hpp"
#include "model/errors.hpp"
#include "run_cli.hpp"
#include "theory/scene_theory.hpp"

using namespace granmix;
using namespace granmix::compare;

namespace {

// v1/MG's mg-fig01: γ and T judged at kinetic-cooling3 with companions of other closures (kinetic, cooling4).
model::Scene mg_fig01() { return theory::load_scene(test::scene_path("mg-fig01.toml")); }

}  // namespace

TEST_CASE("frozen model errors: the committed table is the live computation, bit for bit, and reads back exactly", "[compare]") {
  const model::Scene s = mg_fig01();
  const FrozenModelErrors live = compute_model_errors(s, theory::run_theory(s).table);
  const std::optional<FrozenModelErrors> frozen = load_frozen_model_errors(s);
  REQUIRE(frozen);
  CHECK(largest_drift(*frozen, live).first == 0.0);
  const FrozenModelErrors back = parse_model_errors(format_model_errors(s, live), "x.tsv");
  for (const auto& [q, points] : live.points)
    for (const FrozenPoint& p : points) CHECK(back.at(q, p.species, p.x) == p.model_error);
}

TEST_CASE("frozen model errors: a planted 2% bug in the judged level moves the curve, not the bound, and the drift check fails", "[compare]") {
  const model::Scene s = mg_fig01();
  const model::Table good = theory::run_theory(s).table;
  model::Table bug = good;  // the judged level's γ 2% high; its companions (other closures) unchanged
  const int g = bug.column("gamma");
  REQUIRE(g >= 0);
  for (auto& row : bug.rows) row[std::size_t(g)] *= 1.02;
  const FrozenModelErrors frozen = compute_model_errors(s, good);
  const FrozenModelErrors live = compute_model_errors(s, bug);
  // Live, the bound grows with the bug (|1.02γ − γ_companion| ≈ 2% more): a drift far beyond 5%.
  const auto [drift, where] = largest_drift(frozen, live);
  INFO(where);
  CHECK(drift > default_model_error_drift);
  // Judged against the frozen table, every point keeps its reviewed bound while its deviation moves.
  model::Table dsmc;  // DSMC equal to the good theory, error bars of 0.1%
  dsmc.columns = {good.columns[0], "species", "gamma", "gamma_err"};
  const int sp = good.column("species");
  for (const auto& row : good.rows) dsmc.rows.push_back({row[0], row[std::size_t(sp)], row[std::size_t(good.column("gamma"))], 1e-3 * std::abs(row[std::size_t(good.column("gamma"))])});
  std::vector<model::CompareQuantity> gamma;
  for (const auto& q : s.compare)
    if (q.name == "gamma") gamma.push_back(q);
  REQUIRE(!gamma.empty());
  const auto with_frozen = deviations(bug, dsmc, gamma, &frozen), live_bound = deviations(bug, dsmc, gamma);
  REQUIRE(with_frozen.size() == live_bound.size());
  std::size_t wider = 0;
  for (std::size_t i = 0; i < with_frozen.size(); ++i) {
    CHECK(with_frozen[i].model_error == frozen.at(with_frozen[i].quantity, with_frozen[i].species, with_frozen[i].t).value());
    wider += live_bound[i].model_error > with_frozen[i].model_error * 1.5;
  }
  CHECK(wider > 0);
}

TEST_CASE("frozen model errors: a paper scene edited after its table was written is refused naming the command - exit 2", "[compare]") {
  model::Scene s = mg_fig01();
  s.text += "\n# edited\n";
  try {
    load_frozen_model_errors(s);
    FAIL("accepted a table of another version of the scene");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("granmix model-errors --write") != std::string::npos);
  }
}
