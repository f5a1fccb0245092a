#include "tagged_particle_mc.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace granmix::test {

using std::numbers::pi;

McDiffusion tagged_particle_mc(const std::vector<Partner>& partners, double zeta, double sd_k, double corr_time,
                               double correlation_times, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N01;
  std::uniform_real_distribution<double> U01;
  std::exponential_distribution<double> Exp1;
  auto gauss_vec = [&](double sd) { return Vec{sd * N01(rng), sd * N01(rng), sd * N01(rng)}; };
  const double grid = corr_time / 10, cutoff = 10 * corr_time, burn = 20 * corr_time;
  const std::size_t lag = std::size_t(cutoff / grid), batches = 100;
  const std::size_t points = std::size_t(correlation_times * corr_time / grid), per_batch = points / batches;
  std::vector<Vec> ring_u(2 * lag + 1), ring_X(2 * lag + 1);
  std::vector<double> batch_sum(batches, 0.0), batch_u2(batches, 0.0);
  Vec u = gauss_vec(sd_k), X = {0, 0, 0};
  double s = 0.0, next_grid = burn;
  std::size_t recorded = 0;
  McDiffusion out;
  auto drift = [&](double ds) {  // u(s) = u e^{ζs/2}, X += ∫u
    const double grow = std::exp(0.5 * zeta * ds), integral = zeta > 0 ? (grow - 1) / (0.5 * zeta) : ds;
    X = axpy(integral, u, X);
    for (double& x : u) x *= grow;
    s += ds;
  };
  auto advance = [&](double target) {  // to target, recording every grid point on the way
    while (next_grid <= target && recorded < points + 2 * lag) {
      drift(next_grid - s);
      const std::size_t n = 2 * lag + 1, b = recorded % n;
      ring_u[b] = u, ring_X[b] = X;
      if (recorded >= 2 * lag && (recorded - 2 * lag) / per_batch < batches) batch_u2[(recorded - 2 * lag) / per_batch] += dot(u, u);
      if (recorded >= 2 * lag) {  // centre c = recorded − U, window [c − U, c + U]
        const std::size_t c = (recorded - lag) % n, e = (recorded - 2 * lag) % n, index = (recorded - 2 * lag) / per_batch;
        if (index < batches) batch_sum[index] += 0.5 * dot(ring_u[c], axpy(-1.0, ring_X[e], ring_X[b]));
      }
      ++recorded, next_grid += grid;
    }
    drift(target - s);
  };
  std::vector<double> mean_speed(partners.size());
  for (std::size_t i = 0; i < partners.size(); ++i) mean_speed[i] = 2 * partners[i].sd * std::sqrt(2 / pi);
  while (recorded < points + 2 * lag) {
    // Thinning over a window h in which |u| ≤ u_max; candidate w from f_i(w)(u_max + |w|).
    // h = one mean free time at the present speed, so u_max stays within e^{ζh/2} of |u|.
    const double speed = std::sqrt(dot(u, u));
    double total = 0;
    for (std::size_t i = 0; i < partners.size(); ++i) total += pi * partners[i].weight * (speed + mean_speed[i]);
    const double h0 = 1.0 / total, umax = speed * std::exp(0.5 * zeta * h0);
    std::vector<double> rate(partners.size());
    total = 0;
    for (std::size_t i = 0; i < partners.size(); ++i) total += rate[i] = pi * partners[i].weight * (umax + mean_speed[i]);
    const double wait = Exp1(rng) / total;
    if (wait > h0) {
      advance(s + h0);
      continue;
    }
    advance(s + wait);
    double pick = U01(rng) * total;
    std::size_t i = 0;
    while (i + 1 < partners.size() && pick > rate[i]) pick -= rate[i++];
    const Partner& P = partners[i];
    Vec w;
    if (U01(rng) * (umax + mean_speed[i]) < umax) {
      w = gauss_vec(P.sd);
    } else {  // density ∝ |w| f(w): |w|²/(2 sd²) ~ Gamma(2, 1), isotropic direction
      const double r = P.sd * std::sqrt(2 * (Exp1(rng) + Exp1(rng)));
      w = gauss_vec(1.0);
      const double n = std::sqrt(dot(w, w));
      for (double& x : w) x *= r / n;
    }
    const Vec g = axpy(-1.0, w, u);
    const double gn = std::sqrt(dot(g, g));
    if (U01(rng) * (umax + std::sqrt(dot(w, w))) >= gn) continue;  // rejected candidate
    // σ̂ around ĝ with density ∝ cos θ: cos θ = √U.
    const Vec e3 = {g[0] / gn, g[1] / gn, g[2] / gn};
    const Vec t = std::abs(e3[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0};
    Vec e1 = axpy(-dot(t, e3), e3, t);
    const double n1 = std::sqrt(dot(e1, e1));
    for (double& x : e1) x /= n1;
    const Vec e2 = {e3[1] * e1[2] - e3[2] * e1[1], e3[2] * e1[0] - e3[0] * e1[2], e3[0] * e1[1] - e3[1] * e1[0]};
    const double ct = std::sqrt(U01(rng)), st = std::sqrt(1 - ct * ct), phi = 2 * pi * U01(rng);
    Vec sigma;
    for (int d = 0; d < 3; ++d) sigma[d] = st * std::cos(phi) * e1[d] + st * std::sin(phi) * e2[d] + ct * e3[d];
    u = axpy(-P.beta * gn * ct, sigma, u);
    ++out.collisions;
  }
  double m = 0, m2 = 0;
  for (double b : batch_sum) {
    const double x = b / (3.0 * per_batch);
    m += x / batches, m2 += x * x / batches;
  }
  out.D = m, out.err = std::sqrt((m2 - m * m) / (batches - 1));
  m = 0, m2 = 0;
  for (double b : batch_u2) {
    const double x = b / double(per_batch);
    m += x / batches, m2 += x * x / batches;
  }
  out.u2 = m, out.u2_err = std::sqrt((m2 - m * m) / (batches - 1));
  return out;
}

}  // namespace granmix::test
