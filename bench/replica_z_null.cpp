#include "replica_z_null.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dsmc/rng.hpp"

namespace granmix::bench {

ZNull z_null(std::size_t n, std::size_t R, std::size_t trials, std::uint64_t seed) {
  dsmc::Rng rng(seed, 1000 * n + R);
  std::vector<double> z(trials);
  std::vector<double> est(R);
  for (std::size_t i = 0; i < trials; ++i) {
    double mean = 0.0;
    for (double& e : est) {
      double s = 0.0;
      for (std::size_t d = 0; d < 3 * n; ++d) {
        const double x = rng.normal();
        s += x * x;
      }
      e = s / double(3 * n), mean += e / double(R);
    }
    double var = 0.0;
    for (double e : est) var += (e - mean) * (e - mean);
    z[i] = (mean - 1.0) / std::sqrt(var / double(R - 1) / double(R));
  }
  std::sort(z.begin(), z.end());
  auto q = [&](double p) { return z[std::min(trials - 1, static_cast<std::size_t>(p * double(trials)))]; };
  ZNull out;
  out.particles = n, out.replicas = R, out.trials = trials;
  out.q005 = q(0.005), out.q025 = q(0.025), out.q50 = q(0.5), out.q975 = q(0.975), out.q995 = q(0.995);
  out.p_above4 = double(z.end() - std::upper_bound(z.begin(), z.end(), 4.0)) / double(trials);
  out.p_below4 = double(std::lower_bound(z.begin(), z.end(), -4.0) - z.begin()) / double(trials);
  out.spread = std::sqrt(2.0 / (3.0 * double(n)));
  return out;
}

}  // namespace granmix::bench
