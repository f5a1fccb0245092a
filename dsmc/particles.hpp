#pragma once
// Particles grouped by species: species k owns indices [begin(k), end(k)). Each particle's velocity
// is one packed record of doubles (24 bytes), so a proposed pair costs two cache lines, not six (the
// velocity loads were the largest cost of the loop in perf); the collision dynamics stay in double.
//
// Displacements exist only when an MSD is asked for (v1 Eq. 15), as a flight intercept in single
// precision anchored at a global epoch t_e (a double kept with the particles):
//   R(t) = R0_e + v (t − t_e)                  for t after the particle's last collision.
// * A collision at t changes v by Δv; R is continuous through it, R0_e' + (v + Δv)(t − t_e) =
//   R0_e + v (t − t_e), so R0_e' = R0_e − Δv (t − t_e) (dsmc/collision_rule.hpp).
// * A re-anchor to t_new (reanchor(), every N collisions: at the event loop's refresh points, where an
//   O(N) pass happens anyway, and at the time-step scheme's step boundaries):
//   R(t) = R0_e + v (t_new − t_e) + v (t − t_new), so
//   R0_e(new) = R0_e(old) + v (t_new − t_e) = R(t_new), and t_e = t_new.
// Right after a re-anchor R0_e is the displacement itself; until the next one it moves by
// |Δv| (t − t_e), a few free paths (t − t_e spans ~2 collisions per particle). So |R0_e| stays of the
// order of the true displacement |R| plus a few free paths, not of v t, in elastic and cooling gases
// alike. Every update (collision or re-anchor) is computed in double and rounded once to float,
// an error of at most u = 2⁻²⁴ ≈ 6e-8 of |R0_e|; the n updates of a particle add up to at most
// n u max|R0_e|, and, the roundings being unbiased and uncorrelated, to u √(n/3) max|R0_e| rms
// (1e5 updates: 1.1e-5 of the displacement scale per particle; the MSD, an average over particles of
// R² whose errors are of either sign, moves by far less: 2e-10 against the double intercept, measured). The read-out R0_e + v (t − t_e) is in double. A float intercept anchored at
// t = 0 instead (R0 = R − v t) would carry u |v| t per update: in an elastic
// gas at 1e5 collision times |v| t is ~300 times the displacement (tests/dsmc/test_displacement_float.cpp).
// Memory: 24 bytes per particle, 36 with displacements (a double intercept would take 48, R and t_last
// stored 56).
#include <cstddef>
#include <vector>

#include "model/mixture.hpp"
#include "rng.hpp"

namespace granmix::dsmc {

// A single-precision displacement record (the flight intercept R0_e).
struct Vec3f {
  float x, y, z;
};

struct Particles {
  std::vector<std::size_t> offset;  // offset[k] .. offset[k+1]: species k
  std::vector<double> mass;         // per species
  std::vector<Vec3> v;
  bool track_displacement = false;
  double epoch = 0.0;         // t_e, the time the flight intercepts are anchored at
  std::vector<Vec3f> flight;  // R0_e = R(t) − v (t − t_e) per particle (when track_displacement)

  std::size_t species() const { return mass.size(); }
  std::size_t size() const { return v.size(); }
  // Memory of one particle's records (the per-species tables are O(M), not O(N)).
  static std::size_t bytes_per_particle(bool with_displacement) {
    return sizeof(Vec3) + (with_displacement ? sizeof(Vec3f) : 0);
  }
  std::size_t count(std::size_t k) const { return offset[k + 1] - offset[k]; }
  std::size_t begin(std::size_t k) const { return offset[k]; }
  std::size_t end(std::size_t k) const { return offset[k + 1]; }
};

// Maxwellian velocities at T_k per species; each species' centre-of-mass velocity removed, then
// (if rescale) scaled so the species has exactly T_k (docs/physics.md §7: remove the CM velocity first).
Particles maxwellian_particles(const model::Mixture& mix, const std::vector<std::size_t>& counts,
                               const std::vector<double>& T, bool track_displacement, bool rescale, Rng& rng);

// Displacement of particle a at time t without touching the state (v1 Eq. 15), in double.
inline Vec3 displacement(const Particles& p, std::size_t a, double t) {
  const Vec3f& r0 = p.flight[a];
  const Vec3& v = p.v[a];
  const double flight_time = t - p.epoch;
  return {r0.x + v.x * flight_time, r0.y + v.y * flight_time, r0.z + v.z * flight_time};
}

// r += s w, computed in double and rounded once to float: the one rounding of an intercept update.
inline void add_scaled(Vec3f& r, double s, const Vec3& w) {
  r = {static_cast<float>(r.x + s * w.x), static_cast<float>(r.y + s * w.y), static_cast<float>(r.z + s * w.z)};
}

// Re-anchor every flight intercept at t (R0_e += v (t − t_e), then t_e = t), O(N); nothing without
// displacements.
void reanchor(Particles& p, double t);

// T_k = m_k ⟨v²⟩ / 3 of one species; kinetic energies Σ m v²/2 of one species and of all.
double species_temperature(const Particles& p, std::size_t k);
double species_energy(const Particles& p, std::size_t k);
double kinetic_energy(const Particles& p);
double speed_max(const Particles& p, std::size_t k);

}  // namespace granmix::dsmc
