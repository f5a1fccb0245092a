#pragma once
// Per species pair constants the selectors need: σ_ik² and χ_ik, their maxima, and the volume.
// σ_ik = (σ_i + σ_k)/2 is computed on demand; χ_ik is stored (M×M) only for an Enskog gas: a dilute
// gas of 1e5 species would otherwise need two 80 GB tables of ones and squares.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "model/mixture.hpp"

namespace granmix::dsmc {

struct PairTable {
  std::size_t M = 0;
  std::vector<double> sigma;  // per species diameter
  std::vector<double> chi_ik; // [i*M + k] for an Enskog gas; empty when dilute (χ = 1)
  double sigma2_max = 0.0, chi_max = 1.0;
  double volume = 1.0;  // V = N / n

  // chi: the contact values χ_ik (M×M), or empty for a dilute gas.
  PairTable(const model::Mixture& mix, const std::vector<std::vector<double>>& chi, double V) : M(mix.size()), volume(V) {
    for (std::size_t i = 0; i < M; ++i) sigma.push_back(mix[i].diameter);
    const double smax = *std::max_element(sigma.begin(), sigma.end());
    sigma2_max = smax * smax;
    if (chi.empty()) return;
    chi_max = 0.0;
    chi_ik.resize(M * M);
    for (std::size_t i = 0; i < M; ++i)
      for (std::size_t k = 0; k < M; ++k) chi_ik[i * M + k] = chi[i][k], chi_max = std::max(chi_max, chi[i][k]);
  }
  bool dilute() const { return chi_ik.empty(); }
  double sigma2(std::size_t i, std::size_t k) const {
    const double s = 0.5 * (sigma[i] + sigma[k]);
    return s * s;
  }
  double chi(std::size_t i, std::size_t k) const { return chi_ik.empty() ? 1.0 : chi_ik[i * M + k]; }
};

}  // namespace granmix::dsmc
