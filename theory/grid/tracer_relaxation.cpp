#include "theory/grid/tracer_relaxation.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "theory/sonine/sonine_cooling.hpp"
#include "theory/grid/speed_grid.hpp"
#include "theory/grid/tracer_temperature.hpp"

namespace granmix::theory {

namespace {

constexpr double relaxation_widths = 8.0;  // U in units of √(θ₀/m₂), one more than the stationary solver's: θ may move by tens of percent from θ₀
constexpr double first_step = 1e-3, step_growth = 0.05;
// Settled (see relax_intruder's loop): the drift a step still shows, times the scaled time left, below this; then the
// settled steps grow by settled_growth up to settled_step/ζ.
constexpr double settle_tolerance = 1e-9, settled_growth = 1.5, settled_step = 0.2;

// Real time elapsed over a scaled-time step h at the cooling rate ζ (T₁ = T₁₀ e^(−ζσ), dt = dσ/√T₁): exact Haff clock.
double real_time(double h, double zeta, double T1) {
  const double x = 0.5 * zeta * h;
  return (std::abs(x) < 1e-12 ? h : std::expm1(x) / (0.5 * zeta)) / std::sqrt(T1);
}

// Scaled time from real time t to t_end at a constant cooling rate ζ from T₁ (the inverse of real_time).
double scaled_time_left(double t, double t_end, double zeta, double T1) {
  const double x = 0.5 * zeta * std::sqrt(T1) * (t_end - t);
  return std::abs(zeta) < 1e-300 ? std::sqrt(T1) * (t_end - t) : std::log1p(x) / (0.5 * zeta);
}

// The gas alone relaxes its cumulant c = 2a₂ linearly, dc/ds = g′(c − c₀) at T₁ = 1 (sonine_cooling.hpp, the ⟨w⁴⟩
// balance; g(c₀) = 0 at its HCS): g′.
double gas_cumulant_slope(const CollisionRates& rates, double c0) {
  const CollisionRates alone(model::Mixture({rates.mixture()[0]}), model::Restitution::constant(1, rates.law().eps(0, 0)), {{rates.chi(0, 0)}});
  const SonineCooling cooling(alone);
  const double T = 1.0, dc = 1e-3;
  double xi = 0.0, g0 = 0.0, g1 = 0.0, c = c0;
  cooling.rates(&T, &c, &xi, &g0);
  c = c0 + dc;
  cooling.rates(&T, &c, &xi, &g1);
  const double slope = (g1 - g0) / dc;  // g is linear in c: exact
  if (!(slope < 0.0)) throw NumericalError("intruder relaxation: the gas's cumulant does not relax (dg/dc = " + std::to_string(slope) + ")");
  return slope;
}

// The weak form with the gas at cumulant a₂: the collision parts are linear in the gas's shape (speed_grid.hpp),
// base at a₂ = 0 plus a₂ times the part of S₂.
SpeedGrid at_gas_a2(const SpeedGrid& base, const SpeedGrid& s2, double a2) {
  SpeedGrid g = base;
  g.collisions += a2 * s2.collisions, g.collisions_p1 += a2 * s2.collisions_p1;
  g.gain += a2 * s2.gain, g.drag += a2 * s2.drag, g.gain4 += a2 * s2.gain4;
  return g;
}

}  // namespace

TracerRelaxation relax_intruder(const CollisionRates& rates, double theta0, double t_end, RelaxationOptions opt) {
  if (rates.size() != 2) throw std::invalid_argument("intruder relaxation: needs exactly two species (gas, intruder)");
  if (rates.law().is_viscoelastic() || !(rates.law().eps(0, 0) < 1.0))
    throw std::invalid_argument("intruder relaxation: needs a constant restitution coefficient below 1 for the gas");
  if (!(theta0 > 0.0 && std::isfinite(theta0))) throw std::invalid_argument("intruder relaxation: theta0 must be positive");
  if (!(t_end > 0.0 && std::isfinite(t_end))) throw std::invalid_argument("intruder relaxation: t_end must be positive");
  const model::Mixture& mix = rates.mixture();
  const KineticTracerGas gas = kinetic_tracer_gas(rates);
  const SpeedGridProblem p = speed_grid_problem(rates, {1.0, 0.0, 0.0}), p2 = speed_grid_problem(rates, {0.0, 1.0, 0.0});
  static const CollisionRule rule(speed_grid_rule_points);
  const double width = std::sqrt(theta0 / p.m2), U = relaxation_widths * width;
  const auto K = std::size_t(relaxation_widths * speed_grid_knots);
  const SpeedGrid base = assemble_speed_grid(p, U, K, rule), s2 = assemble_speed_grid(p2, U, K, rule);
  // The gas's cumulant in time: from DSMC's Maxwellian start to its HCS (c₀ = 2a₂), or settled from the start.
  const double c0 = 2.0 * gas.shape.a2, slope = gas_cumulant_slope(rates, c0), xi11 = rates.xi(0, 0, 1.0, 1.0);
  auto gas_a2 = [&](double s) { return opt.gas_relaxes ? -0.5 * c0 * std::expm1(slope * s) : gas.shape.a2; };
  const double heating = -mix[1].density / (1.5 * mix[0].density);  // ξ₁₂ per unit gain
  const double loss = p.rate * std::numbers::pi * (3.0 * width + 2.0 * p.sd_gas), max_step = 2.0 / loss;
  auto moments = [&](const SpeedGrid& g, const Eigen::VectorXd& P) {
    const SpeedMoments m = speed_moments(g, p, P);
    if (!(m.theta > 0.5 * theta0 && m.theta < 1.5 * theta0))
      throw NumericalError("intruder relaxation: theta " + std::to_string(m.theta) + " left the speed grid's range around theta0 " +
                           std::to_string(theta0));
    return m;
  };
  // The intruders' mutual collisions with a Maxwellian partner at θ (v1 A1, A2 for the pair 22): their energy loss ξ₂₂ a
  // uniform contraction of the speeds (in the drift), their momentum exchange τ_v,22⁻¹ a uniform decay of q.
  auto xi22 = [&](double theta) { return opt.mutual_collisions ? rates.xi(1, 1, theta, theta) : 0.0; };
  auto inv_tau22 = [&](double theta) { return opt.mutual_collisions ? rates.inv_tau_v(1, 1, theta, theta) : 0.0; };
  auto A = [&](const SpeedGrid& g, double zeta, double theta) { return Eigen::MatrixXd(g.collisions + 0.5 * (zeta - xi22(theta)) * g.drift); };
  auto A1 = [&](const SpeedGrid& g, double zeta, double theta) {
    return Eigen::MatrixXd(g.collisions_p1 + 0.5 * (zeta - xi22(theta)) * g.drift - inv_tau22(theta) * g.gram);
  };
  auto nu22 = [&](double theta) { return inv_tau22(theta) + 0.5 * xi22(theta); };
  // The gas's state under the intruders: its cumulant a₂ (relaxing from the start) and cooling rate ξ₁₁(1 + 3a₂/16) (= ζ₁
  // settled), with their heating ξ₁₂ and, with gas_shape, the shift of its cumulant that heating sources, in both its
  // cooling rate and the intruders' collisions: δc = −source/g′, source = 2(1 + a₂)(S₄/⟨w⁴⟩ − 2S₂/⟨w²⟩),
  // ⟨w⁴⟩ = 15(1 + a₂)/m₁², S₂/⟨w²⟩ = −ξ₁₂ (quasi-static: c relaxes within a few collisions, the source over hundreds).
  struct GasState {
    double a2, zeta;
  };
  auto gas_state = [&](double s_at, const SpeedMoments& x) {
    const double a2 = gas_a2(s_at), xi12 = opt.heating ? heating * x.gain : 0.0;
    double shifted = a2;
    if (opt.heating && opt.gas_shape) {
      const double source = 2.0 * p.m1 * p.m1 * (mix[1].density / mix[0].density) * x.gain4 / 15.0 + 4.0 * (1.0 + a2) * xi12;
      shifted += -0.5 * source / slope;
    }
    return GasState{shifted, xi11 * (1.0 + 3.0 * shifted / 16.0) + xi12};
  };
  SpeedGrid g = at_gas_a2(base, s2, gas_a2(0.0));
  Eigen::VectorXd P = maxwellian_speed_density(g, p.m2, theta0);
  SpeedMoments m = moments(g, P);
  GasState gs = gas_state(0.0, m);
  if (opt.gas_shape) g = at_gas_a2(base, s2, gs.a2), m = moments(g, P), gs = gas_state(0.0, m);
  double zeta = gs.zeta, s = 0.0, t = 0.0, T1 = 1.0;
  TracerRelaxation out;
  out.theta_start.push_back(m.theta);
  // The displacement-weighted distribution q (l = 1, speed_grid.hpp) from q = 0, and the MSD M: dM/ds = 2 u1·q.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(P.size());
  double M = 0.0;
  out.msd_start.push_back(0.0), out.q_start.push_back(0.0);
  while (t < t_end) {
    const double h = std::min(max_step, first_step + step_growth * s);
    const Eigen::VectorXd rhs = (g.gram + 0.5 * h * A(g, zeta, m.theta)) * P;
    Eigen::VectorXd next = P;
    GasState gn = gas_state(s + h, m);
    SpeedGrid g_next = at_gas_a2(base, s2, gn.a2);
    SpeedMoments mn = m;
    for (int pass = 0; pass < 2; ++pass) {  // the new step's gas state and θ from its own solution
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(g.gram - 0.5 * h * A(g_next, gn.zeta, mn.theta));
      next = lu.solve(rhs);
      if (!next.allFinite()) throw NumericalError("intruder relaxation: a trapezoidal step's system is singular at s = " + std::to_string(s));
      mn = moments(g_next, next);
      gn = gas_state(s + h, mn);
      if (opt.gas_shape) g_next = at_gas_a2(base, s2, gn.a2), mn = moments(g_next, next);
    }
    const double zeta_next = gn.zeta;
    // q's trapezoidal step with the same ζ's; its source the speed density, moving.
    const Eigen::VectorXd q_next = Eigen::PartialPivLU<Eigen::MatrixXd>(g.gram - 0.5 * h * A1(g_next, zeta_next, mn.theta))
                                       .solve((g.gram + 0.5 * h * A1(g, zeta, m.theta)) * q + 0.5 * h * g.gram_u * (P / g.mass.dot(P) + next / g.mass.dot(next)));
    M += h * (g.u1.dot(q) + g.u1.dot(q_next));
    q = q_next;
    out.msd_start.push_back(M), out.q_start.push_back(g.u1.dot(q));
    const double z = 0.5 * (zeta + zeta_next);
    out.h.push_back(h), out.zeta.push_back(z);
    out.theta.push_back(0.5 * (m.theta + mn.theta)), out.nu.push_back(0.5 * (m.nu + mn.nu + nu22(m.theta) + nu22(mn.theta))), out.a2.push_back(0.5 * (m.a2 + mn.a2));
    out.theta_start.push_back(mn.theta);
    t += real_time(h, z, T1), T1 *= std::exp(-z * h), s += h;
    // Settled: where what this step changed (θ, ν, ζ, the intruder's Q = u₁·q), at its rate, would move them by less than
    // settle_tolerance over all the scaled time left, nothing changes any more: the rest in steps growing to
    // settled_step/ζ (the TAMSD's 3-point Gauss–Legendre pieces then see T₁ change by e^(−0.2)) without solves, P and q
    // staying, M growing by 2u₁·q h. Near ε = 1 the run to t_end is otherwise ~t_end·loss/2 steps: v2 Fig. 5's sizes at
    // ε = 0.999 would take 1.7e5 steps and 14 s; settled, 1.6 s, the MSD within 2e-12 and the TAMSD within 1e-7 of the
    // fine steps; where θ creeps to the end (v2 Fig. 5 itself) it never starts: its numbers are bitwise the same.
    const double left = scaled_time_left(t, t_end, zeta_next, T1), q0 = out.q_start[out.q_start.size() - 2], q1 = out.q_start.back();
    const double drift = std::max({std::abs(mn.theta / m.theta - 1.0), std::abs(mn.nu / m.nu - 1.0), std::abs(zeta_next / zeta - 1.0),
                                   std::abs(q1 / q0 - 1.0)}) / h * left;
    P = next, m = mn, zeta = zeta_next, g = g_next;
    if (!opt.settle || !(drift < settle_tolerance) || !(zeta > 0.0)) continue;
    for (double hs = h; t < t_end;) {
      hs = std::min(settled_growth * hs, settled_step / zeta);
      M += 2.0 * hs * q1;
      out.msd_start.push_back(M), out.q_start.push_back(q1);
      out.h.push_back(hs), out.zeta.push_back(zeta);
      out.theta.push_back(m.theta), out.nu.push_back(m.nu + nu22(m.theta)), out.a2.push_back(m.a2);
      out.theta_start.push_back(m.theta);
      t += real_time(hs, zeta, T1), T1 *= std::exp(-zeta * hs), s += hs;
    }
  }
  return out;
}

}  // namespace granmix::theory
