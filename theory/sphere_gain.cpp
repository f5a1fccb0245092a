#include "sphere_gain.hpp"

#include <algorithm>
#include <cmath>

namespace granmix::theory {

namespace {

// The four cubic B-splines nonzero on a knot interval, s = h(q + t), 0 ≤ t < 1: N_e(t) for spline q + e.
void splines_at(double t, double out[4]) {
  const double r = 1.0 - t, t2 = t * t, t3 = t2 * t;
  out[0] = r * r * r / 6.0;
  out[1] = (4.0 - 6.0 * t2 + 3.0 * t3) / 6.0;
  out[2] = (1.0 + 3.0 * t + 3.0 * t2 - 3.0 * t3) / 6.0;
  out[3] = t3 / 6.0;
}

// M[p][e] = ∫₀ᵗ τᵖ N_e(τ) dτ, p = 0, 1, 2 (p = 2 only with second: the speed density needs p ≤ 1, a third fewer
// polynomials in its innermost loop).
using Moments = std::array<std::array<double, 4>, 3>;
Moments moments_to(double t, bool second = true) {
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t, t6 = t5 * t, r = 1.0 - t;
  Moments M{};
  M[0] = {(1.0 - r * r * r * r) / 24.0, (4.0 * t - 2.0 * t3 + 0.75 * t4) / 6.0, (t + 1.5 * t2 + t3 - 0.75 * t4) / 6.0, t4 / 24.0};
  M[1] = {(0.5 * t2 - t3 + 0.75 * t4 - 0.2 * t5) / 6.0, (2.0 * t2 - 1.5 * t4 + 0.6 * t5) / 6.0, (0.5 * t2 + t3 + 0.75 * t4 - 0.6 * t5) / 6.0,
          0.2 * t5 / 6.0};
  if (!second) return M;
  M[2] = {(t3 / 3.0 - 0.75 * t4 + 0.6 * t5 - t6 / 6.0) / 6.0, (4.0 * t3 / 3.0 - 1.2 * t5 + 0.5 * t6) / 6.0,
          (t3 / 3.0 + 0.75 * t4 + 0.6 * t5 - 0.5 * t6) / 6.0, t6 / 36.0};
  return M;
}

const Moments& whole_interval() {
  static const Moments M = moments_to(1.0);
  return M;
}

}  // namespace

SphereGain::SphereGain(std::size_t nb, double h) : h_(h), nb_(nb), gain_(nb + 3), whole_(nb + 3) {}

void SphereGain::clear() {
  std::fill(gain_.begin(), gain_.end(), 0.0);
  std::fill(whole_.begin(), whole_.end(), std::array<double, 3>{});
}

// On interval q, with a_p = h^(p+1) W_p: ∫ N_(q+e)(s) Σ_p W_p sᵖ ds = Σ_p a_p ∫ N_e(t)(q + t)ᵖ dt
//   = (a₀ + a₁q + a₂q²) ΔM₀ + (a₁ + 2a₂q) ΔM₁ + a₂ ΔM₂.
void SphereGain::add_range(double s_lo, double s_hi, const std::array<double, 3>& W) {
  const double x_lo = s_lo / h_, x_hi = std::min(s_hi / h_, double(nb_));  // beyond: only the dropped entries
  if (x_lo >= x_hi) return;
  const std::array<double, 3> a = {h_ * W[0], h_ * h_ * W[1], h_ * h_ * h_ * W[2]};
  auto add = [&](std::size_t q, const Moments& M, double sign) {
    const double fq = double(q), c0 = sign * (a[0] + fq * (a[1] + fq * a[2])), c1 = sign * (a[1] + 2.0 * fq * a[2]), c2 = sign * a[2];
    for (std::size_t e = 0; e < 4; ++e) gain_[q + e] += c0 * M[0][e] + c1 * M[1][e] + c2 * M[2][e];
  };
  const bool second = W[2] != 0.0;
  const auto q_lo = std::size_t(x_lo), q_hi = std::min(std::size_t(x_hi), nb_ - 1);
  const Moments lo = moments_to(x_lo - double(q_lo), second);
  if (q_lo == q_hi) {
    add(q_lo, moments_to(x_hi - double(q_lo), second), 1.0);
    return add(q_lo, lo, -1.0);
  }
  add(q_lo, whole_interval(), 1.0), add(q_lo, lo, -1.0);                          // [t_lo, 1] of interval q_lo
  if (x_hi > double(q_hi)) add(q_hi, moments_to(x_hi - double(q_hi), second), 1.0);       // [0, t_hi] of interval q_hi
  for (std::size_t p = 0; p < 3; ++p) whole_[q_lo + 1][p] += a[p], whole_[q_hi][p] -= a[p];  // q_lo < q < q_hi
}

void SphereGain::add_point(double s, double weight) {
  const double x = s / h_;
  const auto j0 = std::size_t(x);
  if (j0 >= nb_) return;
  double N[4];
  splines_at(x - double(j0), N);
  for (std::size_t e = 0; e < 4; ++e) gain_[j0 + e] += weight * N[e];
}

std::vector<double>& SphereGain::finish() {
  const Moments& M = whole_interval();
  std::array<double, 3> a{};
  for (std::size_t q = 0; q < nb_; ++q) {
    for (std::size_t p = 0; p < 3; ++p) a[p] += whole_[q][p];
    if (a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0) continue;
    const double fq = double(q), c0 = a[0] + fq * (a[1] + fq * a[2]), c1 = a[1] + 2.0 * fq * a[2], c2 = a[2];
    for (std::size_t e = 0; e < 4; ++e) gain_[q + e] += c0 * M[0][e] + c1 * M[1][e] + c2 * M[2][e];
  }
  return gain_;
}

}  // namespace granmix::theory
