// The judging rule of compare/deviations.cpp on hand-made tables: the computed model error and its cap.
#include <catch2/catch.hpp>

#include <cmath>

#include "compare/deviations.hpp"
#include "model/model_error.hpp"

using namespace granmix;

namespace {

// One species at t = 1 and t = 2: theory 1.0 (its companion "converged" 1.10 at t = 2: a 10% computed model error
// there, none at t = 1), DSMC 1.05 ± 0.01 at both.
struct Tables {
  model::Table theory, dsmc;
  Tables() {
    theory.columns = {"t", "species", "msd", "msd_converged"};
    theory.rows = {{1.0, 1, 1.0, 1.0}, {2.0, 1, 1.0, 1.1}};
    dsmc.columns = {"t", "species", "msd", "msd_err"};
    dsmc.rows = {{1.0, 1, 1.05, 0.01}, {2.0, 1, 1.05, 0.01}};
  }
};

model::CompareQuantity msd(double cap) {
  model::CompareQuantity q;
  q.name = "msd", q.correction_from = {"converged"}, q.relative = 0.0, q.z = 4.0, q.model_error_max = cap;
  return q;
}

}  // namespace

TEST_CASE("deviations: a computed model error above model_error_max fails the point as unresolved, whatever DSMC says", "[compare]") {
  const Tables t;
  // No cap: t = 1 fails (5% off, 4σ = 4%), t = 2 passes inside its 10% computed bound.
  auto d = compare::deviations(t.theory, t.dsmc, {msd(INFINITY)});
  REQUIRE(d.size() == 2);
  CHECK(!d[0].pass);
  CHECK(d[1].pass);
  CHECK(d[1].model_error == Approx(0.1 / 1.0));  // |1.0 − 1.1| / |1.0|
  CHECK(d[0].resolved);
  CHECK(d[1].resolved);
  // A cap of 3%: t = 2's bound of 10% is more than the level claims to resolve, so it fails, unresolved; t = 1 is as before.
  d = compare::deviations(t.theory, t.dsmc, {msd(0.03)});
  CHECK(!d[1].pass);
  CHECK(!d[1].resolved);
  CHECK(d[0].resolved);
  const auto r = compare::summarise(d, {msd(0.03)});
  REQUIRE(r.size() == 1);
  CHECK(r[0].failed == 2);
  CHECK(r[0].unresolved == 1);
  // A cap above the computed model error changes nothing: t = 2 passes again.
  d = compare::deviations(t.theory, t.dsmc, {msd(0.11)});
  CHECK(d[1].pass);
  CHECK(d[1].resolved);
  // The summary names the cap beside the computed parts, the JSON carries it.
  CHECK(compare::tolerance_text(msd(0.03)) == "Δc≤0.03+4σ");
  CHECK(compare::tolerance_json(msd(0.03))["model_error_max"].get<double>() == 0.03);
  CHECK(!compare::tolerance_json(msd(INFINITY)).contains("model_error_max"));
  // deviations.tsv: a `resolved` column after model_error (extended, nothing renamed).
  const std::string tsv = compare::format_deviations("", "t", d);
  CHECK(tsv.substr(0, tsv.find('\n')).ends_with("\tmodel_error\tresolved"));
}

TEST_CASE("model error: the judged points' largest computed model error is the one deviations applies", "[compare]") {
  // model::max_model_error (model/model_error.hpp: what `granmix bench theory` reports beside a level's cost) over the
  // hand-made tables: the 10% companion change at t = 2 is the largest; deviations applies the same number there.
  Tables t;
  const model::CompareQuantity q = msd(INFINITY);
  CHECK(model::max_model_error(q, t.theory) == Approx(0.1));
  CHECK(compare::deviations(t.theory, t.dsmc, {q})[1].model_error == model::max_model_error(q, t.theory));
  // Judged points only: x_max = 1.5 leaves t = 1 (no correction), a species the quantity does not cover leaves none.
  model::CompareQuantity early = q, other = q;
  early.x_max = 1.5, other.species = {2};
  CHECK(model::max_model_error(early, t.theory) == 0.0);
  CHECK(model::max_model_error(other, t.theory) == 0.0);
  // `relative` and the level's own error column add; a NaN there or in a companion counts as none (stricter).
  t.theory.columns.push_back("msd_error");
  t.theory.rows[0].push_back(0.02), t.theory.rows[1].push_back(std::nan(""));
  model::CompareQuantity own = q;
  own.error_column = "msd_error", own.relative = 0.01;
  CHECK(model::max_model_error(own, t.theory) == Approx(0.11));  // t = 2: 0.01 + 0.1 + 0 > t = 1: 0.01 + 0 + 0.02
  t.theory.rows[1][3] = std::nan("");
  CHECK(model::max_model_error(own, t.theory) == Approx(0.03));
}
