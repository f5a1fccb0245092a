#include "unit_cost.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pair_table.hpp"

namespace granmix::dsmc {

double estimated_collisions(const DsmcSetup& s) {
  const model::Mixture& mix = s.mixture;
  const std::size_t M = mix.size();
  const PairTable pairs(mix, s.chi, 1.0);
  // Above 200 species the pair sums run over every stride-th species (each standing for its
  // neighbours' density): the estimate orders work, and an O(M²) loop over 5000 species would not pay.
  const std::size_t stride = std::max<std::size_t>(1, M / 200);
  double sampled_density = 0.0, T = 0.0;
  for (std::size_t i = 0; i < M; i += stride) sampled_density += mix[i].density;
  for (std::size_t k = 0; k < M; ++k) T += mix.fraction(k) * s.T0[k];
  const double density_scale = mix.total_density() / sampled_density;
  double nu = 0.0, loss = 0.0;  // per particle: collision frequency, energy loss rate
  for (std::size_t k = 0; k < M; k += stride)
    for (std::size_t i = 0; i < M; i += stride) {
      const double V = s.T0[k] / mix[k].mass + s.T0[i] / mix[i].mass;  // variance of one component of g
      const double rate = mix[i].density * density_scale * std::numbers::pi * pairs.sigma2(k, i) * pairs.chi(k, i) *
                          std::sqrt(8.0 * V / std::numbers::pi);
      const double w = mix.fraction(k) * density_scale * double(stride), eps = s.law.eps_at(k, i, std::sqrt(V));
      const double reduced = mix[k].mass * mix[i].mass / (mix[k].mass + mix[i].mass);
      nu += w * rate;
      // A collision loses (1 − ε²) m_red g_n²/2 with ⟨g_n²⟩ = 2V over collisions (weight |g_n|),
      // shared by the two particles.
      loss += w * rate * (1.0 - eps * eps) * reduced * V / 2.0;
    }
  double xi = loss / (1.5 * T);  // dT/dt = −ξ T
  double t_end = s.times.empty() ? 0.0 : s.times.back();
  if (s.tamsd_measurement_time > 0.0) t_end = std::max(t_end, s.tamsd_measurement_time);
  auto per_particle = [&](double nu0, double xi0, double t) {
    return xi0 * t < 1e-8 ? nu0 * t : 2.0 * nu0 / xi0 * std::log1p(xi0 * t / 2.0);
  };
  double c = 0.0;
  if (s.aged && T > 1.0 && xi > 0.0) {
    c += nu / xi * std::log(T);  // Haff from T_hot to 1: 1 + ξ̄t/2 = √T_hot
    nu /= std::sqrt(T), xi /= std::sqrt(T), T = 1.0;  // nu, ξ ∝ √T
  }
  c += per_particle(nu, xi, t_end);
  double N = 0.0;
  for (std::size_t n : s.counts) N += double(n);
  return N * c / 2.0;  // each collision involves two particles
}

}  // namespace granmix::dsmc
