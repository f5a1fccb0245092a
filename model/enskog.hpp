#pragma once
// Enskog pair correlation at contact, Carnahan–Starling form for mixtures (MG Eq. 26).
#include <vector>

#include "mixture.hpp"

namespace granmix::model {

// Largest packing fraction accepted: the fluid range of the Carnahan–Starling form.
inline constexpr double max_packing_fraction = 0.5;

// χ_ij for every pair; all ones in the dilute (Boltzmann) limit. Throws std::invalid_argument
// (naming the limit) for ν >= max_packing_fraction.
std::vector<std::vector<double>> enskog_contact_values(const Mixture& mix);
std::vector<std::vector<double>> dilute_contact_values(std::size_t species);

// Volume packing fraction ν = (π/6) Σ n_i σ_i³ (MG text below Eq. 26).
double packing_fraction(const Mixture& mix);

// The mixture with all densities scaled so that MG's reduced density n σ_12³ = n_star (σ_11 for one
// species; MG Sec. 2), composition unchanged.
Mixture with_reduced_density(const Mixture& mix, double n_star);

}  // namespace granmix::model
