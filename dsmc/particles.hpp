#pragma once
// Particles grouped by species: species k owns indices [begin(k), end(k)). Each particle's velocity
// is one packed record (24 bytes), so a proposed pair costs two cache lines, not six (the velocity
// loads were the largest cost of the loop in perf). Displacements exist only when an MSD is asked
// for, as the intercept R0 = R(t) − v t of the current free flight (v1 Eq. 15 with the
// last-collision time folded in: R(t) = R0 + v t, and a collision at t that changes v by Δv changes
// R0 by −Δv t), one 24-byte record. Memory: 24 bytes per particle, 48 with displacements (was 56
// with R and t_last stored). R0 loses no precision where it matters: in a cooling gas v t stays of
// the order of the displacement (v ∝ 1/t), in an elastic one the rounding of v t is 1e-16 t.
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
  std::vector<Vec3> flight;  // R0 = R(t) − v t per particle (when track_displacement)

  std::size_t species() const { return mass.size(); }
  std::size_t size() const { return v.size(); }
  // Memory of one particle's records (the per-species tables are O(M), not O(N)).
  static std::size_t bytes_per_particle(bool with_displacement) { return sizeof(Vec3) * (with_displacement ? 2 : 1); }
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
  const Vec3 &r0 = p.flight[a], &v = p.v[a];
  return {r0.x + v.x * t, r0.y + v.y * t, r0.z + v.z * t};
}

// T_k = m_k ⟨v²⟩ / 3 of one species; kinetic energies Σ m v²/2 of one species and of all.
double species_temperature(const Particles& p, std::size_t k);
double species_energy(const Particles& p, std::size_t k);
double kinetic_energy(const Particles& p);
double speed_max(const Particles& p, std::size_t k);

}  // namespace granmix::dsmc
