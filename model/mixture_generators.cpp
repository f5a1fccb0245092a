#include "mixture_generators.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace granmix::model {

std::size_t power_law_species_count(const PowerLaw& p) {
  if (!(p.n1_particles >= 1.0)) throw std::invalid_argument("power law: n1_particles must be >= 1");
  if (p.theta <= 0.0) return p.max_species;  // the count never falls below one
  // N1 k^(-θ) >= 1  <=>  k <= N1^(1/θ); guard the floor against rounding just below an integer.
  const double kmax = std::pow(p.n1_particles, 1.0 / p.theta);
  std::size_t k = static_cast<std::size_t>(std::floor(kmax * (1.0 + 1e-12)));
  if (k < 1) k = 1;
  return k < p.max_species ? k : p.max_species;
}

Mixture power_law_mixture(const PowerLaw& p) {
  const std::size_t M = power_law_species_count(p);
  std::vector<Species> s(M);
  for (std::size_t j = 0; j < M; ++j) {
    const double k = static_cast<double>(j + 1);
    s[j] = {p.mass1 * k, p.diameter1 * std::pow(k, p.diameter_exponent), p.n1 * std::pow(k, -p.theta)};
  }
  return Mixture(std::move(s));
}

}  // namespace granmix::model

namespace granmix::model {

Mixture montanero_garzo_binary(double mu, double delta, double w, double n_star) {
  if (!(mu > 0 && delta > 0 && w > 0 && n_star >= 0))
    throw std::invalid_argument("Montanero–Garzó parameters: μ, δ, w must be positive and n* >= 0");
  const double s12 = 0.5 * (w + 1.0);
  const double n = (n_star > 0 ? n_star : 1.0) / (s12 * s12 * s12);
  const double x1 = delta / (1.0 + delta);
  return Mixture({{mu, w, x1 * n}, {1.0, 1.0, (1.0 - x1) * n}});
}

}  // namespace granmix::model

namespace granmix::model {

std::vector<double> exponential_counts(const Exponential& e) {
  std::vector<double> counts;
  for (std::size_t j = 0; j < e.species; ++j) {
    const double c = std::floor(e.n1_particles * std::exp(-e.decay * double(j)));
    if (c < 1.0) break;  // counts only fall with k
    counts.push_back(c);
  }
  if (counts.empty()) throw std::invalid_argument("exponential mixture: n1_particles must be >= 1");
  return counts;
}

Mixture exponential_mixture(const Exponential& e) {
  const std::vector<double> counts = exponential_counts(e);
  double N = 0.0;
  for (double c : counts) N += c;
  std::vector<Species> s;
  for (std::size_t j = 0; j < counts.size(); ++j) {
    const double k = double(j + 1);
    s.push_back({e.mass1 * k, e.diameter1 * std::pow(k, e.diameter_exponent), e.total_density * counts[j] / N});
  }
  return Mixture(std::move(s));
}

}  // namespace granmix::model
