#include "theory/sonine/sonine_terms.hpp"

#include <cmath>
#include <numbers>

#include "theory/numerics/vector_clones.hpp"

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
  const double w = x_j * chi_ij * s_ij, sqrt_lj = std::sqrt(lambda_j), inv_sqrt_lj = 1.0 / sqrt_lj;
  SonineMoments m;
  sonine_cross_row(1, &w, &a, &mu, lambda_i, &sqrt_lj, &inv_sqrt_lj,
                   {&m.zeta0, &m.zeta_self, &m.zeta_cross, &m.Lambda0, &m.Lambda_self, &m.Lambda_cross});
  return m;
}

namespace {
// The loop of sonine_cross_row with every array a restrict parameter (GCC honours restrict on parameters, not on
// local copies: the six outputs could alias each other, and no vector loop is made). Elementwise +, ×, ÷, √ alone: the
// AVX2 and AVX-512 builds give the baseline's numbers (vector_clones.hpp).
GRANMIX_VECTOR_CLONES void cross_row_kernel(std::size_t n, const double* __restrict w_, const double* __restrict alpha, const double* __restrict mu_,
                      double lambda_i, const double* __restrict sqrt_lambda_j, const double* __restrict inv_sqrt_lambda_j,
                      double* __restrict zeta0, double* __restrict zeta_self, double* __restrict zeta_cross, double* __restrict Lambda0,
                      double* __restrict Lambda_self, double* __restrict Lambda_cross) {
  const double sqrt_li = std::sqrt(lambda_i), inv_sqrt_li = 1.0 / sqrt_li, l52 = pow_m25(lambda_i);
  for (std::size_t j = 0; j < n; ++j) {
    // √η, 1/√η from the species' own roots; then one square root (√(1+η)) and one division (1/(1+η)) per pair.
    const double a = alpha[j], mu = mu_[j], sqrt_eta = sqrt_li * inv_sqrt_lambda_j[j], inv_sqrt_eta = sqrt_lambda_j[j] * inv_sqrt_li;
    const double eta = sqrt_eta * sqrt_eta, b = mu * (1.0 + a) * (1.0 + eta);  // η = λ_i/λ_j, b = μ(1+α)(1+η)
    const double s1 = std::sqrt(1.0 + eta), r1 = 1.0 / (1.0 + eta), inv_s1 = s1 * r1;
    const double pref = w_[j] * mu * (1.0 + a), lj = inv_sqrt_lambda_j[j];
    const double p15 = r1 * inv_s1, p25 = r1 * p15;  // (1+η)^(−3/2), (1+η)^(−5/2)
    // MG Eq. (39), 2nd term
    zeta0[j] = 4.0 / 3.0 * sqrt_pi * pref * (s1 * inv_sqrt_eta) * lj * (2.0 - b);
    // MG Eq. (40), 2nd term
    zeta_self[j] = 1.0 / 12.0 * sqrt_pi * pref * p15 * inv_sqrt_eta * lj * (2.0 * (3.0 + 4.0 * eta) - 3.0 * b);
    // MG Eq. (41): ((1+η)/η)^(−3/2) = η^(3/2) (1+η)^(−3/2)
    zeta_cross[j] = -1.0 / 12.0 * sqrt_pi * pref * (eta * sqrt_eta * p15) * lj * (2.0 + 3.0 * b);
    // MG Eq. (42), 2nd term (enters with a minus inside −√(2π)λ^(-5/2){…})
    Lambda0[j] = sqrt_2pi * l52 * std::numbers::sqrt2 * pref * inv_s1 *
                     (-2.0 * (6.0 + 5.0 * eta) + b * (14.0 + 5.0 * eta) - 8.0 * b * b + 2.0 * b * b * b);
    // MG Eq. (43), 2nd term
    Lambda_self[j] = sqrt_2pi * l52 * std::numbers::sqrt2 / 16.0 * pref * p25 *
                         (-2.0 * (90.0 + 231.0 * eta + 184.0 * eta * eta + 40.0 * eta * eta * eta) +
                          3.0 * b * (70.0 + 117.0 * eta + 44.0 * eta * eta) - 24.0 * b * b * (5.0 + 4.0 * eta) + 30.0 * b * b * b);
    // MG Eq. (44)
    Lambda_cross[j] = sqrt_pi / 8.0 * pref * l52 * eta * eta * p25 *
                          (2.0 * (2.0 + 5.0 * eta) + 3.0 * b * (2.0 + 5.0 * eta) - 24.0 * b * b + 30.0 * b * b * b);
  }
}
}  // namespace

void sonine_cross_row(std::size_t n, const double* w, const double* alpha, const double* mu, double lambda_i, const double* sqrt_lambda_j,
                      const double* inv_sqrt_lambda_j, const SonineRow& row) {
  cross_row_kernel(n, w, alpha, mu, lambda_i, sqrt_lambda_j, inv_sqrt_lambda_j, row.zeta0, row.zeta_self, row.zeta_cross, row.Lambda0,
                   row.Lambda_self, row.Lambda_cross);
}

}  // namespace granmix::theory
