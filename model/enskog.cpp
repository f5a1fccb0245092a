#include "enskog.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace granmix::model {

double packing_fraction(const Mixture& mix) {
  double nu = 0.0;
  for (const Species& s : mix.species()) nu += s.density * std::pow(s.diameter, 3);
  return std::numbers::pi / 6.0 * nu;
}

std::vector<std::vector<double>> enskog_contact_values(const Mixture& mix) {
  const double nu = packing_fraction(mix);
  // Carnahan–Starling describes the fluid; above ν ≈ 0.5 hard spheres freeze and the contact values
  // (and the Enskog theory built on them) lose their meaning.
  if (!(nu < max_packing_fraction))
    throw std::invalid_argument("Enskog: packing fraction " + std::to_string(nu) + " is not below " +
                                std::to_string(max_packing_fraction) +
                                ", the fluid range of the Carnahan-Starling contact values (MG Eq. 26)");
  double xi = 0.0;  // ξ = (π/6) Σ n_i σ_i²
  for (const Species& s : mix.species()) xi += s.density * s.diameter * s.diameter;
  xi *= std::numbers::pi / 6.0;
  const std::size_t N = mix.size();
  std::vector<std::vector<double>> chi(N, std::vector<double>(N));
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) {
      // MG Eq. (26): r = σ_ii σ_jj / σ_ij.
      const double r = mix[i].diameter * mix[j].diameter / mix.sigma(i, j);
      const double a = 1.0 - nu;
      chi[i][j] = 1.0 / a + 1.5 * xi / (a * a) * r + 0.5 * xi * xi / (a * a * a) * r * r;
    }
  return chi;
}

Mixture with_reduced_density(const Mixture& mix, double n_star) {
  const double s12 = mix.sigma(0, mix.size() > 1 ? 1 : 0), scale = n_star / (mix.total_density() * s12 * s12 * s12);
  Mixture out = mix;
  for (std::size_t k = 0; k < mix.size(); ++k) out = out.with_density(k, mix[k].density * scale);
  return out;
}

std::vector<std::vector<double>> dilute_contact_values(std::size_t species) {
  return std::vector<std::vector<double>>(species, std::vector<double>(species, 1.0));
}

}  // namespace granmix::model
