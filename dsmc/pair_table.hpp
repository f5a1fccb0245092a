#pragma once
// Per species pair constants the selectors need: σ_ik², χ_ik and their maxima, and the volume.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "model/mixture.hpp"

namespace granmix::dsmc {

struct PairTable {
  std::size_t M = 0;
  std::vector<double> sigma2, chi;  // [i*M + k]
  std::vector<double> sigma;        // per species diameter
  double sigma2_max = 0.0, chi_max = 1.0;
  double volume = 1.0;  // V = N / n

  PairTable(const model::Mixture& mix, const std::vector<std::vector<double>>& chi_ik, double V) : M(mix.size()), volume(V) {
    sigma2.resize(M * M), chi.resize(M * M);
    chi_max = 0.0;
    for (std::size_t i = 0; i < M; ++i) {
      sigma.push_back(mix[i].diameter);
      for (std::size_t k = 0; k < M; ++k) {
        const double s = mix.sigma(i, k);
        sigma2[i * M + k] = s * s;
        chi[i * M + k] = chi_ik[i][k];
        sigma2_max = std::max(sigma2_max, s * s);
        chi_max = std::max(chi_max, chi_ik[i][k]);
      }
    }
  }
};

}  // namespace granmix::dsmc
