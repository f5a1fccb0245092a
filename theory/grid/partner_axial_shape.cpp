#include "theory/grid/partner_axial_shape.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "theory/grid/speed_grid.hpp"

namespace granmix::theory {

namespace {

// Per knot interval: the spline is a cubic there, P(u)/u smooth away from 0 (8 points: ≤ 1e-8 relative from the
// second interval on, where 1/u's nearest singularity is 1.5 half-widths away) and u^k B_n(u²/2θ) smooth everywhere.
constexpr std::size_t axial_interval_points = 8;

// The rule on [a, b] from one on [0, 1] (built once).
GaussRule axial_rule_on(double a, double b) {
  static const GaussRule unit = legendre(axial_interval_points, 0.0, 1.0);
  GaussRule r = unit;
  for (std::size_t q = 0; q < r.x.size(); ++q) r.x[q] = a + (b - a) * r.x[q], r.weight[q] *= b - a;
  return r;
}

double axial_tail_piece(const Eigen::VectorXd& P, double h, double a, double b) {
  const GaussRule r = axial_rule_on(a, b);
  double s = 0.0;
  for (std::size_t q = 0; q < r.x.size(); ++q) s += r.weight[q] * speed_density_at(h, P, r.x[q]) / r.x[q];
  return s;
}

}  // namespace

AxialShape::AxialShape(const SpeedDensity& d, double theta) : theta_(theta) {
  if (!(theta > 0.0) || d.P.size() < 4 || !(d.h > 0.0)) throw std::invalid_argument("AxialShape: needs a speed density and θ > 0");
  const std::size_t intervals = std::size_t(d.P.size() - 3);
  // The density's own ⟨v*²⟩ fixes v₀: ⟨u²⟩ = 3θ.
  double norm = 0.0, second = 0.0;
  for (std::size_t j = 0; j < intervals; ++j) {
    const GaussRule r = axial_rule_on(double(j) * d.h, double(j + 1) * d.h);
    for (std::size_t q = 0; q < r.x.size(); ++q) {
      const double p = r.weight[q] * speed_density_at(d.h, d.P, r.x[q]);
      norm += p, second += p * r.x[q] * r.x[q];
    }
  }
  if (!(norm > 0.0 && second > 0.0)) throw std::invalid_argument("AxialShape: the density has no positive mass or second moment");
  const double v0 = std::sqrt(3.0 * theta * norm / second);
  h_ = v0 * d.h;
  P_ = d.P / (v0 * norm);  // P(u) = P*(u/v₀)/v₀, normalised to ∫P du = 1
  tail_.assign(intervals + 1, 0.0);
  for (std::size_t j = intervals; j-- > 1;) tail_[j] = tail_[j + 1] + axial_tail_piece(P_, h_, double(j) * h_, double(j + 1) * h_);
  // On [0, h] the cubic through four points (t = u/h at Chebyshev-like nodes), as Σ c_m u^m.
  Eigen::Matrix4d V;
  Eigen::Vector4d p;
  const double t[4] = {0.1, 0.4, 0.6, 0.9};
  for (int i = 0; i < 4; ++i) {
    for (int m = 0; m < 4; ++m) V(i, m) = std::pow(t[i], m);
    p[i] = speed_density_at(h_, P_, t[i] * h_);
  }
  const Eigen::Vector4d c = V.fullPivLu().solve(p);
  for (int m = 0; m < 4; ++m) first_[std::size_t(m)] = c[m] / std::pow(h_, m);
}

double AxialShape::at(double y) const {
  if (!(y >= 0.0)) return 0.0;
  const double vz = std::sqrt(2.0 * theta_ * y), x = vz / h_;
  const std::size_t intervals = tail_.size() - 1;
  if (x >= double(intervals)) return 0.0;
  double integral = 0.0;
  if (x >= 1.0) {
    const auto j = std::size_t(x);
    integral = tail_[j + 1] + axial_tail_piece(P_, h_, vz, double(j + 1) * h_);
  } else {
    // ∫_s^h Σ c_m u^(m−1) du exactly; a Galerkin P need not vanish at u = 0 (its c₀: a log, integrable in v_z).
    const double s = std::max(vz, 1e-12 * h_);
    integral = tail_[1] + first_[0] * std::log(h_ / s);
    for (std::size_t m = 1; m < 4; ++m) integral += first_[m] * (std::pow(h_, double(m)) - std::pow(s, double(m))) / double(m);
  }
  // g/g_M = ½ integral · √(2πθ) e^y
  return 0.5 * integral * std::sqrt(2.0 * std::numbers::pi * theta_) * std::exp(y);
}

Eigen::VectorXd AxialShape::source(const RadialBasis& basis) const {
  const std::size_t intervals = tail_.size() - 1, n = axial_interval_points * intervals;
  std::vector<double> x(n), w(n);
  for (std::size_t j = 0; j < intervals; ++j) {
    const GaussRule r = axial_rule_on(double(j) * h_, double(j + 1) * h_);
    for (std::size_t q = 0; q < axial_interval_points; ++q) {
      const std::size_t i = j * axial_interval_points + q;
      x[i] = r.x[q] * r.x[q] / (2.0 * theta_);
      w[i] = r.weight[q] * speed_density_at(h_, P_, r.x[q]) * x[i];  // P du · c²
    }
  }
  std::vector<double> B(basis.size * n);
  basis.eval(x.data(), n, B.data(), nullptr);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(Eigen::Index(basis.size));
  for (std::size_t m = 0; m < basis.size; ++m)
    for (std::size_t i = 0; i < n; ++i) r[Eigen::Index(m)] += B[m * n + i] * w[i];
  return r;
}

}  // namespace granmix::theory
