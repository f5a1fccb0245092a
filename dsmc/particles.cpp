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
    // Selectors draw a particle of a species with 32-bit random integers (Rng::below_pair).
    if (counts[k] > 0xffffffffu)
      throw std::invalid_argument("particles: species " + std::to_string(k + 1) + " has more than 2^32 - 1 particles (the limit per species)");
    p.offset.push_back(p.offset.back() + counts[k]);
    p.mass.push_back(mix[k].mass);
  }
  const std::size_t N = p.offset.back();
  p.v.resize(N);
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
      Vec3& v = p.v[j];
      v.x = sd * rng.normal(), v.y = sd * rng.normal(), v.z = sd * rng.normal();
      c.x += v.x, c.y += v.y, c.z += v.z;
    }
    const double n = static_cast<double>(counts[k]);
    if (counts[k] > 1) {
      for (std::size_t j = p.begin(k); j < p.end(k); ++j) p.v[j].x -= c.x / n, p.v[j].y -= c.y / n, p.v[j].z -= c.z / n;
      M_many += n * mix[k].mass;
    } else {
      const std::size_t j = p.begin(k);
      const double f = rescale ? std::sqrt(T[k] / species_temperature(p, k)) : 1.0;
      Vec3& v = p.v[j];
      v.x *= f, v.y *= f, v.z *= f;
      P.x += mix[k].mass * v.x, P.y += mix[k].mass * v.y, P.z += mix[k].mass * v.z;
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
      p.v[j] = {u.x + f * p.v[j].x, u.y + f * p.v[j].y, u.z + f * p.v[j].z};
  }
  p.track_displacement = track_displacement;
  if (track_displacement) p.flight.assign(N, Vec3f{0, 0, 0});
  return p;
}

double species_temperature(const Particles& p, std::size_t k) {
  return 2.0 * species_energy(p, k) / (3.0 * static_cast<double>(p.count(k)));  // T_k = m_k ⟨v²⟩/3
}

void reanchor(Particles& p, double t) {
  if (!p.track_displacement) return;
  const double since_epoch = t - p.epoch;
  for (std::size_t j = 0; j < p.size(); ++j) add_scaled(p.flight[j], since_epoch, p.v[j]);
  p.epoch = t;
}

double speed_max(const Particles& p, std::size_t k) {
  double s = 0.0;
  for (std::size_t j = p.begin(k); j < p.end(k); ++j) s = std::max(s, norm2(p.v[j]));
  return std::sqrt(s);
}

}  // namespace granmix::dsmc

namespace granmix::dsmc {

double species_energy(const Particles& p, std::size_t k) {
  double s = 0.0;
  for (std::size_t j = p.begin(k); j < p.end(k); ++j) s += norm2(p.v[j]);
  return 0.5 * p.mass[k] * s;
}

double kinetic_energy(const Particles& p) {
  double e = 0.0;
  for (std::size_t k = 0; k < p.species(); ++k) e += species_energy(p, k);
  return e;
}

}  // namespace granmix::dsmc
