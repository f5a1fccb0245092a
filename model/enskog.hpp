#pragma once
// Enskog pair correlation at contact, Carnahan–Starling form for mixtures (MG Eq. 26).
#include <vector>

#include "mixture.hpp"

namespace granmix::model {

// χ_ij for every pair; all ones in the dilute (Boltzmann) limit.
std::vector<std::vector<double>> enskog_contact_values(const Mixture& mix);
std::vector<std::vector<double>> dilute_contact_values(std::size_t species);

// Volume packing fraction ν = (π/6) Σ n_i σ_i³ (MG text below Eq. 26).
double packing_fraction(const Mixture& mix);

}  // namespace granmix::model
