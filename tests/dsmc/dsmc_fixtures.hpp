#pragma once
// A DSMC set-up for tests: species, one ε for all pairs, counts, sample times, replicas; all T_k(0) = 1.
#include "dsmc/ensemble.hpp"

namespace granmix::test {

inline dsmc::DsmcSetup dsmc_setup(std::vector<model::Species> s, double eps, std::vector<std::size_t> counts, std::vector<double> times,
                                  std::size_t replicas, dsmc::Method m = dsmc::Method::automatic) {
  dsmc::DsmcSetup d;
  d.mixture = model::Mixture(std::move(s));
  d.law = model::Restitution::constant(d.mixture.size(), eps);
  d.counts = std::move(counts);
  d.T0.assign(d.mixture.size(), 1.0);
  d.times = std::move(times);
  d.replicas = replicas;
  d.method = m;
  d.seed = 2024;
  return d;
}

}  // namespace granmix::test
