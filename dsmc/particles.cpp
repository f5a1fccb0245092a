#include "particles.hpp"

#include "rng.hpp"

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
  // Species of two or more particles get zero mean velocity; a single particle keeps its own (zero
  // would leave T = 0). The single particles' momentum is then taken up by a common drift u of the
  // other particles, so that the total momentum is zero: otherwise the centre-of-mass energy P²/2M
  // can never be dissipated and the measured temperatures stop falling (a floor near 1e-8 in a
  // power-law mixture with 1e5 particles, v1 Fig. 8).
  Vec3 P{0, 0, 0};
  double M_many = 0.0;
  for (std::size_t k = 0; k < M; ++k) {
    const double sd = std::sqrt(T[k] / mix[k].mass);
    Vec3 c{0, 0, 0};
    for (std::size_t j = p.begin(k); j < p.end(k); ++j) {
      p.vx[j] = sd * rng.normal(), p.vy[j] = sd * rng.normal(), p.vz[j] = sd * rng.normal();
      c.x += p.vx[j], c.y += p.vy[j], c.z += p.vz[j];
    }
    const double n = static_cast<double>(counts[k]);
    if (counts[k] > 1) {
      for (std::size_t j = p.begin(k); j < p.end(k); ++j) p.vx[j] -= c.x / n, p.vy[j] -= c.y / n, p.vz[j] -= c.z / n;
      M_many += n * mix[k].mass;
    } else {
      const std::size_t j = p.begin(k);
      const double f = rescale ? std::sqrt(T[k] / species_temperature(p, k)) : 1.0;
      p.vx[j] *= f, p.vy[j] *= f, p.vz[j] *= f;
      P.x += mix[k].mass * p.vx[j], P.y += mix[k].mass * p.vy[j], P.z += mix[k].mass * p.vz[j];
    }
  }
  const Vec3 u = M_many > 0.0 ? Vec3{-P.x / M_many, -P.y / M_many, -P.z / M_many} : Vec3{0, 0, 0};
  const double u2 = u.x * u.x + u.y * u.y + u.z * u.z;
  for (std::size_t k = 0; k < M; ++k) {
    if (counts[k] < 2) continue;
    // v = u + f w with Σw = 0: m⟨v²⟩/3 = T_k exactly when f² = (3T_k/m − u²)/⟨w²⟩ (rescale), else f = 1.
    const double w2 = 3.0 * species_temperature(p, k) / p.mass[k], target = 3.0 * T[k] / p.mass[k] - u2;
    const double f = rescale && w2 > 0.0 && target > 0.0 ? std::sqrt(target / w2) : 1.0;
    for (std::size_t j = p.begin(k); j < p.end(k); ++j)
      p.vx[j] = u.x + f * p.vx[j], p.vy[j] = u.y + f * p.vy[j], p.vz[j] = u.z + f * p.vz[j];
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
