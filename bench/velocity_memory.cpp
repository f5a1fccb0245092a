#include "velocity_memory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granmix::bench {

double integral_log_grid(const std::vector<double>& t, const std::vector<double>& f, std::size_t a, std::size_t b) {
  if (b <= a || (b - a) % 2 != 0 || b >= t.size()) throw std::invalid_argument("integral_log_grid: need an even number of intervals");
  const double h = std::log(t[a + 1] / t[a]);
  double s = 0.0;
  for (std::size_t j = a; j < b; j += 2) s += f[j] * t[j] + 4.0 * f[j + 1] * t[j + 1] + f[j + 2] * t[j + 2];  // dt = t ds
  return s * h / 3.0;
}

double effective_rate(const std::vector<double>& t, const std::vector<double>& v2, const std::vector<double>& Q, std::size_t a,
                      std::size_t b) {
  return (integral_log_grid(t, v2, a, b) - (Q[b] - Q[a])) / integral_log_grid(t, Q, a, b);
}

namespace {

// Value at time x in [t0, t1] between samples f0, f1: a power law when both are positive, else linear.
double interpolate(double t0, double t1, double f0, double f1, double x) {
  if (f0 > 0.0 && f1 > 0.0) return f0 * std::pow(f1 / f0, std::log(x / t0) / std::log(t1 / t0));
  return f0 + (f1 - f0) * (x - t0) / (t1 - t0);
}

}  // namespace

std::vector<double> msd_from_memory(const std::vector<double>& t, const std::vector<double>& v2, const std::vector<double>& nu) {
  std::vector<double> M(t.size());
  double Q = v2[0] * t[0], m = v2[0] * t[0] * t[0];
  M[0] = m;
  for (std::size_t j = 0; j + 1 < t.size(); ++j) {
    const double h = t[j + 1] - t[j];
    const int n = std::max(8, static_cast<int>(std::ceil(std::max(std::abs(nu[j]), std::abs(nu[j + 1])) * h / 0.05)));
    const double dt = h / n;
    auto g = [&](double x) { return interpolate(t[j], t[j + 1], v2[j], v2[j + 1], x); };
    auto r = [&](double x) { return interpolate(t[j], t[j + 1], nu[j], nu[j + 1], x); };
    for (int i = 0; i < n; ++i) {
      const double x = t[j] + i * dt, xm = x + 0.5 * dt, xe = x + dt;
      // y = (Q, M): dQ = g − rQ, dM = 2Q.
      const double q1 = g(x) - r(x) * Q, m1 = 2.0 * Q;
      const double Q2 = Q + 0.5 * dt * q1, q2 = g(xm) - r(xm) * Q2, m2 = 2.0 * Q2;
      const double Q3 = Q + 0.5 * dt * q2, q3 = g(xm) - r(xm) * Q3, m3 = 2.0 * Q3;
      const double Q4 = Q + dt * q3, q4 = g(xe) - r(xe) * Q4, m4 = 2.0 * Q4;
      Q += dt * (q1 + 2.0 * q2 + 2.0 * q3 + q4) / 6.0;
      m += dt * (m1 + 2.0 * m2 + 2.0 * m3 + m4) / 6.0;
    }
    M[j + 1] = m;
  }
  return M;
}


}  // namespace granmix::bench
