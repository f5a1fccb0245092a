#include "tracer_limit.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "bracketed_root.hpp"

namespace granmix::theory {

TracerLimit tracer_limit(const CollisionRates& r) {
  if (r.size() != 2) throw std::invalid_argument("tracer limit: needs exactly two species (gas, intruder)");
  TracerLimit out;
  const double xi11 = r.xi(0, 0, 1.0, 1.0);
  out.tau0 = xi11 > 0.0 ? 2.0 / xi11 : std::numeric_limits<double>::infinity();
  out.tau_v_gas = 1.0 / r.inv_tau_v(0, 0, 1.0, 1.0);
  out.D_gas = out.tau_v_gas / r.mixture()[0].mass;
  const double scale = std::abs(xi11) + 1.0 / out.tau_v_gas;
  const double root = bracketed_root(
      [&](double x) { return (r.xi(1, 0, std::exp(x), 1.0) - xi11) / scale; }, "tracer limit: ξ_21(θ) = ξ_11").x;
  out.theta = std::exp(root);
  out.tau_v_intruder = 1.0 / r.inv_tau_v(1, 0, out.theta, 1.0);
  out.D_intruder = out.theta * out.tau_v_intruder / r.mixture()[1].mass;
  return out;
}

}  // namespace granmix::theory
