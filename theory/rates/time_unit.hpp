#pragma once
// Montanero–Garzó's time unit (MG Fig. 1): t0 = λ11/v01(0), λ11 = (√2 π n1 χ11 σ11²)⁻¹ the 1–1
// mean free path and v01(0) = √(2 T1(0)/m1) the initial thermal speed of species 1.
#include <vector>

#include "model/mixture.hpp"

namespace granmix::theory {

double mg_time_unit(const model::Mixture& mix, const std::vector<std::vector<double>>& chi, double T1_initial);

}  // namespace granmix::theory
