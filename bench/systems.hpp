#pragma once
// The systems the selector study runs: one species, the binary 1:100 of v1 Fig. 2, a
// ternary of one material, the 691-species system of v2 Fig. 6 / Table 1, and polydisperse
// mixtures of M species (power law θ = 3 or exponential) with at least one particle per species.
// All start Maxwellian at T = 1 with total density 0.1.
#include <cstddef>
#include <string>

#include "dsmc/ensemble.hpp"

namespace granmix::bench {

struct BenchSystem {
  std::string name;
  dsmc::DsmcSetup setup;  // mixture, law, counts, T0 (times, method, seed: set by the study)
};

BenchSystem one_species(std::size_t particles);
BenchSystem binary_1_100(std::size_t particles);       // m = 1, 100; σ = 1, 100^(1/3); ε = 0.5
BenchSystem ternary(std::size_t particles);            // m = 1, 10, 100; σ = m^(1/3); ε = 0.9
BenchSystem exponential_691(double n1_particles);      // v2: N_k = floor(N1 e^(−0.01(k−1))), ε = 0.99
// M species, m_k = k, σ_k = k^(1/3), ε = 0.99; counts 1 + floor((N − M) w_k) with w_k ∝ k^(−3)
// ("powerlaw") or e^(−6.9(k−1)/M) ("exponential": the 691 system's 1e-3 range over any M).
BenchSystem polydisperse(const std::string& shape, std::size_t species, std::size_t particles);

}  // namespace granmix::bench
