#pragma once
// What a few replicas of a species with a few particles can say (v1 Fig. 8's
// species of 1–40 particles). Null model: every particle's displacement at long times is an isotropic
// Gaussian of the right variance, so one replica's MSD estimate is the mean of n values |X|²/3 (a
// χ² of 3n degrees of freedom over 3n), and the scene's z = (mean over R replicas − truth)/(standard
// error over replicas). This z is far from normal for small n R: the error is small exactly when
// the mean is low (skewed χ²), so low z tails are long and high ones short.
#include <cstddef>
#include <cstdint>

namespace granmix::bench {

struct ZNull {
  std::size_t particles = 0, replicas = 0, trials = 0;
  double q005 = 0, q025 = 0, q50 = 0, q975 = 0, q995 = 0;  // quantiles of z
  double p_above4 = 0, p_below4 = 0;                      // P(z > 4), P(z < −4)
  double spread = 0;  // relative standard deviation of one replica's estimate, √(2/(3n))
};

ZNull z_null(std::size_t particles, std::size_t replicas, std::size_t trials, std::uint64_t seed);

}  // namespace granmix::bench
