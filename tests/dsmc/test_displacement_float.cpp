// The single-precision flight intercepts anchored at a global epoch (dsmc/particles.hpp) against a
// double-precision reference integrated by hand: a few particles collide through the real collision
// rule at Poisson times, the reference advances every position by v dt in double, and the intercepts
// are re-anchored every N collisions as the event loop does.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "dsmc/collision_rule.hpp"
#include "dsmc/particles.hpp"
#include "dsmc/rng.hpp"

using namespace granmix;
using namespace granmix::dsmc;

namespace {

constexpr double u = 0x1p-24;  // float rounding to nearest: |error| <= u |x|

struct Outcome {
  double max_z = 0.0;             // largest |error| / bound over particles and components (epoch anchor)
  double naive_over_bound = 0.0;  // largest |error of a float intercept anchored at t = 0| / the same bound
  double intercept_over_scale = 0.0;  // largest max|R0_e| / max(|R| + |v| (t − t_e)) over particles
  double max_updates = 0.0;
  double updates = 0.0, displacement = 0.0, flight = 0.0;  // per particle: updates; rms |R|; rms |v| t
  double cooled = 1.0;                                      // E / E0 at the end
};

// N particles of masses 1 and 4 (half each), restitution eps, `per_particle` collisions per particle.
// Pairs are drawn uniformly, e from the |g·e|-weighted hemisphere; the waiting time has mean 2/N
// times √(E0/E) (a collision rate ∝ √T, Haff), so each particle has about one collision per unit
// time at the start.
Outcome run(double eps, double per_particle, std::uint64_t seed) {
  const std::size_t N = 8;
  Rng rng(seed, 0);
  Particles anchored;
  anchored.offset = {0, N / 2, N};
  anchored.mass = {1.0, 4.0};
  anchored.track_displacement = true;
  for (std::size_t j = 0; j < N; ++j) {
    const double sd = 1.0 / std::sqrt(anchored.mass[j < N / 2 ? 0 : 1]);
    anchored.v.push_back({sd * rng.normal(), sd * rng.normal(), sd * rng.normal()});
  }
  // Zero total momentum: a centre-of-mass drift would make every displacement ballistic.
  Vec3 P{0, 0, 0};
  for (std::size_t j = 0; j < N; ++j) {
    const double m = anchored.mass[j < N / 2 ? 0 : 1];
    P = {P.x + m * anchored.v[j].x, P.y + m * anchored.v[j].y, P.z + m * anchored.v[j].z};
  }
  const double M = double(N / 2) * (anchored.mass[0] + anchored.mass[1]);
  for (Vec3& v : anchored.v) v = {v.x - P.x / M, v.y - P.y / M, v.z - P.z / M};
  anchored.flight.assign(N, Vec3f{0, 0, 0});
  Particles naive = anchored;  // the same collisions, never re-anchored: R0 = R − v t in float
  std::vector<Vec3> R(N, Vec3{0, 0, 0});  // the double reference
  std::vector<double> updates(N, 0.0), sum_x2(N, 0.0), max_r0(N, 0.0), max_scale(N, 0.0);
  Outcome o;
  // After an update of particle j at t (t − t_e = since_epoch): the stored float components (their
  // squares bound the rounding's variance), |R0_e| and |R| + |v| (t − t_e), the size it is claimed to
  // stay within (particles.hpp).
  auto updated = [&](std::size_t j, double since_epoch) {
    const Vec3f& f = anchored.flight[j];
    const Vec3 &r = R[j], &v = anchored.v[j];
    updates[j] += 1.0;
    for (double x : {double(f.x), double(f.y), double(f.z)}) sum_x2[j] += x * x;
    max_r0[j] = std::max(max_r0[j], std::sqrt(double(f.x) * f.x + double(f.y) * f.y + double(f.z) * f.z));
    max_scale[j] = std::max(max_scale[j], std::sqrt(norm2(r)) + std::sqrt(norm2(v)) * since_epoch);
  };
  const double E0 = kinetic_energy(anchored);
  const auto collisions = static_cast<std::uint64_t>(per_particle * double(N) / 2.0);
  double t = 0.0, ref_rounding = 0.0;
  for (std::uint64_t n = 1; n <= collisions; ++n) {
    const double dt = rng.standard_exponential() * 2.0 / double(N) * std::sqrt(E0 / kinetic_energy(anchored));
    t += dt;
    for (std::size_t j = 0; j < N; ++j) {
      R[j] = {R[j].x + anchored.v[j].x * dt, R[j].y + anchored.v[j].y * dt, R[j].z + anchored.v[j].z * dt};
      ref_rounding += 0x1p-53 * std::sqrt(norm2(R[j]));  // the reference's own rounding (bounded, summed)
    }
    std::size_t a = rng.below(N), b = rng.below(N - 1);
    if (b >= a) ++b;
    const Vec3 g = anchored.v[a] - anchored.v[b];
    const double gn = std::sqrt(norm2(g));
    const Vec3 e = rng.hemisphere({g.x / gn, g.y / gn, g.z / gn});
    const double ge = g.x * e.x + g.y * e.y + g.z * e.z;
    const double ma = anchored.mass[a < N / 2 ? 0 : 1], mb = anchored.mass[b < N / 2 ? 0 : 1];
    collide(anchored, a, b, ma, mb, eps, e, ge, t);
    collide(naive, a, b, ma, mb, eps, e, ge, t);
    updated(a, t - anchored.epoch), updated(b, t - anchored.epoch);
    if (n % N == 0) {  // the event loop's refresh point (every N collisions)
      reanchor(anchored, t);
      for (std::size_t j = 0; j < N; ++j) updated(j, 0.0);
    }
  }
  REQUIRE(naive.epoch == 0.0);
  o.cooled = kinetic_energy(anchored) / E0;
  double r2 = 0.0, vt2 = 0.0;
  for (std::size_t j = 0; j < N; ++j) {
    const Vec3 ra = displacement(anchored, j, t), rn = displacement(naive, j, t);
    // Unbiased, uncorrelated roundings of at most u|x| each: standard deviation at most
    // u √(Σx²/3); bound 5 of those, plus the reference's own rounding (summed, worst case).
    const double bound = 5.0 * u * std::sqrt(sum_x2[j] / 3.0) + ref_rounding;
    const double err[3] = {ra.x - R[j].x, ra.y - R[j].y, ra.z - R[j].z}, err_naive[3] = {rn.x - R[j].x, rn.y - R[j].y, rn.z - R[j].z};
    for (int c = 0; c < 3; ++c) {
      o.max_z = std::max(o.max_z, std::abs(err[c]) / bound);
      o.naive_over_bound = std::max(o.naive_over_bound, std::abs(err_naive[c]) / bound);
    }
    o.updates += updates[j] / double(N), o.max_updates = std::max(o.max_updates, updates[j]);
    o.intercept_over_scale = std::max(o.intercept_over_scale, max_r0[j] / max_scale[j]);
    r2 += norm2(R[j]) / double(N), vt2 += norm2(anchored.v[j]) * t * t / double(N);
  }
  o.displacement = std::sqrt(r2), o.flight = std::sqrt(vt2);
  std::printf("float intercepts, eps %.2g, %.0f updates/particle to t = %.4g: rms |R| %.4g, rms |v| t %.4g; "
              "max |error|/bound %.3f (epoch anchor), %.3g (float anchored at t = 0); max |R0_e|/scale %.7f; E/E0 %.2g\n",
              eps, o.updates, t, o.displacement, o.flight, o.max_z, o.naive_over_bound, o.intercept_over_scale, o.cooled);
  return o;
}

}  // namespace

TEST_CASE("float flight intercepts at a global epoch: displacements within u sqrt(n/3) |R0_e| of double", "[dsmc]") {
  SECTION("elastic, 1e5 collisions per particle: the epoch anchor holds, a float anchored at t = 0 does not") {
    const Outcome o = run(1.0, 1e5, 3);
    CHECK(o.updates > 1.4e5);  // 1e5 collisions and 0.5e5 re-anchors per particle
    CHECK(o.max_z <= 1.0);
    // |R0_e| = |R − v (t − t_e)| <= |R| + |v| (t − t_e), up to the accumulated rounding (the bound above).
    CHECK(o.intercept_over_scale <= 1.0 + 5.0 * u * std::sqrt(o.max_updates / 3.0));
    // The intercept anchored at t = 0 is of size |v| t, ~ √(t/τ) times the displacement (diffusive in
    // an elastic gas); its error is that factor (~300 at t = 1e5 τ) times larger and fails the bound.
    CHECK(o.flight > 100.0 * o.displacement);
    CHECK(o.naive_over_bound > 10.0);
  }
  SECTION("cooling, eps = 0.8, 1e3 collisions per particle (E falls below 1e-20 E0)") {
    const Outcome o = run(0.8, 1e3, 5);
    CHECK(o.max_z <= 1.0);
    CHECK(o.intercept_over_scale <= 1.0 + 5.0 * u * std::sqrt(o.max_updates / 3.0));
    CHECK(o.cooled < 1e-20);
  }
}

TEST_CASE("a particle with displacements costs at most 40 bytes", "[dsmc]") {
  std::printf("bytes per particle: %zu, %zu with displacements\n", Particles::bytes_per_particle(false), Particles::bytes_per_particle(true));
  CHECK(Particles::bytes_per_particle(false) == sizeof(Vec3));
  CHECK(Particles::bytes_per_particle(true) <= 40);
}
