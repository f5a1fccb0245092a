#include "tracer_temperature_galerkin.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "sonine_hcs.hpp"
#include "sonine_tracer.hpp"

namespace granmix::theory {

namespace {

constexpr double alpha = 0.5;  // P_q = L_q^(α)(y), y = c²/λ ~ Gamma(3/2) under f_w

// N_q = ⟨P_q²⟩_w = Γ(q + 3/2)/(q! Γ(3/2)).
double norm(std::size_t q) {
  double n = 1.0;
  for (std::size_t r = 1; r <= q; ++r) n *= (double(r) + alpha) / double(r);
  return n;
}

// ⟨P_q y^j⟩_w, exact: 0 for q > j (orthogonality), else the monomial sum of L_q^(α) against the Gamma(3/2) moments
// Γ(3/2 + i + j)/Γ(3/2) (q ≤ j ≤ 3 here: no cancellation to speak of).
double moment(std::size_t q, std::size_t j) {
  if (q > j) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i <= q; ++i) {
    // (−1)^i C(q + α, q − i)/i!
    double c = (i % 2 ? -1.0 : 1.0);
    for (std::size_t r = 1; r <= q - i; ++r) c *= (double(i + r) + alpha) / double(r);  // C(q + α, q − i) = Π (i + r + α)/r
    for (std::size_t r = 1; r <= i; ++r) c /= double(r);
    double mu = 1.0;
    for (std::size_t r = 0; r < i + j; ++r) mu *= 1.5 + double(r);
    sum += c * mu;
  }
  return sum;
}

struct Solution {
  double ratio;  // ⟨c²⟩_φ/(3/2): the solution's temperature in units of θ_ref
  double x2, x3;  // ⟨c⁴⟩_φ, ⟨c⁶⟩_φ
};

// The Galerkin problem of its first `size` functions at θ_ref, from the assembly C of the whole basis (nested: a
// smaller problem is the leading block of the same assembly).
Solution solve(const Eigen::MatrixXd& C, double zeta1, double lambda, std::size_t size) {
  const auto m = Eigen::Index(size - 1);
  Eigen::MatrixXd K(m, m);
  Eigen::VectorXd rhs(m);
  for (Eigen::Index n = 1; n <= m; ++n) {
    // Σ_qn = ⟨P_q y P_n′(y)⟩ = n N_n δ_qn − (n + α) N_{n−1} δ_q,n−1 (y L_n′ = n L_n − (n + α) L_{n−1}).
    for (Eigen::Index q = 0; q <= m; ++q) {
      double sigma = 0.0;
      if (q == n) sigma = double(n) * norm(std::size_t(n));
      if (q == n - 1) sigma = -(double(n) + alpha) * norm(std::size_t(n - 1));
      const double k = -C(q, n) + zeta1 * sigma;
      if (q == 0)
        rhs[n - 1] = -k;  // b₀ = 1
      else
        K(n - 1, q - 1) = k;
    }
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (!lu.isInvertible()) return {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
  Eigen::VectorXd b(m + 1);
  b[0] = 1.0, b.tail(m) = lu.solve(rhs);
  double x[4] = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t j = 1; j <= 3; ++j)
    for (Eigen::Index q = 0; q <= std::min<Eigen::Index>(m, Eigen::Index(j)); ++q) x[j] += b[q] * moment(std::size_t(q), j) * std::pow(lambda, double(j));
  return {x[1] / 1.5, x[2], x[3]};
}

}  // namespace

TracerTemperature converged_tracer_temperature(const CollisionRates& rates, double zeta1, const PartnerShape& gas, double theta_start,
                                               std::size_t size, double lambda) {
  if (rates.size() != 2) throw std::invalid_argument("converged tracer temperature: needs exactly two species (gas, intruder)");
  // Up to 8 functions the pair rule (60 × 36, 24 impact speeds) is converged: v2 Fig. 5's intruder gives the same θ to
  // 1e-5 with 120 × 72 and 200 × 120 points; at 9 and 10 functions they differ by 0.1% and 1.5%.
  if (size < 2 || size > converged_temperature_basis)
    throw std::invalid_argument("converged tracer temperature: 2 to " + std::to_string(converged_temperature_basis) + " functions");
  if (!(theta_start > 0.0 && std::isfinite(theta_start))) throw std::invalid_argument("converged tracer temperature: theta_start must be positive");
  const model::Mixture& mix = rates.mixture();
  const RadialBasis basis = density_radial_basis(size, lambda);
  TracerTemperature out;
  double theta = theta_start;
  for (int pass = 0; pass < 100; ++pass) {
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(Eigen::Index(size), Eigen::Index(size));
    add_pair_collisions(rates, 1, 0, theta / mix[1].mass, 1.0 / mix[0].mass, basis, lambda, &gas, 1, &C, TestForm::density);
    const Solution s = solve(C, zeta1, lambda, size);
    if (!(s.ratio > 0.0 && std::isfinite(s.ratio))) return out;  // no stationary distribution in the basis
    const double next = theta * s.ratio;
    const bool settled = std::abs(s.ratio - 1.0) < 1e-12;
    theta = next;
    if (!settled) continue;
    out.theta = theta;
    if (size > 2) out.change = std::abs(solve(C, zeta1, lambda, size - 1).ratio - 1.0);  // one function fewer (leading block), over θ
    // Cumulants at the solution's own temperature: ⟨c²⟩ = 3/2 here (settled), so X = c² directly.
    out.a2 = 0.6 * s.x2 / (1.5 * 1.5) - 1.0;
    out.a3 = (-s.x3 / 6.0 + 1.75 * s.x2 - 35.0 / 8.0 * 1.5 + 35.0 / 16.0) / (35.0 / 16.0);
    return out;
  }
  throw NumericalError("converged tracer temperature: the basis temperature did not settle in 100 passes (theta " + std::to_string(theta) + ")");
}

TracerTemperature converged_tracer_temperature(const CollisionRates& rates, std::size_t size) {
  if (rates.size() != 2) throw std::invalid_argument("converged tracer temperature: needs exactly two species (gas, intruder)");
  const model::Restitution& law = rates.law();
  if (law.is_viscoelastic()) return {};
  const model::Mixture& mix = rates.mixture();
  const TracerLimit start = sonine_tracer_limit(rates, {true, 1});
  // The gas alone (the tracer limit drops the intruders' collisions with it): its first-Sonine c₁ at ε₁₁, χ₁₁.
  const SonineHcs gas = sonine_hcs(model::Mixture({mix[0]}), model::Restitution::constant(1, law.eps(0, 0)), {{rates.chi(0, 0)}});
  const double zeta1 = std::isfinite(start.tau0) ? 2.0 / start.tau0 : 0.0;  // ξ₁₁(1 + 3c₁/32); 0 for an elastic gas
  return converged_tracer_temperature(rates, zeta1, {1.0, 0.5 * gas.c[0], 0.0}, start.theta, size);
}

}  // namespace granmix::theory
