#pragma once
// Mixture generators: the power-law polydisperse mixtures of v1 Fig. 8 / v2 Fig. 4, the exponential
// one of v2 Fig. 6 / Table 1, and Montanero–Garzó's binary parameters.
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

namespace granmix::model {

// Montanero–Garzó binary parameters (MG Sec. 3): μ = m_1/m_2, δ = n_1/n_2, w = σ_11/σ_22,
// n* = n σ_12³. Units: m_2 = 1, σ_22 = 1. With n* = 0 (dilute) the total density is set to
// n σ_12³ = 1; every ratio is independent of it, absolute times are not.
Mixture montanero_garzo_binary(double mu, double delta, double w, double n_star);

}  // namespace granmix::model

namespace granmix::model {

// Particle counts N_k = floor(N1 e^(−decay (k−1))), k = 1…species (v2 Sec. III, Fig. 6 / Table 1: N1 = 999,
// decay = 0.01, 691 species, about 1e5 particles); m_k = k m1, σ_k = σ1 k^(diameter_exponent), number
// densities n_k = total_density N_k / Σ N. Species whose count floors to zero are dropped.
struct Exponential {
  double n1_particles = 999;
  double decay = 0.01;
  std::size_t species = 691;
  double total_density = 0.1;
  double diameter_exponent = 1.0 / 3.0;
  double mass1 = 1.0, diameter1 = 1.0;
};

Mixture exponential_mixture(const Exponential& e);
// The particle counts N_k of that mixture (the species kept).
std::vector<double> exponential_counts(const Exponential& e);

}  // namespace granmix::model
