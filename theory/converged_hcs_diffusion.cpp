#include "converged_hcs_diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "parallel_each.hpp"
#include "tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

std::vector<double> converged_d_ratios(const CollisionRates& rates, const SettledHcs& state, std::vector<double>* basis) {
  const std::size_t N = rates.size();
  GalerkinOptions opt;
  opt.zeta = state.zeta;  // one ζ for every species: the HCS's (code units at its T)
  std::vector<double> a2(N);
  for (std::size_t k = 0; k < N; ++k) a2[k] = 0.5 * state.hcs.c[k];  // c_k = 2a₂,k
  opt.a2 = a2.data(), opt.a3 = state.hcs.a3.data();
  std::vector<double> D(N), change(N);
  // Each species' problem wholly on one thread: the numbers do not depend on the thread count.
  parallel_each(N, [&](std::size_t k) {
    const ConvergedDiffusion d = converged_tracer_diffusion(rates, k, state.hcs.T.data(), opt);
    D[k] = d.D, change[k] = converged_diffusion_change(d);
  });
  std::vector<double> ratios(N);
  if (basis != nullptr) basis->assign(N, 0.0);
  for (std::size_t k = 0; k < N; ++k) {
    ratios[k] = D[k] / D[0];
    if (basis != nullptr && k > 0) (*basis)[k] = change[k] + change[0];
  }
  return ratios;
}

std::vector<double> ConvergedRatioError::total() const {
  std::vector<double> t(grid.size());
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = grid[k] + hcs_partners[k] + partners[k] + basis[k];
  return t;
}

ConvergedRatioError converged_d_ratio_error(const CollisionRates& rates, const ConvergedHcs& checked) {
  if (checked.grid_variants.empty()) throw std::invalid_argument("converged_d_ratio_error: needs converged_hcs(rates, true)");
  const std::size_t N = rates.size();
  ConvergedRatioError e;
  const std::vector<double> d = converged_d_ratios(rates, checked, &e.basis);
  auto changes = [&](const SettledHcs& variant) {
    const std::vector<double> v = converged_d_ratios(rates, variant);
    std::vector<double> c(N, 0.0);
    for (std::size_t k = 1; k < N; ++k) c[k] = std::abs(v[k] / d[k] - 1.0);
    return c;
  };
  e.grid.assign(N, 0.0);
  for (const SettledHcs& v : checked.grid_variants) {
    const std::vector<double> c = changes(v);
    for (std::size_t k = 0; k < N; ++k) e.grid[k] = std::max(e.grid[k], 2.0 * c[k]);
  }
  e.hcs_partners = changes(checked.partners_full);
  SettledHcs no_a3 = checked;  // the same HCS, its a₃ left out of the tracer problem's shapes only
  std::fill(no_a3.hcs.a3.begin(), no_a3.hcs.a3.end(), 0.0);
  e.partners = changes(no_a3);
  return e;
}

}  // namespace granmix::theory
