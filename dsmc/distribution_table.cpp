#include "distribution_table.hpp"

#include <cmath>

#include "theory/scene_theory.hpp"
#include "theory/shell_average.hpp"
#include "theory/sonine_hcs.hpp"

namespace granmix::dsmc {

namespace {

// Mean over the sample times of a settled per-species quantity, with an error bound: the standard
// deviation of a mean of correlated estimates is at most the mean of their standard deviations.
std::pair<double, double> time_mean(const Estimate& e, std::size_t times, std::size_t M, std::size_t k) {
  double m = 0.0, err = 0.0;
  for (std::size_t j = 0; j < times; ++j) m += e.mean[j * M + k], err += e.err[j * M + k];
  return {m / double(times), err / double(times)};
}

}  // namespace

model::Table settled_distribution_table(const model::Scene& s, const DsmcSetup& d, const DsmcResult& r) {
  const std::size_t M = s.mixture.size(), B = d.distribution_bins, J = d.times.size();
  // MG's T = Σ x_k T_k and v0² = 2T(m_1+m_2)/(m_1 m_2): λ_k = m_k v0²/(2T_k) (MG Eq. 17).
  std::vector<double> Tk(M);
  double T = 0.0, N = 0.0;
  for (std::size_t k = 0; k < M; ++k) Tk[k] = time_mean(r.T, J, M, k).first, T += double(d.counts[k]) * Tk[k], N += double(d.counts[k]);
  T /= N;
  const double m1 = s.mixture[0].mass, m2 = s.mixture[1].mass, v0sq = 2.0 * T * (m1 + m2) / (m1 * m2);
  // G_k's weight exp(2β_k v*/ζ*) is part of MG's definition (Eq. 30), taken from the first-Sonine
  // β_k and ζ*: the same function multiplies theory and simulation, so it cannot favour either.
  const theory::SonineHcs h = theory::sonine_hcs(s.mixture, s.restitution, theory::scene_contact_values(s));
  std::vector<double> lambda(M);
  std::vector<std::pair<double, double>> cumulant(M);
  for (std::size_t k = 0; k < M; ++k) lambda[k] = s.mixture[k].mass * v0sq / (2.0 * Tk[k]), cumulant[k] = time_mean(r.cumulant, J, M, k);
  model::Table t;
  t.columns = {"v", "species", "phi", "phi_err", "delta", "delta_err", "G", "G_err"};
  const double width = d.distribution_vmax / double(B);
  for (std::size_t b = 0; b < B; ++b) {
    const double lo = b * width, hi = lo + width, v = 0.5 * (lo + hi);
    for (std::size_t k = 0; k < M; ++k) {
      // The bin's Maxwellian is its shell average, as the histogram's Φ is (theory/shell_average.hpp).
      const double maxwell = theory::shell_average([&](double u) { return theory::maxwellian_phi(lambda[k], u); }, lo, hi);
      const double phi = r.distribution.mean[k * B + b], phi_err = r.distribution.err[k * B + b];
      const auto [c, c_err] = cumulant[k];
      // Δ = (2/c)(Φ/Φ_M − 1); its error from Φ and from c (∂Δ/∂c = −Δ/c), as if independent.
      const double delta = 2.0 / c * (phi / maxwell - 1.0);
      const double delta_err = std::hypot(2.0 * phi_err / (c * maxwell), delta * c_err / c);
      const double tail = std::exp(h.tail_exponent(k) * v);
      t.rows.push_back({v, double(k + 1), phi, phi_err, delta, std::abs(delta_err), tail * phi, tail * phi_err});
    }
  }
  return t;
}

}  // namespace granmix::dsmc
