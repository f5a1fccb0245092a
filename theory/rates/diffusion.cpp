#include "theory/rates/diffusion.hpp"

#include <limits>

#include "theory/rates/settled_ratios.hpp"

namespace granmix::theory {

SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) {
  const std::size_t N = rates.size();
  SettledDiffusion d;
  d.T = std::move(T);
  d.tau_v.resize(N);
  d.D.resize(N);
  d.D_ratio.resize(N);
  rates.inv_tau_v_all(d.T.data(), d.tau_v.data());
  for (std::size_t k = 0; k < N; ++k) {
    d.tau_v[k] = 1.0 / d.tau_v[k];
    d.D[k] = d.T[k] * d.tau_v[k] / rates.mixture()[k].mass;  // v1 Eq. (19)
  }
  for (std::size_t k = 0; k < N; ++k) d.D_ratio[k] = d.D[k] / d.D[0];
  const double xi1 = rates.xi_species(0, d.T.data());
  // τ₀ = 2/ξ (docs/physics.md §2); in the settled state every ξ_k equals ξ_1.
  d.tau0 = xi1 > 0.0 ? 2.0 / xi1 : std::numeric_limits<double>::infinity();
  return d;
}

SettledDiffusion settled_diffusion(const CollisionRates& rates) {
  return diffusion_at(rates, settled_temperatures(rates).T);
}

}  // namespace granmix::theory
