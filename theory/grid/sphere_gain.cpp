#include "theory/grid/sphere_gain.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace granmix::theory {

namespace {

// The four cubic B-splines nonzero on a knot interval, s = h(q + t), 0 ≤ t < 1: N_e(t) = Σ_k spline_terms[e][k] tᵏ
// for spline q + e.
constexpr double spline_terms[4][4] = {
    {1.0 / 6.0, -3.0 / 6.0, 3.0 / 6.0, -1.0 / 6.0},
    {4.0 / 6.0, 0.0, -6.0 / 6.0, 3.0 / 6.0},
    {1.0 / 6.0, 3.0 / 6.0, 3.0 / 6.0, -3.0 / 6.0},
    {0.0, 0.0, 0.0, 1.0 / 6.0},
};

void splines_at(double t, double out[4]) {
  for (std::size_t e = 0; e < 4; ++e)
    out[e] = spline_terms[e][0] + t * (spline_terms[e][1] + t * (spline_terms[e][2] + t * spline_terms[e][3]));
}

// The coefficient of tⁿ (n = 1 … 6) in ∫₀ᵗ (q + τ)ᵖ N_e(τ) dτ = Σ_j C(p, j) q^(p−j) Σ_k spline_terms[e][k] t^(k+j+1)/(k+j+1).
double interval_term(std::size_t q, std::size_t p, std::size_t e, std::size_t n) {
  constexpr double binomial[3][3] = {{1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {1.0, 2.0, 1.0}};
  double sum = 0.0;
  for (std::size_t j = 0; j <= p; ++j)
    if (n >= j + 1 && n - j - 1 < 4) sum += binomial[p][j] * std::pow(double(q), double(p - j)) * spline_terms[e][n - j - 1] / double(n);
  return sum;
}

}  // namespace

// The tables of nb splines (they do not depend on h), built once per nb: an assembly makes a SphereGain per knot interval.
const SphereGain::Terms& SphereGain::terms(std::size_t nb) {
  static std::mutex guard;
  static std::map<std::size_t, Terms> built;  // nodes stay where they are: the references handed out stay valid
  const std::lock_guard<std::mutex> lock(guard);
  const auto found = built.find(nb);
  if (found != built.end()) return found->second;
  Terms t{std::vector<double>(3 * nb * 4 * powers), std::vector<std::array<double, 3>>(nb)};
  for (std::size_t p = 0; p < 3; ++p)
    for (std::size_t q = 0; q < nb; ++q)
      for (std::size_t e = 0; e < 4; ++e) {
        double* c = t.interval.data() + ((p * nb + q) * 4 + e) * powers;
        for (std::size_t n = 1; n < powers; ++n) c[n] = interval_term(q, p, e, n);
        // n = 0: spline q + e over the intervals below q (an end in interval q has passed those)
        for (std::size_t below = q + e >= 3 ? q + e - 3 : 0; below < q; ++below)
          for (std::size_t n = 1; n < powers; ++n) c[0] += interval_term(below, p, q + e - below, n);
        if (q + e < nb)  // interval q's whole share of spline q + e (t = 1): summed, the spline's support above 0
          for (std::size_t n = 1; n < powers; ++n) t.whole[q + e][p] += interval_term(q, p, e, n);
      }
  return built.emplace(nb, std::move(t)).first->second;
}

SphereGain::SphereGain(std::size_t nb, double h)
    : h_(h), inv_h_(1.0 / h), nb_(nb), gain_(nb + 3), storage_(3 * nb * stride + stride), terms_(terms(nb)) {
  void* start = storage_.data();
  std::size_t space = storage_.size() * sizeof(double);
  sums_ = static_cast<double*>(std::align(stride * sizeof(double), 3 * nb * stride * sizeof(double), start, space));
  if (sums_ == nullptr) throw std::logic_error("SphereGain: std::align found no 64-byte line in its storage");
}

void SphereGain::clear() {
  std::fill(gain_.begin(), gain_.end(), 0.0);
  for (std::size_t p = 0; p < 3; ++p) {
    if (!used_[p]) continue;
    std::fill_n(sums_ + p * nb_ * stride, nb_ * stride, 0.0);
  }
  used_ = {};
}

void SphereGain::add_point(double s, double weight) {
  const double x = s * inv_h_;
  const auto j0 = std::size_t(x);
  if (j0 >= nb_) return;
  double N[4];
  splines_at(x - double(j0), N);
  for (std::size_t e = 0; e < 4; ++e) gain_[j0 + e] += weight * N[e];
}

std::vector<double>& SphereGain::finish() {
  for (std::size_t p = 0; p < 3; ++p) {
    if (!used_[p]) continue;
    const double* sums = sums_ + p * nb_ * stride;
    double passed = 0.0;  // Σ of the ends' weights in the intervals above m (their t⁰ sums): spline m wholly passed
    for (std::size_t m = nb_ - 1; m-- > 0;) passed += sums[(m + 1) * stride], gain_[m] += passed * terms_.whole[m][p];
    for (std::size_t q = 0; q < nb_; ++q) {
      const double* s = sums + q * stride;
      const double* c = terms_.interval.data() + (p * nb_ + q) * 4 * powers;
      for (std::size_t e = 0; e < 4; ++e, c += powers) {
        double sum = 0.0;
        for (std::size_t n = 0; n < p + 5; ++n) sum += c[n] * s[n];
        gain_[q + e] += sum;
      }
    }
  }
  return gain_;
}

}  // namespace granmix::theory
