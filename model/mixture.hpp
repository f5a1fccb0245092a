#pragma once
// Species and Mixture: the shared vocabulary of every layer.
// Units: k_B = 1; masses, diameters and number densities in the scene's units; σ = diameter.
#include <cstddef>
#include <vector>

namespace granmix::model {

struct Species {
  double mass = 1.0;
  double diameter = 1.0;
  double density = 0.1;  // number density n_k = N_k / V
};

// Any number N >= 1 of species; pair quantities follow docs/physics.md (σ_ki = (σ_k+σ_i)/2).
class Mixture {
 public:
  explicit Mixture(std::vector<Species> species);

  std::size_t size() const { return species_.size(); }
  const Species& operator[](std::size_t k) const { return species_[k]; }
  const std::vector<Species>& species() const { return species_; }

  double sigma(std::size_t k, std::size_t i) const;         // σ_ki = (σ_k + σ_i)/2
  double reduced_mass(std::size_t k, std::size_t i) const;  // m_eff = m_k m_i / (m_k + m_i)
  double effective_diameter(std::size_t k, std::size_t i) const;  // v1 Eq. (8): σ_kσ_i/(σ_k+σ_i)
  double total_density() const { return total_density_; }
  double fraction(std::size_t k) const { return species_[k].density / total_density_; }

  // ⟨T⟩ = Σ n_k T_k / n (v1 Eq. 24).
  double mean_temperature(const std::vector<double>& T) const;

  Mixture with_density(std::size_t k, double density) const;

 private:
  std::vector<Species> species_;
  double total_density_ = 0.0;
};

}  // namespace granmix::model
