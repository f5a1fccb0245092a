#pragma once
// The judged theory's computed model error at a point of its table (docs/judging.md, "tolerances", docs/architecture.md §4): the quantity's
// `relative`, plus the largest |theory − theory_<c>|/|theory| over its `correction_from` columns c (the corrections of
// independent truncations: the largest), plus its `error_column` there (the level's own computed part). One place for
// it: compare (deviations.cpp: the tolerance of each judged point) and bench (`granmix bench theory`: each level's
// error beside its cost) read the same number.
#include <string>
#include <vector>

#include "scene.hpp"
#include "table.hpp"

namespace granmix::model {

// The theory column that predicts the quantity (its `theory`; default its `name`).
const std::string& predicted_name(const CompareQuantity& q);
// Whether a quantity judges this species' rows (its `species`; empty: every row).
bool covers(const CompareQuantity& q, int species);
// Whether it judges the row at x (the table's first column: t, v* or the swept value) of a species it covers:
// x in [t_min, x_max]; rows outside are reported, not judged.
bool judges(const CompareQuantity& q, double x);

class ModelError {
 public:
  // The columns of `theory` the quantity reads, located once: its prediction (`theory`, default `name`), the
  // corrections' `<prediction>_<c>` and its error column. A column the table lacks counts as no correction there.
  ModelError(const CompareQuantity& q, const Table& theory);
  // The prediction's column, -1 if the table has none (then nothing is judged).
  int predicted() const { return predicted_; }
  // At a row whose prediction is finite: relative + the largest correction + the own computed part (a NaN in a
  // correction or the error column counts as none: stricter, never wider).
  double at(const std::vector<double>& row) const;

 private:
  double relative_;
  int predicted_, own_;
  std::vector<int> corrections_;
};

// The largest model error over the judged rows of a theory table (x in [t_min, x_max], the species it covers); 0 where
// the quantity has no prediction in it.
double max_model_error(const CompareQuantity& q, const Table& theory);

}  // namespace granmix::model
