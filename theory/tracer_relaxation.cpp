#include "tracer_relaxation.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "tracer_speed_grid.hpp"
#include "tracer_temperature.hpp"

namespace granmix::theory {

namespace {

constexpr double domain_widths = 8.0;  // U in units of √(θ₀/m₂): θ may move by tens of percent from θ₀
constexpr double steps_per_width = 8;  // knots per √(θ₀/m₂), as the stationary solver's
constexpr std::size_t gas_points = 12;  // the stationary solver's collision quadrature
constexpr double first_step = 1e-3, step_growth = 0.05;

// Real time elapsed over a scaled-time step h at the cooling rate ζ (T₁ = T₁₀ e^(−ζσ), dt = dσ/√T₁): exact Haff clock.
double real_time(double h, double zeta, double T1) {
  const double x = 0.5 * zeta * h;
  return (std::abs(x) < 1e-12 ? h : std::expm1(x) / (0.5 * zeta)) / std::sqrt(T1);
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
  const SpeedGridProblem p = speed_grid_problem(rates, gas.shape);
  static const CollisionRule rule(gas_points);
  const double width = std::sqrt(theta0 / p.m2);
  const SpeedGrid g = assemble_speed_grid(p, domain_widths * width, std::size_t(domain_widths * steps_per_width), rule);
  const double heating = -mix[1].density / (1.5 * mix[0].density);  // ξ₁₂ per unit gain
  const double loss = p.rate * std::numbers::pi * (3.0 * width + 2.0 * p.sd_gas), max_step = 2.0 / loss;
  auto moments = [&](const Eigen::VectorXd& P) {
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
  auto A = [&](double zeta, double theta) { return Eigen::MatrixXd(g.collisions + 0.5 * (zeta - xi22(theta)) * g.drift); };
  auto A1 = [&](double zeta, double theta) {
    return Eigen::MatrixXd(g.collisions_p1 + 0.5 * (zeta - xi22(theta)) * g.drift - inv_tau22(theta) * g.gram);
  };
  auto nu22 = [&](double theta) { return inv_tau22(theta) + 0.5 * xi22(theta); };
  auto gas_rate = [&](const SpeedMoments& x) { return gas.zeta1 + (opt.heating ? heating * x.gain : 0.0); };
  Eigen::VectorXd P = maxwellian_speed_density(g, p.m2, theta0);
  SpeedMoments m = moments(P);
  double zeta = gas_rate(m), s = 0.0, t = 0.0, T1 = 1.0;
  TracerRelaxation out;
  out.theta_start.push_back(m.theta);
  // The displacement-weighted distribution q (l = 1, tracer_speed_grid.hpp) from q = 0, and the MSD M: dM/ds = 2 u1·q.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(P.size());
  double M = 0.0;
  out.msd_start.push_back(0.0), out.q_start.push_back(0.0);
  while (t < t_end) {
    const double h = std::min(max_step, first_step + step_growth * s);
    const Eigen::VectorXd rhs = (g.gram + 0.5 * h * A(zeta, m.theta)) * P;
    Eigen::VectorXd next = P;
    double zeta_next = zeta;
    SpeedMoments mn = m;
    for (int pass = 0; pass < 2; ++pass) {  // the new step's ζ and θ from its own solution
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(g.gram - 0.5 * h * A(zeta_next, mn.theta));
      next = lu.solve(rhs);
      if (!next.allFinite()) throw NumericalError("intruder relaxation: a trapezoidal step's system is singular at s = " + std::to_string(s));
      mn = moments(next);
      zeta_next = gas_rate(mn);
    }
    // q's trapezoidal step with the same ζ's; its source the speed density, moving.
    const Eigen::VectorXd q_next = Eigen::PartialPivLU<Eigen::MatrixXd>(g.gram - 0.5 * h * A1(zeta_next, mn.theta))
                                       .solve((g.gram + 0.5 * h * A1(zeta, m.theta)) * q + 0.5 * h * g.gram_u * (P / g.mass.dot(P) + next / g.mass.dot(next)));
    M += h * (g.u1.dot(q) + g.u1.dot(q_next));
    q = q_next;
    out.msd_start.push_back(M), out.q_start.push_back(g.u1.dot(q));
    const double z = 0.5 * (zeta + zeta_next);
    out.h.push_back(h), out.zeta.push_back(z);
    out.theta.push_back(0.5 * (m.theta + mn.theta)), out.nu.push_back(0.5 * (m.nu + mn.nu + nu22(m.theta) + nu22(mn.theta))), out.a2.push_back(0.5 * (m.a2 + mn.a2));
    out.theta_start.push_back(mn.theta);
    t += real_time(h, z, T1), T1 *= std::exp(-z * h), s += h;
    P = next, m = mn, zeta = zeta_next;
  }
  return out;
}

}  // namespace granmix::theory
