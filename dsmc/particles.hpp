#pragma once
// Particles grouped by species: species k owns indices [begin(k), end(k)). Each particle's velocity
// is one packed record (24 bytes), so a proposed pair costs two cache lines, not six (the velocity
// loads were the largest cost of the loop in perf). Displacements R with the last-collision time
// (one 32-byte record) exist only when an MSD is asked for (v1 Eq. 15: R is advanced lazily at a
// particle's collisions). Memory: 24 bytes per particle, 56 with displacements.
#include <cstddef>
#include <vector>

#include "model/mixture.hpp"
#include "rng.hpp"

namespace granmix::dsmc {

struct Particles {
  std::vector<std::size_t> offset;  // offset[k] .. offset[k+1]: species k
  std::vector<double> mass;         // per species
  std::vector<Vec3> v;
  bool track_displacement = false;
  struct Flight {
    Vec3 r;         // displacement up to t_last
    double t_last;  // time of the last collision
  };
  std::vector<Flight> flight;

  std::size_t species() const { return mass.size(); }
  std::size_t size() const { return v.size(); }
  // Memory of one particle's records (the per-species tables are O(M), not O(N)).
  static std::size_t bytes_per_particle(bool with_displacement) { return sizeof(Vec3) + (with_displacement ? sizeof(Flight) : 0); }
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
  const Particles::Flight& f = p.flight[a];
  const Vec3& v = p.v[a];
  const double dt = t - f.t_last;
  return {f.r.x + v.x * dt, f.r.y + v.y * dt, f.r.z + v.z * dt};
}

// T_k = m_k ⟨v²⟩ / 3 of one species; kinetic energies Σ m v²/2 of one species and of all.
double species_temperature(const Particles& p, std::size_t k);
double species_energy(const Particles& p, std::size_t k);
double kinetic_energy(const Particles& p);
double speed_max(const Particles& p, std::size_t k);

}  // namespace granmix::dsmc
