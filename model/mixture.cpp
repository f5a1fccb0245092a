#include "mixture.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace granmix::model {

Mixture::Mixture(std::vector<Species> species) : species_(std::move(species)) {
  if (species_.empty()) throw std::invalid_argument("a mixture needs at least one species");
  for (std::size_t k = 0; k < species_.size(); ++k) {
    const Species& s = species_[k];
    if (!(s.mass > 0 && std::isfinite(s.mass)) || !(s.diameter > 0 && std::isfinite(s.diameter)) ||
        !(s.density > 0 && std::isfinite(s.density)))
      throw std::invalid_argument("species " + std::to_string(k + 1) +
                                  ": mass, diameter and density must be positive and finite");
    total_density_ += s.density;
  }
}

double Mixture::sigma(std::size_t k, std::size_t i) const {
  return 0.5 * (species_[k].diameter + species_[i].diameter);
}

double Mixture::reduced_mass(std::size_t k, std::size_t i) const {
  const double mk = species_[k].mass, mi = species_[i].mass;
  return mk * mi / (mk + mi);
}

double Mixture::effective_diameter(std::size_t k, std::size_t i) const {
  const double sk = species_[k].diameter, si = species_[i].diameter;
  return sk * si / (sk + si);
}

double Mixture::mean_temperature(const std::vector<double>& T) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < species_.size(); ++k) sum += species_[k].density * T[k];
  return sum / total_density_;
}

Mixture Mixture::with_density(std::size_t k, double density) const {
  std::vector<Species> s = species_;
  s.at(k).density = density;
  return Mixture(std::move(s));
}

}  // namespace granmix::model
