#include "theory/grid/tracer_temperature.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_tracer.hpp"
#include "theory/grid/speed_grid.hpp"

namespace granmix::theory {

namespace {

constexpr std::size_t coarse_gas_points = 6;  // the collision rule of the coarse check
constexpr double max_heating_share = 0.1;  // converged_intruder_temperature's range: |ξ₁₂| ≤ this × ζ₁

// The stationary speed density on K knot intervals of [0, U] (NaN θ where the weak form is singular).
SpeedMoments solve(const SpeedGridProblem& p, double zeta, double U, std::size_t K, const CollisionRule& rule) {
  const SpeedGrid g = assemble_speed_grid(p, U, K, rule);
  const Eigen::VectorXd P = stationary_speed_density(g.collisions, g, zeta);
  if (P.size() == 0) return {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0, 0.0, 0.0};
  return speed_moments(g, p, P);
}

// The grid placed for θ (its domain and knots scale with √(θ/m₂)), step_scale times the knots' spacing.
SpeedMoments solve_at(const SpeedGridProblem& p, double zeta, double theta, double step_scale, const CollisionRule& rule) {
  const double width = std::sqrt(theta / p.m2);
  return solve(p, zeta, speed_grid_widths * width, std::size_t(std::ceil(speed_grid_widths * speed_grid_knots / step_scale)), rule);
}

const CollisionRule& fine_rule() {
  static const CollisionRule r(speed_grid_rule_points);
  return r;
}

// θ where the grid placed for it returns it (to 1e-5), from theta_start; TracerTemperature without its `change`.
TracerTemperature settle(const CollisionRates& rates, const SpeedGridProblem& p, double zeta1, double theta_start) {
  const model::Mixture& mix = rates.mixture();
  double theta = theta_start;
  for (int pass = 0; pass < 30; ++pass) {
    const SpeedMoments r = solve_at(p, zeta1, theta, 1.0, fine_rule());
    if (!(r.theta > 0.0 && std::isfinite(r.theta))) return {};
    const bool settled = std::abs(r.theta / theta - 1.0) < 1e-5;
    theta = r.theta;
    if (!settled) continue;
    // The gas's energy density is n₁(3/2)T₁ (T₁ = 1): the intruders at n₂ change its cooling rate by ξ₁₂ = −n₂ gain/(n₁ 3/2).
    return {r.theta, r.a2, r.a3, std::numeric_limits<double>::quiet_NaN(), -mix[1].density * r.gain / (1.5 * mix[0].density), r.nu};
  }
  // Measured: the grid's θ stops settling from a mass ratio of ~500 (ε = 0.5), its kicks too small for the knots.
  throw NumericalError("converged tracer temperature: the speed grid did not settle on θ in 30 passes (theta " + std::to_string(theta) +
                       ", mass ratio " + std::to_string(p.m2 / p.m1) + ": its θ settles for intruders up to about m2/m1 = 300 at eps = 0.5)");
}

// TracerTemperature::change at a settled θ: the grid with knots 3/2 as far apart, and with the coarse collision rule.
double grid_change(const SpeedGridProblem& p, double zeta1, double theta) {
  static const CollisionRule coarse(coarse_gas_points);
  return std::max(std::abs(solve_at(p, zeta1, theta, 1.5, fine_rule()).theta / theta - 1.0), std::abs(solve_at(p, zeta1, theta, 1.0, coarse).theta / theta - 1.0));
}

}  // namespace

TracerTemperature converged_tracer_temperature(const CollisionRates& rates, double zeta1, const PartnerShape& gas, double theta_start) {
  if (rates.size() != 2) throw std::invalid_argument("converged tracer temperature: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic()) throw std::invalid_argument("converged tracer temperature: constant restitution only");
  if (!(theta_start > 0.0 && std::isfinite(theta_start))) throw std::invalid_argument("converged tracer temperature: theta_start must be positive");
  if (!(zeta1 >= 0.0 && std::isfinite(zeta1))) throw std::invalid_argument("converged tracer temperature: zeta1 must be >= 0");
  const SpeedGridProblem p = speed_grid_problem(rates, gas);
  TracerTemperature out = settle(rates, p, zeta1, theta_start);
  if (std::isfinite(out.theta)) out.change = grid_change(p, zeta1, out.theta);
  return out;
}

KineticTracerGas kinetic_tracer_gas(const CollisionRates& rates) {
  const model::Mixture& mix = rates.mixture();
  const TracerLimit start = sonine_tracer_limit(rates, {true, 1});
  const SonineHcs gas = sonine_hcs(model::Mixture({mix[0]}), model::Restitution::constant(1, rates.law().eps(0, 0)), {{rates.chi(0, 0)}});
  return {std::isfinite(start.tau0) ? 2.0 / start.tau0 : 0.0, {1.0, 0.5 * gas.c[0], 0.0}, start.theta};
}

TracerTemperature converged_tracer_temperature(const CollisionRates& rates) {
  if (rates.size() != 2) throw std::invalid_argument("converged tracer temperature: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic()) return {};
  const KineticTracerGas gas = kinetic_tracer_gas(rates);
  return converged_tracer_temperature(rates, gas.zeta1, gas.shape, gas.theta_start);
}

TracerTemperature converged_intruder_temperature(const CollisionRates& rates, const TracerTemperature& tracer) {
  if (rates.size() != 2) throw std::invalid_argument("converged intruder temperature: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic()) return {};
  const KineticTracerGas gas = kinetic_tracer_gas(rates);
  TracerTemperature t = tracer;
  // Intruders: a small part of the gas's energy budget (else the gas's own shape and the intruders' mutual collisions,
  // both left out here, matter as much): omitted (NaN) above max_heating_share.
  if (!std::isfinite(t.theta) || !(std::abs(t.xi12) <= max_heating_share * gas.zeta1)) return {};
  // F(ζ) = ζ − ζ₁ − ξ₁₂(θ(ζ)) = 0 by the secant method from ζ₁ (F(ζ₁) = −ξ₁₂) and ζ₁ + ξ₁₂ (one fixed-point pass).
  double z0 = gas.zeta1, f0 = -t.xi12, z1 = gas.zeta1 + t.xi12;
  const SpeedGridProblem p = speed_grid_problem(rates, gas.shape);
  for (int pass = 0; pass < 20; ++pass) {
    const TracerTemperature next = settle(rates, p, z1, t.theta);  // the grid's change measured once, at the end
    if (!std::isfinite(next.theta)) return {};
    const double f1 = z1 - gas.zeta1 - next.xi12;
    const bool settled = std::abs(next.theta / t.theta - 1.0) < 1e-6;
    t = next;
    if (settled) {
      t.change = grid_change(p, z1, t.theta);
      return t;
    }
    const double z2 = f1 == f0 ? z1 : z1 - f1 * (z1 - z0) / (f1 - f0);
    z0 = z1, f0 = f1, z1 = z2;
    if (!(z1 > 0.0)) return {};
  }
  throw NumericalError("converged intruder temperature: zeta = zeta_1 + xi_12(theta) did not settle in 20 passes (theta " + std::to_string(t.theta) + ")");
}

}  // namespace granmix::theory
