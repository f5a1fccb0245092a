#pragma once
// A generated closed form as a table of exact terms coefficient · a^ia · β^ib per entry (sonine_cpq_table.hpp,
// sonine_moment_table.hpp), grouped per (entry, power of a) into polynomials in β for Horner. β = μ(1 + ε) is
// constant for a pair, so its polynomials are computed once (beta_polynomials) and each evaluation at a new
// a = θ_k/(θ_k + θ_i) costs one multiply-add per group (evaluate).
#include <array>
#include <cstddef>
#include <vector>

namespace granmix::theory {

class TermTable {
 public:
  struct Term {
    unsigned entry;
    int ia, ib;
    double coefficient;
  };
  static constexpr int a_lowest = 4, a_highest = 11, beta_terms = 10;  // a^−4 … a^11, β^0 … β^9
  // rows sorted by entry, ia, ib; std::logic_error for a power out of range.
  explicit TermTable(const std::vector<Term>& rows);

  // The β polynomials of the first `groups` groups (all by default), in group order.
  std::vector<double> beta_polynomials(double beta, std::size_t groups) const;
  std::vector<double> beta_polynomials(double beta) const { return beta_polynomials(beta, groups_.size()); }
  // Number of groups whose entry is below `entry_limit` (entries are sorted: a prefix of the table).
  std::size_t groups_below(unsigned entry_limit) const;
  // out[entry] += poly_j · a^ia_j over the given polynomials (a prefix of the groups).
  void evaluate(const std::vector<double>& polys, double a, double* out) const;
  // The same for four pairs at once, lane l of each: polys4[4·j + l] is pair l's polynomial j (the first `groups`),
  // a4[l] its a, out4[4·entry + l] its sums. Each lane's operations and order are evaluate's, so its numbers are
  // exactly evaluate's for that pair (term_table.cpp is built without FMA contraction).
  void evaluate4(const double* polys4, std::size_t groups, const double* a4, double* out4) const;

 private:
  struct Group {
    unsigned entry;
    int a_index, degree;
    std::array<double, beta_terms> beta;
  };
  std::vector<Group> groups_;
  // The groups' a-indices again, contiguous, and their runs of one entry: evaluate reads only these (and the
  // polynomials), and the C_pq of a 43-species mixture evaluate 1849 pairs per right-hand side. Each run's sum is kept
  // in a register, the same additions in the same order as out[entry] += … group by group, where every add would wait
  // on the store before it (v1 Fig. 8: evaluate would then be 9% of its kinetic level's time).
  struct Run {
    unsigned entry;
    std::size_t end;  // one past the run's last group
  };
  std::vector<Run> runs_;
  std::vector<unsigned char> a_index_;
};

}  // namespace granmix::theory
