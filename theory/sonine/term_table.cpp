#include "theory/sonine/term_table.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "theory/numerics/vector_clones.hpp"

namespace granmix::theory {

TermTable::TermTable(const std::vector<Term>& rows) {
  for (const Term& r : rows) {
    if (r.ia < -a_lowest || r.ia > a_highest || r.ib < 0 || r.ib >= beta_terms) throw std::logic_error("generated term table: power out of range");
    const int a_index = a_lowest + r.ia;
    if (groups_.empty() || groups_.back().entry != r.entry || groups_.back().a_index != a_index) groups_.push_back({r.entry, a_index, 0, {}});
    groups_.back().beta[std::size_t(r.ib)] = r.coefficient;  // rows sorted by entry, ia, ib
    groups_.back().degree = std::max(groups_.back().degree, r.ib);
  }
  for (std::size_t j = 0; j < groups_.size(); ++j) {
    if (runs_.empty() || runs_.back().entry != groups_[j].entry) runs_.push_back({groups_[j].entry, j});
    runs_.back().end = j + 1;
    a_index_.push_back((unsigned char)(groups_[j].a_index));
  }
}

std::vector<double> TermTable::beta_polynomials(double beta, std::size_t groups) const {
  std::vector<double> out;
  out.reserve(groups);
  for (std::size_t j = 0; j < groups; ++j) {
    const Group& g = groups_[j];
    double poly = g.beta[std::size_t(g.degree)];
    for (int d = g.degree; d-- > 0;) poly = poly * beta + g.beta[std::size_t(d)];
    out.push_back(poly);
  }
  return out;
}

std::size_t TermTable::groups_below(unsigned entry_limit) const {
  return std::size_t(std::partition_point(groups_.begin(), groups_.end(), [&](const Group& g) { return g.entry < entry_limit; }) -
                     groups_.begin());
}

void TermTable::evaluate(const std::vector<double>& polys, double a, double* out) const {
  std::array<double, a_lowest + a_highest + 1> apow{};  // a^(j − a_lowest)
  apow[a_lowest] = 1.0;
  for (std::size_t j = a_lowest + 1; j < apow.size(); ++j) apow[j] = apow[j - 1] * a;
  for (std::size_t j = a_lowest; j-- > 0;) apow[j] = apow[j + 1] / a;
  const unsigned char* a_index = a_index_.data();
  const double* poly = polys.data();
  const std::size_t n = polys.size();  // a prefix of the groups
  std::size_t j = 0;
  for (const Run& r : runs_) {
    if (j == n) break;
    const std::size_t end = std::min(r.end, n);
    double sum = out[r.entry];
    for (; j < end; ++j) sum += poly[j] * apow[a_index[j]];
    out[r.entry] = sum;
  }
}

GRANMIX_VECTOR_CLONES void TermTable::evaluate4(const double* polys4, std::size_t groups, const double* a4, double* out4) const {
  using Lanes = double __attribute__((vector_size(32)));
  using LanesMem = double __attribute__((vector_size(32), aligned(8), may_alias));
  const Lanes a = *reinterpret_cast<const LanesMem*>(a4);
  std::array<Lanes, a_lowest + a_highest + 1> apow{};  // as evaluate's, lane by lane
  apow[a_lowest] = Lanes{1.0, 1.0, 1.0, 1.0};
  for (std::size_t j = a_lowest + 1; j < apow.size(); ++j) apow[j] = apow[j - 1] * a;
  for (std::size_t j = a_lowest; j-- > 0;) apow[j] = apow[j + 1] / a;
  const unsigned char* a_index = a_index_.data();
  std::size_t j = 0;
  for (const Run& r : runs_) {
    if (j == groups) break;
    const std::size_t end = std::min(r.end, groups);
    LanesMem& to = *reinterpret_cast<LanesMem*>(out4 + 4 * std::size_t(r.entry));
    Lanes sum = to;
    for (; j < end; ++j) sum += *reinterpret_cast<const LanesMem*>(polys4 + 4 * j) * apow[a_index[j]];
    to = sum;
  }
}

}  // namespace granmix::theory
