#include "theory/numerics/scaled_time_motion.hpp"

#include <algorithm>
#include <complex>
#include <cmath>
#include <stdexcept>
#include <string>


namespace granmix::theory {

namespace {

using cplx = std::complex<double>;

// (1 − e^(−x))/x and (x − 1 + e^(−x))/x², with their series where they cancel.
cplx phi1(cplx x) { return std::abs(x) < 1e-5 ? 1.0 - x / 2.0 + x * x / 6.0 : (1.0 - std::exp(-x)) / x; }
cplx phi2(cplx x) { return std::abs(x) < 1e-3 ? 0.5 - x / 6.0 + x * x / 24.0 - x * x * x / 120.0 : (1.0 - phi1(x)) / x; }

// Real time over a scaled-time span σ at cooling rate ζ from T₁ (T₁ e^(−ζσ) after; dt = dσ/√T₁), and its inverse.
double real_span(double sigma, double zeta, double T1) {
  const double x = 0.5 * zeta * sigma;
  return (std::abs(x) < 1e-12 ? sigma : std::expm1(x) / (0.5 * zeta)) / std::sqrt(T1);
}
double scaled_span(double dt, double zeta, double T1) {
  const double x = 0.5 * zeta * std::sqrt(T1) * dt;
  return std::abs(x) < 1e-12 ? std::sqrt(T1) * dt : std::log1p(x) / (0.5 * zeta);
}

}  // namespace

ScaledTimeMotion::ScaledTimeMotion(std::vector<double> h, std::vector<double> zeta, std::vector<MotionMode> modes)
    : h_(std::move(h)), zeta_(std::move(zeta)), modes_(std::move(modes)) {
  const std::size_t n = h_.size();
  if (n == 0 || zeta_.size() != n || modes_.empty())
    throw std::invalid_argument("scaled-time motion: h and zeta need one value per step (at least one step), and one mode or more");
  for (const MotionMode& m : modes_)
    if (m.weight.size() != n || m.kappa.size() != n) throw std::invalid_argument("scaled-time motion: every mode needs one weight and rate per step");
  t_ = {0.0}, T1_ = {1.0}, s_ = {0.0};
  for (std::size_t j = 0; j < n; ++j) {
    if (!(h_[j] > 0.0) || !std::isfinite(zeta_[j]))
      throw std::invalid_argument("scaled-time motion: step " + std::to_string(j) + " has h <= 0 or a cooling rate that is not finite");
    t_.push_back(t_.back() + real_span(h_[j], zeta_[j], T1_.back()));
    T1_.push_back(T1_.back() * std::exp(-zeta_[j] * h_[j]));
    s_.push_back(s_.back() + h_[j]);
  }
  for (const MotionMode& m : modes_) {
    std::vector<ModeState> at = {{0.0, 0.0, 0.0}};
    for (std::size_t j = 0; j < n; ++j) {
      if (!std::isfinite(std::abs(m.weight[j])) || !std::isfinite(std::abs(m.kappa[j])))
        throw std::invalid_argument("scaled-time motion: a mode's weight or rate is not finite at step " + std::to_string(j));
      at.push_back(state_after(at.back(), m.weight[j], m.kappa[j], h_[j]));
    }
    nodes_.push_back(std::move(at));
    std::vector<cplx> R(n + 1, 0.0);
    for (std::size_t j = n; j-- > 0;) R[j] = h_[j] * phi1(m.kappa[j] * h_[j]) + std::exp(-m.kappa[j] * h_[j]) * R[j + 1];
    rest_.push_back(std::move(R));
  }
}

ScaledTimeMotion::ModeState ScaledTimeMotion::state_after(const ModeState& x, cplx a, cplx kappa, double sigma) {
  const cplx k = kappa * sigma, p1 = phi1(k);
  return {x.M + 2.0 * (x.Q * sigma * p1 + a * sigma * sigma * phi2(k)), x.Q * std::exp(-k) + a * sigma * p1, x.K + k};
}

ScaledTimeMotion::Place ScaledTimeMotion::locate(double t) const {
  if (!(t >= 0.0 && t <= t_.back()))
    throw std::out_of_range("scaled-time motion: time " + std::to_string(t) + " outside [0, " + std::to_string(t_.back()) + "]");
  const std::size_t n = std::min(std::size_t(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1, h_.size() - 1);
  return {n, std::min(h_[n], scaled_span(t - t_[n], zeta_[n], T1_[n]))};
}

ScaledTimeMotion::ModeState ScaledTimeMotion::state(std::size_t j, const Place& p) const {
  return state_after(nodes_[j][p.n], modes_[j].weight[p.n], modes_[j].kappa[p.n], p.sigma);
}

cplx ScaledTimeMotion::rest(std::size_t j, const Place& p) const {
  const double x = h_[p.n] - p.sigma;
  const cplx k = modes_[j].kappa[p.n] * x;
  return x * phi1(k) + std::exp(-k) * rest_[j][p.n + 1];
}

cplx ScaledTimeMotion::carried(std::size_t j, const Place& a, const Place& b) const {
  return rest(j, a) - std::exp(-(state(j, b).K - state(j, a).K)) * rest(j, b);
}

double ScaledTimeMotion::msd(double t) const {
  const Place p = locate(t);
  double out = 0.0;
  for (std::size_t j = 0; j < modes_.size(); ++j) out += state(j, p).M.real();
  return out;
}

double ScaledTimeMotion::increment(double t, double lag) const {
  const Place a = locate(t), b = locate(t + lag);
  double out = 0.0;
  for (std::size_t j = 0; j < modes_.size(); ++j) {
    const ModeState x = state(j, a), y = state(j, b);
    out += (y.M - x.M - 2.0 * x.Q * carried(j, a, b)).real();
  }
  return out;
}

double ScaledTimeMotion::tamsd(double measurement_time, double lag) const {
  if (!(lag > 0.0 && lag < measurement_time)) throw std::invalid_argument("TAMSD: the lag must lie in (0, measurement time)");
  // The increment is smooth between the times where t or t + lag crosses a step's end (there its v and κ jump): 3-point
  // Gauss–Legendre on each of those pieces (each a fraction of a step: the rule's error is far below 1e-10).
  const double span = measurement_time - lag;
  std::vector<double> cuts = {0.0, span};
  for (double tn : t_) {
    if (tn > 0.0 && tn < span) cuts.push_back(tn);
    if (tn - lag > 0.0 && tn - lag < span) cuts.push_back(tn - lag);
  }
  std::sort(cuts.begin(), cuts.end());
  static const double x[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1], mid = 0.5 * (a + b), half = 0.5 * (b - a);
    if (half <= 0.0) continue;
    for (int j = 0; j < 3; ++j) sum += half * w[j] * increment(mid + half * x[j], lag);
  }
  return sum / span;
}

}  // namespace granmix::theory
