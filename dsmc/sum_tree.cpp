#include "sum_tree.hpp"

namespace granmix::dsmc {

SumTree::SumTree(const std::vector<double>& weights) : size_(weights.size()), leaves_(1) {
  while (leaves_ < size_) leaves_ *= 2;
  node_.assign(2 * leaves_, 0.0);
  for (std::size_t i = 0; i < size_; ++i) node_[leaves_ + i] = weights[i];
  for (std::size_t n = leaves_ - 1; n >= 1; --n) node_[n] = node_[2 * n] + node_[2 * n + 1];
}

void SumTree::set(std::size_t i, double w) {
  std::size_t n = leaves_ + i;
  node_[n] = w;
  // Recompute sums (not add differences): no drift from rounding however many updates.
  for (n /= 2; n >= 1; n /= 2) node_[n] = node_[2 * n] + node_[2 * n + 1];
}

}  // namespace granmix::dsmc
