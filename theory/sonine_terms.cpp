#include "sonine_terms.hpp"

#include <cmath>
#include <numbers>

namespace granmix::theory {

namespace {
const double sqrt_pi = std::sqrt(std::numbers::pi);
const double sqrt_2pi = std::sqrt(2.0 * std::numbers::pi);
// x^(−5/2) without pow (pow took two thirds of the time of the N² pair terms at every right-hand side).
double pow_m25(double x) { return 1.0 / (x * x * std::sqrt(x)); }
}  // namespace

SonineMoments sonine_self(double x_i, double chi_ii, double s_ii, double a, double lambda_i) {
  const double w = x_i * chi_ii * s_ii, one_minus_a2 = (1.0 - a) * (1.0 + a);
  SonineMoments m;
  m.zeta0 = 2.0 / 3.0 * sqrt_2pi * w / std::sqrt(lambda_i) * one_minus_a2;                      // MG Eq. (39), 1st term
  m.zeta_self = 1.0 / 8.0 * std::sqrt(std::numbers::pi / 2.0) * w / std::sqrt(lambda_i) * one_minus_a2;  // (40), corrected
  const double l52 = pow_m25(lambda_i);
  m.Lambda0 = -sqrt_2pi * l52 * w * (9.0 + 2.0 * a * a) / 2.0 * one_minus_a2;                  // (42), 1st term
  m.Lambda_self = -sqrt_2pi * l52 * w * (1.0 + a + 3.0 / 64.0 * (69.0 + 10.0 * a * a) * one_minus_a2);  // (43), 1st term
  return m;
}

SonineMoments sonine_cross(double x_j, double chi_ij, double s_ij, double a, double mu, double lambda_i, double lambda_j) {
  const double w = x_j * chi_ij * s_ij, eta = lambda_i / lambda_j, b = mu * (1.0 + a) * (1.0 + eta);  // b = μ(1+α)(1+η)
  // Three square roots per pair (√λ_i, √λ_j, √(1+η)); every other power of η, 1+η and λ is built from them: the
  // kinetic level of a 691-species scene evaluates this for all N² pairs at every right-hand side.
  const double sqrt_li = std::sqrt(lambda_i), sqrt_lj = std::sqrt(lambda_j), s1 = std::sqrt(1.0 + eta);
  const double sqrt_eta = sqrt_li / sqrt_lj, r1 = 1.0 / (1.0 + eta), inv_s1 = 1.0 / s1;
  const double pref = w * mu * (1.0 + a), lj = 1.0 / sqrt_lj, l52 = 1.0 / (lambda_i * lambda_i * sqrt_li);
  const double p15 = r1 * inv_s1, p25 = r1 * p15;  // (1+η)^(−3/2), (1+η)^(−5/2)
  SonineMoments m;
  // MG Eq. (39), 2nd term
  m.zeta0 = 4.0 / 3.0 * sqrt_pi * pref * (s1 / sqrt_eta) * lj * (2.0 - b);
  // MG Eq. (40), 2nd term
  m.zeta_self = 1.0 / 12.0 * sqrt_pi * pref * p15 / sqrt_eta * lj * (2.0 * (3.0 + 4.0 * eta) - 3.0 * b);
  // MG Eq. (41): ((1+η)/η)^(−3/2) = η^(3/2) (1+η)^(−3/2)
  m.zeta_cross = -1.0 / 12.0 * sqrt_pi * pref * (eta * sqrt_eta * p15) * lj * (2.0 + 3.0 * b);
  // MG Eq. (42), 2nd term (enters with a minus inside −√(2π)λ^(-5/2){…})
  m.Lambda0 = sqrt_2pi * l52 * std::numbers::sqrt2 * pref * inv_s1 *
              (-2.0 * (6.0 + 5.0 * eta) + b * (14.0 + 5.0 * eta) - 8.0 * b * b + 2.0 * b * b * b);
  // MG Eq. (43), 2nd term
  m.Lambda_self = sqrt_2pi * l52 * std::numbers::sqrt2 / 16.0 * pref * p25 *
                  (-2.0 * (90.0 + 231.0 * eta + 184.0 * eta * eta + 40.0 * eta * eta * eta) +
                   3.0 * b * (70.0 + 117.0 * eta + 44.0 * eta * eta) - 24.0 * b * b * (5.0 + 4.0 * eta) + 30.0 * b * b * b);
  // MG Eq. (44)
  m.Lambda_cross = sqrt_pi / 8.0 * pref * l52 * eta * eta * p25 *
                   (2.0 * (2.0 + 5.0 * eta) + 3.0 * b * (2.0 + 5.0 * eta) - 24.0 * b * b + 30.0 * b * b * b);
  return m;
}

}  // namespace granmix::theory
