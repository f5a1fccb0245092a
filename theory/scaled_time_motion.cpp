#include "scaled_time_motion.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "model/gsl_setup.hpp"

namespace granmix::theory {

namespace {

// (1 − e^(−x))/x and (x − 1 + e^(−x))/x², with their series where they cancel.
double phi1(double x) { return std::abs(x) < 1e-5 ? 1.0 - x / 2.0 + x * x / 6.0 : -std::expm1(-x) / x; }
double phi2(double x) { return std::abs(x) < 1e-3 ? 0.5 - x / 6.0 + x * x / 24.0 - x * x * x / 120.0 : (1.0 - phi1(x)) / x; }

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

ScaledTimeMotion::ScaledTimeMotion(std::vector<double> h, std::vector<double> zeta, std::vector<double> v, std::vector<double> kappa)
    : h_(std::move(h)), zeta_(std::move(zeta)), v_(std::move(v)), kappa_(std::move(kappa)) {
  const std::size_t n = h_.size();
  if (n == 0 || zeta_.size() != n || v_.size() != n || kappa_.size() != n)
    throw std::invalid_argument("scaled-time motion: h, zeta, v and kappa need one value per step (at least one step)");
  t_ = {0.0}, T1_ = {1.0}, s_ = {0.0};
  for (std::size_t j = 0; j < n; ++j) {
    if (!(h_[j] > 0.0) || !std::isfinite(zeta_[j]) || !(v_[j] >= 0.0) || !std::isfinite(kappa_[j]))
      throw std::invalid_argument("scaled-time motion: step " + std::to_string(j) + " has h <= 0 or a value that is not finite");
    t_.push_back(t_.back() + real_span(h_[j], zeta_[j], T1_.back()));
    T1_.push_back(T1_.back() * std::exp(-zeta_[j] * h_[j]));
    s_.push_back(s_.back() + h_[j]);
  }
}

ScaledTimeMotion::Place ScaledTimeMotion::locate(double t) const {
  if (!(t >= 0.0 && t <= t_.back()))
    throw std::out_of_range("scaled-time motion: time " + std::to_string(t) + " outside [0, " + std::to_string(t_.back()) + "]");
  const std::size_t n = std::min(std::size_t(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1, h_.size() - 1);
  return {n, std::min(h_[n], scaled_span(t - t_[n], zeta_[n], T1_[n]))};
}

double ScaledTimeMotion::increment(double t, double lag) const {
  const Place a = locate(t), b = locate(t + lag);
  double M = 0.0, Q = 0.0;
  for (std::size_t n = a.n; n <= b.n; ++n) {
    const double from = n == a.n ? a.sigma : 0.0, to = n == b.n ? b.sigma : h_[n], x = to - from;
    if (x <= 0.0) continue;
    const double k = kappa_[n] * x;
    M += 2.0 * (Q * x * phi1(k) + v_[n] * x * x * phi2(k));
    Q = Q * std::exp(-k) + v_[n] * x * phi1(k);
  }
  return M;
}

double ScaledTimeMotion::tamsd(double measurement_time, double lag) const {
  if (!(lag > 0.0 && lag < measurement_time)) throw std::invalid_argument("TAMSD: the lag must lie in (0, measurement time)");
  model::use_gsl_return_codes();
  struct Params {
    const ScaledTimeMotion& m;
    double lag;
  } p{*this, lag};
  gsl_function f{[](double t, void* q) {
                   const auto* a = static_cast<const Params*>(q);
                   return a->m.increment(t, a->lag);
                 },
                 &p};
  double result = 0.0, abserr = 0.0;
  const double span = measurement_time - lag;
  const int status = gsl_integration_qag(&f, 0.0, span, 0.0, 1e-10, model::quadrature_intervals, GSL_INTEG_GAUSS21,
                                         model::quadrature_workspace(model::QuadratureLevel::outer), &result, &abserr);
  if (status != GSL_SUCCESS) throw NumericalError(std::string("TAMSD quadrature (scaled-time motion): ") + gsl_strerror(status));
  return result / span;
}

}  // namespace granmix::theory
