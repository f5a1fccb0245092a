#include "unit_cost.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pair_table.hpp"

namespace granmix::dsmc {

namespace {

// One sampled species pair (k, i) at the start: its weight in the mean over particles, collision rate
// per particle of k, and what one collision loses per unit (1 − ε²): m_red ⟨g_n²⟩/2 = m_red V, half of
// it to each particle (⟨g_n²⟩ = 2V over collisions, weight |g_n|; V = T_k/m_k + T_i/m_i).
struct PairRate {
  std::size_t k, i;
  double weight, rate, loss_scale, speed;  // speed: the typical normal impact speed √V
};

}  // namespace

double estimated_collisions(const DsmcSetup& s) {
  const model::Mixture& mix = s.mixture;
  const std::size_t M = mix.size();
  const PairTable pairs(mix, s.chi, 1.0);
  // Above 50 species the pair sums run over every stride-th species, each standing for its
  // neighbours' density: the estimate orders work, and a 5000² loop would not pay.
  const std::size_t stride = std::max<std::size_t>(1, M / 50);
  double sampled = 0.0, T = 0.0;
  for (std::size_t i = 0; i < M; i += stride) sampled += mix[i].density;
  for (std::size_t k = 0; k < M; ++k) T += mix.fraction(k) * s.T0[k];
  const double scale = mix.total_density() / sampled;  // sampled species → all species
  std::vector<PairRate> rates;
  double nu = 0.0;  // mean collision frequency per particle at the start
  for (std::size_t k = 0; k < M; k += stride)
    for (std::size_t i = 0; i < M; i += stride) {
      const double V = s.T0[k] / mix[k].mass + s.T0[i] / mix[i].mass;
      const double rate = mix[i].density * scale * std::numbers::pi * pairs.sigma2(k, i) * pairs.chi(k, i) * std::sqrt(8.0 * V / std::numbers::pi);
      const double reduced = mix[k].mass * mix[i].mass / (mix[k].mass + mix[i].mass);
      rates.push_back({k, i, mix.fraction(k) * scale, rate, reduced * V / 2.0, std::sqrt(V)});
      nu += rates.back().weight * rate;
    }
  // Everything scales with τ = T(t)/T(0): ν ∝ √τ, speeds ∝ √τ, and ξ(τ) = √τ Σ w rate (1 − ε²) loss / (3T/2).
  auto xi = [&](double tau) {
    double loss = 0.0;
    for (const PairRate& p : rates) {
      const double eps = s.law.eps_at(p.k, p.i, p.speed * std::sqrt(tau));
      loss += p.weight * p.rate * (1.0 - eps * eps) * p.loss_scale;
    }
    return std::sqrt(tau) * loss / (1.5 * T);
  };
  double t_end = s.times.empty() ? 0.0 : s.times.back();
  if (s.tamsd_measurement_time > 0.0) t_end = std::max(t_end, s.tamsd_measurement_time);
  double collisions = 0.0;  // per particle
  if (!s.law.is_viscoelastic()) {
    // Constant ε: ξ ∝ √τ, Haff's law T = T0/(1 + ξ0 t/2)², collisions (2ν/ξ0) ln(1 + ξ0 t/2).
    double nu0 = nu, xi0 = xi(1.0);
    if (s.aged && T > 1.0 && xi0 > 0.0) {
      collisions += nu0 / xi0 * std::log(T);  // from T_hot to ⟨T⟩ = 1: 1 + ξ0 t/2 = √T_hot
      nu0 /= std::sqrt(T), xi0 /= std::sqrt(T);
    }
    collisions += xi0 * t_end < 1e-8 ? nu0 * t_end : 2.0 * nu0 / xi0 * std::log1p(xi0 * t_end / 2.0);
  } else {
    // Viscoelastic: ε → 1 as the gas cools, so ξ falls faster than √τ; integrate in u = ln τ:
    // dt = −du/ξ(τ), dC = ν0 √τ dt. An aged start first cools to ⟨T⟩ = 1 (τ = 1/T_hot), clock reset.
    const double du = 0.1, tau_start = s.aged && T > 1.0 ? 1.0 / T : 1.0;
    double u = 0.0, t = 0.0;
    bool measuring = tau_start == 1.0;
    for (int step = 0; step < 100000; ++step) {
      const double tau = std::exp(u - du / 2.0), x = xi(tau);
      const double dt = x > 0.0 ? du / x : INFINITY;
      if (!measuring && u - du <= std::log(tau_start)) {  // the aged gas reaches ⟨T⟩ = 1 in this step
        collisions += nu * std::sqrt(tau) * (u - std::log(tau_start)) / x;
        u = std::log(tau_start), measuring = true;
        continue;
      }
      if (measuring && t + dt >= t_end) {
        collisions += nu * std::sqrt(tau) * (t_end - t);
        break;
      }
      collisions += nu * std::sqrt(tau) * dt;
      if (measuring) t += dt;
      u -= du;
    }
  }
  double N = 0.0;
  for (std::size_t n : s.counts) N += double(n);
  return N * collisions / 2.0;  // each collision involves two particles
}

}  // namespace granmix::dsmc
