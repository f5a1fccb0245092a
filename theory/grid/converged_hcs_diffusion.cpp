#include "theory/grid/converged_hcs_diffusion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "theory/numerics/parallel_each.hpp"
#include "theory/grid/partner_axial_shape.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

std::vector<double> converged_d_ratios(const CollisionRates& rates, const SettledHcs& state, std::vector<double>* basis, bool full_shapes) {
  const std::size_t N = rates.size();
  GalerkinOptions opt;
  opt.zeta = state.zeta;  // one ζ for every species: the HCS's (code units at its T)
  std::vector<double> a2(N);
  for (std::size_t k = 0; k < N; ++k) a2[k] = 0.5 * state.hcs.c[k];  // c_k = 2a₂,k
  opt.a2 = a2.data(), opt.a3 = state.hcs.a3.data();
  std::vector<AxialShape> shapes;
  if (full_shapes) {
    if (state.density.size() != N) throw std::invalid_argument("converged_d_ratios: full shapes need every species' solved density");
    for (std::size_t k = 0; k < N; ++k) shapes.emplace_back(state.density[k], state.hcs.T[k] / rates.mixture()[k].mass);
    opt.full = &shapes;
  }
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
  // The same HCS, the tracer problem seeing every partner and the species' own source through the solved densities.
  const std::vector<double> full = converged_d_ratios(rates, checked, nullptr, true);
  e.partners.assign(N, 0.0);
  for (std::size_t k = 1; k < N; ++k) e.partners[k] = std::abs(full[k] / d[k] - 1.0);
  return e;
}

}  // namespace granmix::theory
