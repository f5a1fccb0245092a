#include "distribution_table.hpp"

#include <cmath>

#include "theory/scene_theory.hpp"
#include "theory/numerics/shell_average.hpp"
#include "theory/sonine/sonine_hcs.hpp"

namespace granmix::dsmc {

namespace {

// Mean over the sample times of a settled per-species quantity, from the means without replica
// `skip` (the jackknife's leave-one-out; skip >= R: all replicas).
double time_mean(const Estimate& e, std::size_t times, std::size_t M, std::size_t k, std::size_t skip) {
  double m = 0.0;
  for (std::size_t j = 0; j < times; ++j) m += e.mean_without(j * M + k, skip);
  return m / double(times);
}

}  // namespace

model::Table settled_distribution_table(const model::Scene& s, const DsmcSetup& d, const DsmcResult& r) {
  const std::size_t M = s.mixture.size(), B = d.distribution_bins, J = d.times.size(), R = r.replicas;
  const double m1 = s.mixture[0].mass, m2 = s.mixture[1].mass;
  // MG's T = Σ x_k T_k and v0² = 2T(m_1+m_2)/(m_1 m_2): λ_k = m_k v0²/(2T_k) (MG Eq. 17), from the
  // replica means without `skip`.
  auto lambda = [&](std::size_t k, std::size_t skip) {
    double T = 0.0, N = 0.0;
    for (std::size_t a = 0; a < M; ++a) T += double(d.counts[a]) * time_mean(r.T, J, M, a, skip), N += double(d.counts[a]);
    const double v0sq = 2.0 * (T / N) * (m1 + m2) / (m1 * m2);
    return s.mixture[k].mass * v0sq / (2.0 * time_mean(r.T, J, M, k, skip));
  };
  // G_k's weight exp(2β_k v*/ζ*) is part of MG's definition (Eq. 30), taken from the first-Sonine
  // β_k and ζ*: the same function multiplies theory and simulation, so it cannot favour either.
  const theory::SonineHcs h = theory::sonine_hcs(s.mixture, s.restitution, theory::scene_contact_values(s));
  model::Table t;
  t.columns = {"v", "species", "phi", "phi_err", "delta", "delta_err", "G", "G_err"};
  const double width = d.distribution_vmax / double(B);
  for (std::size_t b = 0; b < B; ++b) {
    const double lo = b * width, hi = lo + width, v = 0.5 * (lo + hi);
    for (std::size_t k = 0; k < M; ++k) {
      // Δ = (2/c)(Φ/Φ_M − 1) with the simulation's own c_k and λ_k; the bin's Maxwellian is its shell
      // average, as the histogram's Φ is (theory/numerics/shell_average.hpp). Jackknife error: Φ, c and λ come
      // from the same replicas.
      const auto delta = jackknife(R, [&](std::size_t skip) {
        const double l = lambda(k, skip);
        const double maxwell = theory::shell_average([&](double u) { return theory::maxwellian_phi(l, u); }, lo, hi);
        return 2.0 / time_mean(r.cumulant, J, M, k, skip) * (r.distribution.mean_without(k * B + b, skip) / maxwell - 1.0);
      });
      const double phi = r.distribution.mean[k * B + b], phi_err = r.distribution.err[k * B + b];
      const double tail = std::exp(h.tail_exponent(k) * v);
      t.rows.push_back({v, double(k + 1), phi, phi_err, delta.first, delta.second, tail * phi, tail * phi_err});
    }
  }
  return t;
}

}  // namespace granmix::dsmc
