#include "theory/rates/time_unit.hpp"

#include <cmath>
#include <numbers>

namespace granmix::theory {

double mg_time_unit(const model::Mixture& mix, const std::vector<std::vector<double>>& chi, double T1_initial) {
  const double s11 = mix[0].diameter;
  const double lambda11 = 1.0 / (std::sqrt(2.0) * std::numbers::pi * mix[0].density * chi[0][0] * s11 * s11);
  return lambda11 / std::sqrt(2.0 * T1_initial / mix[0].mass);
}

}  // namespace granmix::theory
