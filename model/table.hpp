#pragma once
// Curves as the files hold them (docs/architecture.md §4): long form, one row per (t or x, species),
// named columns; NaN where a column does not apply to a row (gnuplot skips it).
#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace granmix::model {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  static constexpr double missing = std::numeric_limits<double>::quiet_NaN();
  // Index of a named column, -1 when the table has none.
  int column(const std::string& name) const {
    const auto it = std::find(columns.begin(), columns.end(), name);
    return it == columns.end() ? -1 : int(it - columns.begin());
  }
};

}  // namespace granmix::model
