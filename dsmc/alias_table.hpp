#pragma once
// Walker's alias table (Vose's construction): O(1) sampling of an index with probability
// weight/total from fixed weights. The low-rank selector draws its second species from fixed
// weights N_k σ_k^r, so a table replaces a sum-tree descent there.
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace granmix::dsmc {

class AliasTable {
 public:
  explicit AliasTable(const std::vector<double>& w) : prob_(w.size()), alias_(w.size()) {
    const std::size_t n = w.size();
    double total = 0.0;
    for (double x : w) total += x;
    if (n == 0 || !(total > 0.0)) throw std::invalid_argument("alias table: weights must have a positive sum");
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
      scaled[i] = w[i] * double(n) / total;
      (scaled[i] < 1.0 ? small : large).push_back(i);
      alias_[i] = i;
    }
    while (!small.empty() && !large.empty()) {
      const std::size_t s = small.back(), l = large.back();
      small.pop_back();
      prob_[s] = scaled[s], alias_[s] = l;
      scaled[l] -= 1.0 - scaled[s];
      if (scaled[l] < 1.0) large.pop_back(), small.push_back(l);
    }
    for (std::size_t i : large) prob_[i] = 1.0;  // left over: exactly 1 up to rounding
    for (std::size_t i : small) prob_[i] = w[i] > 0.0 ? 1.0 : 0.0;
  }
  // u uniform in [0, 1): its integer part picks the column, its fraction the side (53 bits leave
  // 36 for the fraction at 1e5 entries).
  std::size_t sample(double u) const {
    const double x = u * double(prob_.size());
    const auto j = static_cast<std::size_t>(x);
    return x - double(j) < prob_[j] ? j : alias_[j];
  }
  std::size_t size() const { return prob_.size(); }

 private:
  std::vector<double> prob_;
  std::vector<std::size_t> alias_;
};

}  // namespace granmix::dsmc
