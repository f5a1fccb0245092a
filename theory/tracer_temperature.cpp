#include "tracer_temperature.hpp"

#include <Eigen/Dense>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "sonine_hcs.hpp"
#include "sonine_polynomials.hpp"
#include "sonine_quadrature.hpp"
#include "sonine_tracer.hpp"

namespace granmix::theory {

namespace {

constexpr double domain_widths = 7.0;   // U in units of √(θ/m₂)
constexpr double steps_per_width = 8;   // knots per √(θ/m₂)
constexpr std::size_t gas_points = 12;  // the collision quadrature's size (see the header), and its coarse check's
constexpr std::size_t coarse_gas_points = 6;
constexpr std::size_t speed_points = 4;  // Gauss–Legendre points in u per knot interval
constexpr double max_heating_share = 0.1;  // converged_intruder_temperature's range: |ξ₁₂| ≤ this × ζ₁

// The cardinal cubic B-spline on [0, 4] and its derivative.
double spline(double x) {
  if (x <= 0.0 || x >= 4.0) return 0.0;
  if (x > 2.0) x = 4.0 - x;
  if (x < 1.0) return x * x * x / 6.0;
  x -= 1.0;
  return (1.0 + 3.0 * x + 3.0 * x * x - 3.0 * x * x * x) / 6.0;
}
double spline_slope(double x) {
  if (x <= 0.0 || x >= 4.0) return 0.0;
  const double s = x > 2.0 ? -1.0 : 1.0;
  if (x > 2.0) x = 4.0 - x;
  if (x < 1.0) return s * x * x / 2.0;
  x -= 1.0;
  return s * (3.0 + 6.0 * x - 9.0 * x * x) / 6.0;
}

GaussRule legendre(std::size_t n, double a, double b) {
  gsl_integration_glfixed_table* t = gsl_integration_glfixed_table_alloc(n);
  if (t == nullptr) throw NumericalError("tracer temperature: gsl_integration_glfixed_table_alloc failed");
  GaussRule r;
  for (std::size_t j = 0; j < n; ++j) {
    double x = 0.0, w = 0.0;
    if (gsl_integration_glfixed_point(a, b, j, &x, &w, t) != 0) {
      gsl_integration_glfixed_table_free(t);
      throw NumericalError("tracer temperature: gsl_integration_glfixed_point failed");
    }
    r.x.push_back(x), r.weight.push_back(w);
  }
  gsl_integration_glfixed_table_free(t);
  return r;
}

struct Problem {
  double m1, m2, sd_gas, beta, rate, zeta;  // rate = n₁σ₁₂²χ₁₂
  PartnerShape gas;
};

struct Moments {
  double theta, a2, a3;
  double gain;  // the energy the gas gains per intruder and unit time
};

// The collision quadrature of n points in w_z and |w_⊥|², n/2 in cos θ of σ̂, 3n/4 in its azimuth.
struct CollisionRule {
  GaussRule wz, wp, cs;
  std::vector<double> cos_phi, sin_phi;  // the azimuths' midpoints
  explicit CollisionRule(std::size_t n) : wz(golub_welsch(n, false)), wp(golub_welsch(n, true)), cs(legendre(n / 2, 0.0, 1.0)) {
    for (std::size_t f = 0; f < 3 * n / 4; ++f) {
      const double phi = 2.0 * std::numbers::pi * (double(f) + 0.5) / double(3 * n / 4);
      cos_phi.push_back(std::cos(phi)), sin_phi.push_back(std::sin(phi));
    }
  }
};

// The columns i … i + 3 of the weak form (the trial functions nonzero on knot interval i), rows every test function,
// and those columns' moments ∫N_j u^(2n) du, n = 0 … 3, and ∫N_j G du, G(u) the gas's energy gain rate from an intruder
// of speed u.
void interval(const Problem& p, double h, std::size_t i, const CollisionRule& rule, Eigen::Ref<Eigen::MatrixXd> cols, double (&moments)[4][5]) {
  static const GaussRule uq = legendre(speed_points, 0.0, 1.0);
  const GaussRule &wz = rule.wz, &wp = rule.wp, &cs = rule.cs;
  const std::size_t azimuths = rule.cos_phi.size(), nb = std::size_t(cols.rows());
  std::vector<double> C(nb);
  for (std::size_t q = 0; q < uq.x.size(); ++q) {
    const double u = (double(i) + uq.x[q]) * h, wu = uq.weight[q] * h;
    // C_m(u) = ∫dw f_gas ∫dσ̂ rate (g·σ̂)Θ [N_m(|v′|) − N_m(u)]
    std::fill(C.begin(), C.end(), 0.0);
    double G = 0.0;
    for (std::size_t a = 0; a < wz.x.size(); ++a)
      for (std::size_t b = 0; b < wp.x.size(); ++b) {
        const double x = 0.5 * wz.x[a] * wz.x[a] + wp.x[b];  // m₁w²/(2T₁)
        const double shape = p.gas.one + p.gas.a2 * sonine_S2(x) + p.gas.a3 * sonine_S3(x);
        const double w_z = p.sd_gas * wz.x[a], w_x = p.sd_gas * std::sqrt(2.0 * wp.x[b]);
        const double gx = -w_x, gz = u - w_z, g = std::hypot(gx, gz);
        if (g == 0.0) continue;
        const double e3[2] = {gx / g, gz / g}, e1[2] = {e3[1], -e3[0]};  // (x, z); e2 = ŷ
        const double wab = wz.weight[a] * wp.weight[b] * shape * p.rate * g * 2.0 * std::numbers::pi / double(azimuths);
        for (std::size_t c = 0; c < cs.x.size(); ++c) {
          const double ct = cs.x[c], st = std::sqrt(1.0 - ct * ct), w = wab * cs.weight[c] * ct, kick = p.beta * g * ct;
          // The gas particle: w′ = w + (m₂/m₁) kick σ̂, ΔE = (m₁/2)(2 k w·σ̂ + k²), k = (m₂/m₁) kick.
          const double k = p.m2 / p.m1 * kick, w1 = w_x * e1[0] + w_z * e1[1], w3 = w_x * e3[0] + w_z * e3[1];
          double lost = 0.0;
          for (std::size_t f = 0; f < azimuths; ++f) {
            const double cp = rule.cos_phi[f], sp = rule.sin_phi[f];
            G += w * 0.5 * p.m1 * (2.0 * k * (st * cp * w1 + ct * w3) + k * k);
            const double vx = -kick * (st * cp * e1[0] + ct * e3[0]), vy = -kick * st * sp, vz = u - kick * (st * cp * e1[1] + ct * e3[1]);
            const double s = std::sqrt(vx * vx + vy * vy + vz * vz) / h;
            const auto j0 = std::size_t(s);
            for (std::size_t j = j0; j <= j0 + 3 && j < nb; ++j) C[j] += w * spline(s - double(j) + 3.0);
            lost += w;
          }
          for (std::size_t j = i; j <= i + 3; ++j) C[j] -= lost * spline(u / h - double(j) + 3.0);
        }
      }
    for (std::size_t c = 0; c < 4; ++c) {  // trial function i + c
      const double Nj = spline(u / h - double(i + c) + 3.0) * wu;
      for (int n = 0; n < 4; ++n) moments[c][n] += Nj * std::pow(u, 2 * n);
      moments[c][4] += Nj * G;
      for (std::size_t m = 0; m < nb; ++m)
        cols(Eigen::Index(m), Eigen::Index(c)) += Nj * (C[m] + 0.5 * p.zeta * u * spline_slope(u / h - double(m) + 3.0) / h);
    }
  }
}

// The stationary speed density on K knot intervals of [0, U]; θ and the cumulants from its moments. The intervals run
// on OpenMP threads (one region per solve), each into its own columns, summed in interval order: the same numbers for
// any thread count.
Moments solve(const Problem& p, double U, std::size_t K, const CollisionRule& rule) {
  const double h = U / double(K);
  const std::size_t nb = K + 3;  // N_j(u) = spline(u/h − j + 3), j = 0 … K + 2
  Eigen::MatrixXd blocks = Eigen::MatrixXd::Zero(Eigen::Index(nb), Eigen::Index(4 * K));
  std::vector<double> moments(20 * K, 0.0);
  std::vector<std::exception_ptr> failed(K);
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t i = 0; i < K; ++i) {
    try {
      double m[4][5] = {};
      interval(p, h, i, rule, blocks.middleCols(Eigen::Index(4 * i), 4), m);
      for (std::size_t c = 0; c < 4; ++c)
        for (std::size_t n = 0; n < 5; ++n) moments[20 * i + 5 * c + n] = m[c][n];
    } catch (...) {
      failed[i] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(Eigen::Index(nb), Eigen::Index(nb));
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(Eigen::Index(nb)), m2 = mass, m4 = mass, m6 = mass, gain = mass;
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t c = 0; c < 4; ++c) {
      const auto J = Eigen::Index(i + c);
      const double* m = &moments[20 * i + 5 * c];
      A.col(J) += blocks.col(Eigen::Index(4 * i + c));
      mass[J] += m[0], m2[J] += m[1], m4[J] += m[2], m6[J] += m[3], gain[J] += m[4];
    }
  // The tests sum to ψ = 1 (partition of unity), whose equation is 0 = 0: the last one gives way to ∫P = 1.
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(nb));
  A.row(Eigen::Index(nb - 1)) = mass.transpose(), rhs[Eigen::Index(nb - 1)] = 1.0;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (!lu.isInvertible()) return {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0};
  const Eigen::VectorXd P = lu.solve(rhs);
  const double u2 = m2.dot(P), u4 = m4.dot(P), u6 = m6.dot(P);
  // Cumulants at the solution's own temperature: c² = u² m₂/(2θ), ⟨c²⟩ = 3/2, a_p = ⟨S_p(c²)⟩/⟨S_p²⟩_M (physics.md §6;
  // S₂, S₃ of sonine_polynomials.hpp expanded in the moments, ⟨S₂²⟩_M = 15/8, ⟨S₃²⟩_M = 35/16).
  const double theta = p.m2 * u2 / 3.0, s = p.m2 / (2.0 * theta), x2 = u4 * s * s, x3 = u6 * s * s * s;
  return {theta, 0.6 * x2 / (1.5 * 1.5) - 1.0, (-x3 / 6.0 + 1.75 * x2 - 35.0 / 8.0 * 1.5 + 35.0 / 16.0) / (35.0 / 16.0), gain.dot(P)};
}

}  // namespace

TracerTemperature converged_tracer_temperature(const CollisionRates& rates, double zeta1, const PartnerShape& gas, double theta_start) {
  if (rates.size() != 2) throw std::invalid_argument("converged tracer temperature: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic()) throw std::invalid_argument("converged tracer temperature: constant restitution only");
  if (!(theta_start > 0.0 && std::isfinite(theta_start))) throw std::invalid_argument("converged tracer temperature: theta_start must be positive");
  if (!(zeta1 >= 0.0 && std::isfinite(zeta1))) throw std::invalid_argument("converged tracer temperature: zeta1 must be >= 0");
  const model::Mixture& mix = rates.mixture();
  const double s = mix.sigma(1, 0), m1 = mix[0].mass, m2 = mix[1].mass;
  const Problem p{m1, m2, std::sqrt(1.0 / m1), m1 * (1.0 + rates.law().eps(1, 0)) / (m1 + m2), mix[0].density * s * s * rates.chi(1, 0), zeta1, gas};
  static const CollisionRule fine(gas_points), coarse(coarse_gas_points);
  auto at = [&](double theta, double step_scale, const CollisionRule& rule) {
    const double width = std::sqrt(theta / m2);
    return solve(p, domain_widths * width, std::size_t(std::ceil(domain_widths * steps_per_width / step_scale)), rule);
  };
  double theta = theta_start;
  for (int pass = 0; pass < 30; ++pass) {
    const Moments r = at(theta, 1.0, fine);
    if (!(r.theta > 0.0 && std::isfinite(r.theta))) return {};
    const bool settled = std::abs(r.theta / theta - 1.0) < 1e-5;
    theta = r.theta;
    if (!settled) continue;
    // The gas's energy density is n₁(3/2)T₁ (T₁ = 1): the intruders at n₂ change its cooling rate by ξ₁₂ = −n₂ gain/(n₁ 3/2).
    TracerTemperature out{r.theta, r.a2, r.a3, std::numeric_limits<double>::quiet_NaN(), -mix[1].density * r.gain / (1.5 * mix[0].density)};
    out.change = std::max(std::abs(at(theta, 1.5, fine).theta / r.theta - 1.0), std::abs(at(theta, 1.0, coarse).theta / r.theta - 1.0));
    return out;
  }
  throw NumericalError("converged tracer temperature: the speed grid did not settle on θ in 30 passes (theta " + std::to_string(theta) + ")");
}

namespace {

// The gas of the kinetic tracer form (sonine_tracer.hpp): its one-species first-Sonine HCS (the tracer limit drops the
// intruders' collisions with it), a₂ = c₁/2 at ε₁₁, χ₁₁, its rate ξ₁₁(1 + 3c₁/32) (0 for an elastic gas), and that
// form's θ as the start.
struct KineticGas {
  double zeta1;
  PartnerShape shape;
  double theta_start;
};
KineticGas kinetic_gas(const CollisionRates& rates) {
  const model::Mixture& mix = rates.mixture();
  const TracerLimit start = sonine_tracer_limit(rates, {true, 1});
  const SonineHcs gas = sonine_hcs(model::Mixture({mix[0]}), model::Restitution::constant(1, rates.law().eps(0, 0)), {{rates.chi(0, 0)}});
  return {std::isfinite(start.tau0) ? 2.0 / start.tau0 : 0.0, {1.0, 0.5 * gas.c[0], 0.0}, start.theta};
}

}  // namespace

TracerTemperature converged_tracer_temperature(const CollisionRates& rates) {
  if (rates.size() != 2) throw std::invalid_argument("converged tracer temperature: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic()) return {};
  const KineticGas gas = kinetic_gas(rates);
  return converged_tracer_temperature(rates, gas.zeta1, gas.shape, gas.theta_start);
}

TracerTemperature converged_intruder_temperature(const CollisionRates& rates, const TracerTemperature& tracer) {
  if (rates.size() != 2) throw std::invalid_argument("converged intruder temperature: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic()) return {};
  const KineticGas gas = kinetic_gas(rates);
  TracerTemperature t = tracer;
  // Intruders: a small part of the gas's energy budget (else the gas's own shape and the intruders' mutual collisions,
  // both left out here, matter as much): omitted (NaN) above max_heating_share.
  if (!std::isfinite(t.theta) || !(std::abs(t.xi12) <= max_heating_share * gas.zeta1)) return {};
  // F(ζ) = ζ − ζ₁ − ξ₁₂(θ(ζ)) = 0 by the secant method from ζ₁ (F(ζ₁) = −ξ₁₂) and ζ₁ + ξ₁₂ (one fixed-point pass).
  double z0 = gas.zeta1, f0 = -t.xi12, z1 = gas.zeta1 + t.xi12;
  for (int pass = 0; pass < 20; ++pass) {
    const TracerTemperature next = converged_tracer_temperature(rates, z1, gas.shape, t.theta);
    if (!std::isfinite(next.theta)) return {};
    const double f1 = z1 - gas.zeta1 - next.xi12;
    const bool settled = std::abs(next.theta / t.theta - 1.0) < 1e-6;
    t = next;
    if (settled) return t;
    const double z2 = f1 == f0 ? z1 : z1 - f1 * (z1 - z0) / (f1 - f0);
    z0 = z1, f0 = f1, z1 = z2;
    if (!(z1 > 0.0)) return {};
  }
  throw NumericalError("converged intruder temperature: zeta = zeta_1 + xi_12(theta) did not settle in 20 passes (theta " + std::to_string(t.theta) + ")");
}

}  // namespace granmix::theory
