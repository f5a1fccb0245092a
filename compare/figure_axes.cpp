#include <algorithm>

#include "figure_parts.hpp"

namespace granmix::compare::figure {

int species_style(int k) { return k == 0 ? 9 : 1 + (k - 1) % 8; }

bool spans_decades(const std::vector<double>& v) {
  if (v.empty() || std::any_of(v.begin(), v.end(), [](double x) { return !(x > 0.0); })) return false;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi > 100.0 * *lo;
}

std::vector<double> column_values(const model::Table& t, const std::string& column, const std::vector<int>& species) {
  std::vector<double> out;
  const int c = t.column(column), sc = t.column("species");
  if (c < 0) return out;
  for (const auto& row : t.rows) {
    const bool drawn = species.empty() || sc < 0 || std::find(species.begin(), species.end(), int(row[sc])) != species.end();
    if (drawn && std::isfinite(row[c])) out.push_back(row[c]);
  }
  return out;
}

std::string quote(const std::string& s) {
  std::string q;
  for (char c : s) q += (c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c));
  return "\"" + q + "\"";
}

}  // namespace granmix::compare::figure
