#pragma once
// Particles as a structure of arrays grouped by species: species k owns indices
// [begin(k), end(k)). Displacements R and last-collision times exist only when an MSD is asked for
// (v1 Eq. 15: R is advanced lazily at a particle's collisions).
#include <cstddef>
#include <vector>

#include "model/mixture.hpp"
#include "rng.hpp"

namespace granmix::dsmc {

struct Particles {
  std::vector<std::size_t> offset;  // offset[k] .. offset[k+1]: species k
  std::vector<double> mass;         // per species
  std::vector<double> vx, vy, vz;
  bool track_displacement = false;
  std::vector<double> rx, ry, rz, t_last;

  std::size_t species() const { return mass.size(); }
  std::size_t size() const { return vx.size(); }
  std::size_t count(std::size_t k) const { return offset[k + 1] - offset[k]; }
  std::size_t begin(std::size_t k) const { return offset[k]; }
  std::size_t end(std::size_t k) const { return offset[k + 1]; }
};

// Maxwellian velocities at T_k per species; each species' centre-of-mass velocity removed, then
// (if rescale) scaled so the species has exactly T_k (physics.md §7: remove the CM velocity first).
Particles maxwellian_particles(const model::Mixture& mix, const std::vector<std::size_t>& counts,
                               const std::vector<double>& T, bool track_displacement, bool rescale, Rng& rng);

// Displacement of particle a at time t without touching the state (v1 Eq. 15).
inline Vec3 displacement(const Particles& p, std::size_t a, double t) {
  const double dt = t - p.t_last[a];
  return {p.rx[a] + p.vx[a] * dt, p.ry[a] + p.vy[a] * dt, p.rz[a] + p.vz[a] * dt};
}

// T_k = m_k ⟨v²⟩ / 3 of one species; kinetic energies Σ m v²/2 of one species and of all.
double species_temperature(const Particles& p, std::size_t k);
double species_energy(const Particles& p, std::size_t k);
double kinetic_energy(const Particles& p);
double speed_max(const Particles& p, std::size_t k);

}  // namespace granmix::dsmc
