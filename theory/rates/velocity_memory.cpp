#include "theory/rates/velocity_memory.hpp"

#include <cmath>

namespace granmix::theory {

namespace {

// e^z − 1 without cancellation for small |z| (real part by expm1, the imaginary turn by 2 sin²(y/2)).
std::complex<double> expm1(std::complex<double> z) {
  if (z.imag() == 0.0) return std::expm1(z.real());
  const double e = std::expm1(z.real()), s = std::sin(0.5 * z.imag());
  return {e * std::cos(z.imag()) - 2.0 * s * s, (e + 1.0) * std::sin(z.imag())};
}

}  // namespace

VelocityMemory VelocityMemory::exponential(double D0, double tau_v0) { return {{3.0 * D0 / tau_v0}, {1.0 / tau_v0}}; }

double VelocityMemory::diffusion() const {
  std::complex<double> D = 0.0;
  for (std::size_t j = 0; j < weight.size(); ++j) D += weight[j] / (3.0 * rate[j]);
  return D.real();
}

double msd_increment(const VelocityMemory& m, double tau0, double t, double lag) {
  std::complex<double> sum = 0.0;
  for (std::size_t j = 0; j < m.weight.size(); ++j) {
    const std::complex<double> D = m.weight[j] / (3.0 * m.rate[j]), tau = 1.0 / m.rate[j];
    if (!std::isfinite(tau0)) {
      sum += 6.0 * D * (lag + tau * expm1(-lag * m.rate[j]));  // elastic: stationary (Ornstein–Uhlenbeck per mode)
    } else {
      const double L = std::log1p(lag / (tau0 + t));  // ln(s_Δ/s), s = 1 + t/τ₀
      sum += 6.0 * D * (tau0 * L + tau * expm1(-tau0 * L * m.rate[j]));
    }
  }
  return sum.real();
}

}  // namespace granmix::theory
