#pragma once
// Mixture generators: the power-law polydisperse mixtures of v1 Fig. 8 / v2 Fig. 4.
#include <cstddef>

#include "mixture.hpp"

namespace granmix::model {

// n_k = n1 k^(-θ), m_k = k m1, σ_k = σ1 k^(diameter_exponent) (1/3: same material; 0: equal sizes).
// Species are kept while the particle count N1 k^(-θ) is at least one (v1 Sec. III), and at
// most max_species of them.
struct PowerLaw {
  double n1 = 0.1;
  double theta = 3.0;
  double n1_particles = 1e7;
  double diameter_exponent = 1.0 / 3.0;
  double mass1 = 1.0;
  double diameter1 = 1.0;
  std::size_t max_species = 1000000;
};

Mixture power_law_mixture(const PowerLaw& p);

// Number of species the power law keeps: the largest k with N1 k^(-θ) >= 1, capped.
std::size_t power_law_species_count(const PowerLaw& p);

}  // namespace granmix::model
