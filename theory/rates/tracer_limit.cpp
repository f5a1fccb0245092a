#include "theory/rates/tracer_limit.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "theory/numerics/bracketed_root.hpp"

namespace granmix::theory {

TracerLimit tracer_state(const CollisionRates& r, double theta, double tau0) {
  if (r.size() != 2) throw std::invalid_argument("tracer limit: needs exactly two species (gas, intruder)");
  TracerLimit out;
  out.theta = theta;
  out.tau0 = tau0;
  out.tau_v_gas = 1.0 / r.inv_tau_v(0, 0, 1.0, 1.0);
  out.D_gas = out.tau_v_gas / r.mixture()[0].mass;
  out.tau_v_intruder = 1.0 / r.inv_tau_v(1, 0, theta, 1.0);
  out.D_intruder = theta * out.tau_v_intruder / r.mixture()[1].mass;
  return out;
}

TracerLimit tracer_limit(const CollisionRates& r) {
  if (r.size() != 2) throw std::invalid_argument("tracer limit: needs exactly two species (gas, intruder)");
  const double xi11 = r.xi(0, 0, 1.0, 1.0);
  const double tau0 = xi11 > 0.0 ? 2.0 / xi11 : std::numeric_limits<double>::infinity();
  const double tau_v_gas = 1.0 / r.inv_tau_v(0, 0, 1.0, 1.0);
  const double scale = std::abs(xi11) + 1.0 / tau_v_gas;
  const double root = bracketed_root(
      [&](double x) { return (r.xi(1, 0, std::exp(x), 1.0) - xi11) / scale; }, "tracer limit: ξ_21(θ) = ξ_11").x;
  return tracer_state(r, std::exp(root), tau0);
}

}  // namespace granmix::theory
