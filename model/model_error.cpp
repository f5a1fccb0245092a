#include "model_error.hpp"

#include <algorithm>
#include <cmath>

namespace granmix::model {

const std::string& predicted_name(const CompareQuantity& q) { return q.theory.empty() ? q.name : q.theory; }

bool covers(const CompareQuantity& q, int species) {
  return q.species.empty() || std::find(q.species.begin(), q.species.end(), std::size_t(species)) != q.species.end();
}

bool judges(const CompareQuantity& q, double x) { return x >= q.t_min && x <= q.x_max; }

ModelError::ModelError(const CompareQuantity& q, const Table& theory)
    : relative_(q.relative), predicted_(theory.column(predicted_name(q))),
      own_(q.error_column.empty() ? -1 : theory.column(q.error_column)) {
  for (const std::string& from : q.correction_from) corrections_.push_back(theory.column(predicted_name(q) + "_" + from));
}

double ModelError::at(const std::vector<double>& row) const {
  const double value = row[std::size_t(predicted_)];
  double correction = 0.0;
  for (int l : corrections_) {
    const double lower = l >= 0 ? row[std::size_t(l)] : NAN;
    if (std::isfinite(lower) && value != 0.0) correction = std::max(correction, std::abs(value - lower) / std::abs(value));
  }
  const double own = own_ >= 0 && std::isfinite(row[std::size_t(own_)]) ? row[std::size_t(own_)] : 0.0;
  return relative_ + correction + own;
}

double max_model_error(const CompareQuantity& q, const Table& theory) {
  const ModelError error(q, theory);
  const int species = theory.column("species");
  if (error.predicted() < 0 || species < 0 || theory.columns.empty()) return 0.0;
  double largest = 0.0;
  for (const auto& row : theory.rows) {
    const bool judged = covers(q, int(row[std::size_t(species)])) && judges(q, row.front());
    if (judged && std::isfinite(row[std::size_t(error.predicted())])) largest = std::max(largest, error.at(row));
  }
  return largest;
}

}  // namespace granmix::model
