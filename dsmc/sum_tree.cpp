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

std::size_t SumTree::sample(double u) const {
  double x = u * node_[1];
  std::size_t n = 1;
  while (n < leaves_) {
    const double left = node_[2 * n];
    if (x < left) {
      n = 2 * n;
    } else {
      x -= left;
      n = 2 * n + 1;
    }
  }
  std::size_t i = n - leaves_;
  // Rounding can push x past the last non-empty leaf: step back to a leaf with weight.
  while (i >= size_ || node_[leaves_ + i] == 0.0) --i;
  return i;
}

}  // namespace granmix::dsmc
