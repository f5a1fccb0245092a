#include "theory/rates/cooling_model.hpp"

#include <algorithm>

namespace granmix::theory {

MaxwellClosures::MaxwellClosures(const CollisionRates& rates, bool fused)
    : rates_(rates), fused_(fused), T_(rates.size()), inv_tau_(rates.size()) {}

void MaxwellClosures::rates(const double* T, const double*, double* xi, double*) const {
  if (!fused_) return rates_.xi_all(T, xi);
  rates_.xi_and_inv_tau_v_all(T, xi, inv_tau_.data());
  std::copy(T, T + T_.size(), T_.begin());
  cached_ = true;
}

void VelocityDecay::correlation_rates(const CollisionRates& r, const double* T, const double* xi, const double* Q, double* dQ,
                                      double* nu, const double*, const double*) const {
  rates(T, xi, nu);
  for (std::size_t k = 0; k < r.size(); ++k) dQ[k] = 3.0 * T[k] / r.mixture()[k].mass - Q[k] * nu[k];
}

void MaxwellClosures::rates(const double* T, const double* xi, double* nu) const {
  const std::size_t N = T_.size();
  if (cached_ && std::equal(T, T + N, T_.begin()))
    std::copy(inv_tau_.begin(), inv_tau_.end(), nu);
  else
    rates_.inv_tau_v_all(T, nu);
  for (std::size_t k = 0; k < N; ++k) nu[k] = nu[k] + 0.5 * xi[k];
}

}  // namespace granmix::theory
