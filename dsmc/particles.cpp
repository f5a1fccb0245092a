#include "particles.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace granmix::dsmc {

Particles maxwellian_particles(const model::Mixture& mix, const std::vector<std::size_t>& counts,
                               const std::vector<double>& T, bool track_displacement, bool rescale, Rng& rng) {
  const std::size_t M = mix.size();
  if (counts.size() != M || T.size() != M) throw std::invalid_argument("particles: one count and one T per species");
  Particles p;
  p.offset.assign(1, 0);
  for (std::size_t k = 0; k < M; ++k) {
    if (counts[k] == 0) throw std::invalid_argument("particles: species " + std::to_string(k + 1) + " has no particles");
    p.offset.push_back(p.offset.back() + counts[k]);
    p.mass.push_back(mix[k].mass);
  }
  const std::size_t N = p.offset.back();
  p.vx.resize(N), p.vy.resize(N), p.vz.resize(N);
  for (std::size_t k = 0; k < M; ++k) {
    const double sd = std::sqrt(T[k] / mix[k].mass);
    double cx = 0, cy = 0, cz = 0;
    for (std::size_t j = p.begin(k); j < p.end(k); ++j) {
      p.vx[j] = sd * rng.normal(), p.vy[j] = sd * rng.normal(), p.vz[j] = sd * rng.normal();
      cx += p.vx[j], cy += p.vy[j], cz += p.vz[j];
    }
    const double n = static_cast<double>(counts[k]);
    if (counts[k] > 1) {  // a single particle keeps its velocity: removing it would leave T = 0
      for (std::size_t j = p.begin(k); j < p.end(k); ++j) p.vx[j] -= cx / n, p.vy[j] -= cy / n, p.vz[j] -= cz / n;
    }
    if (rescale) {
      const double f = std::sqrt(T[k] / species_temperature(p, k));
      for (std::size_t j = p.begin(k); j < p.end(k); ++j) p.vx[j] *= f, p.vy[j] *= f, p.vz[j] *= f;
    }
  }
  p.track_displacement = track_displacement;
  if (track_displacement) p.rx.assign(N, 0.0), p.ry.assign(N, 0.0), p.rz.assign(N, 0.0), p.t_last.assign(N, 0.0);
  return p;
}

double species_temperature(const Particles& p, std::size_t k) {
  return 2.0 * species_energy(p, k) / (3.0 * static_cast<double>(p.count(k)));  // T_k = m_k ⟨v²⟩/3
}

double speed_max(const Particles& p, std::size_t k) {
  double s = 0.0;
  for (std::size_t j = p.begin(k); j < p.end(k); ++j) s = std::max(s, p.vx[j] * p.vx[j] + p.vy[j] * p.vy[j] + p.vz[j] * p.vz[j]);
  return std::sqrt(s);
}

}  // namespace granmix::dsmc

namespace granmix::dsmc {

double species_energy(const Particles& p, std::size_t k) {
  double s = 0.0;
  for (std::size_t j = p.begin(k); j < p.end(k); ++j) s += p.vx[j] * p.vx[j] + p.vy[j] * p.vy[j] + p.vz[j] * p.vz[j];
  return 0.5 * p.mass[k] * s;
}

double kinetic_energy(const Particles& p) {
  double e = 0.0;
  for (std::size_t k = 0; k < p.species(); ++k) e += species_energy(p, k);
  return e;
}

}  // namespace granmix::dsmc
