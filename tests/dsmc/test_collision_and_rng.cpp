// The collision rule (docs/physics.md §1), the random streams and the sum tree, one piece at a time.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>
#include <algorithm>

#include "dsmc/collision_rule.hpp"
#include "dsmc/particles.hpp"
#include "dsmc/rng.hpp"
#include "dsmc/sum_tree.hpp"

using namespace granmix;
using namespace granmix::dsmc;

namespace {
Particles two_particles(double ma, double mb) {
  Particles p;
  p.offset = {0, 1, 2};
  p.mass = {ma, mb};
  p.v = {{1.3, -0.2, 0.7}, {-0.4, 0.9, 0.1}};
  return p;
}
}  // namespace

TEST_CASE("one collision: momentum to 1e-13 and the energy loss (1-eps^2) m_eff (g.e)^2/2", "[dsmc]") {
  Rng rng(11, 0);
  for (double eps : {0.0, 0.3, 0.9, 1.0})
    for (double mb : {1.0, 100.0, 1e4}) {
      Particles p = two_particles(1.0, mb);
      const Vec3 g = p.v[0] - p.v[1];
      const double gn = std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z);
      const Vec3 e = rng.hemisphere({g.x / gn, g.y / gn, g.z / gn});
      const double ge = g.x * e.x + g.y * e.y + g.z * e.z;
      REQUIRE(ge > 0.0);
      auto momentum = [&](int c) {
        auto comp = [&](const Vec3& v) { return c == 0 ? v.x : c == 1 ? v.y : v.z; };
        return comp(p.v[0]) + mb * comp(p.v[1]);
      };
      auto energy = [&] {
        return 0.5 * norm2(p.v[0]) + 0.5 * mb * norm2(p.v[1]);
      };
      const double P[3] = {momentum(0), momentum(1), momentum(2)}, E = energy();
      collide(p, 0, 1, 1.0, mb, eps, e, ge, 0.0);
      // Rounding of a few operations on numbers of size mb|v|: 1e-13 relative.
      for (int c = 0; c < 3; ++c) CHECK(std::abs(momentum(c) - P[c]) <= 1e-13 * (1 + mb));
      const double meff = mb / (1 + mb);
      CHECK(E - energy() == Approx((1 - eps * eps) * meff * ge * ge / 2).epsilon(1e-12).margin(1e-14 * E));
      // After the collision the normal relative speed is reversed and scaled by ε (v1 Eq. 4).
      const Vec3 g_after = p.v[0] - p.v[1];
      const double ge_after = g_after.x * e.x + g_after.y * e.y + g_after.z * e.z;
      CHECK(ge_after == Approx(-eps * ge).margin(1e-13));
    }
}

TEST_CASE("hemisphere directions: unit - on the side of n - <cos> = 2/3", "[dsmc]") {
  Rng rng(5, 2);
  const Vec3 n{0.6, 0.0, -0.8};
  const int N = 200000;
  double sum = 0.0, sum2 = 0.0;
  for (int j = 0; j < N; ++j) {
    const Vec3 e = rng.hemisphere(n);
    const double c = e.x * n.x + e.y * n.y + e.z * n.z;
    REQUIRE(std::abs(e.x * e.x + e.y * e.y + e.z * e.z - 1) < 1e-14);
    REQUIRE(c >= 0.0);
    sum += c, sum2 += c * c;
  }
  // Density ∝ cos θ: ⟨cos θ⟩ = 2/3, ⟨cos² θ⟩ = 1/2; z-score bound 4.
  const double mean = sum / N, sd = std::sqrt(sum2 / N - mean * mean) / std::sqrt(double(N));
  std::printf("hemisphere: <cos> = %.5f, z = %.2f\n", mean, (mean - 2.0 / 3) / sd);
  CHECK(std::abs(mean - 2.0 / 3) < 4 * sd);
}

TEST_CASE("normal draws and bounded integers", "[dsmc]") {
  Rng rng(1, 0);
  const int N = 400000;
  double s = 0, s2 = 0;
  std::vector<int> bins(7, 0);
  for (int j = 0; j < N; ++j) {
    const double x = rng.normal();
    s += x, s2 += x * x;
    ++bins[rng.below(7)];
  }
  // Mean 0 (sd 1/√N) and variance 1 (sd √(2/N)): z bound 4.
  CHECK(std::abs(s / N) < 4 / std::sqrt(double(N)));
  CHECK(std::abs(s2 / N - 1) < 4 * std::sqrt(2.0 / N));
  double chi2 = 0;
  for (int b : bins) chi2 += std::pow(b - N / 7.0, 2) / (N / 7.0);
  CHECK(chi2 < 22.5);  // χ² with 6 degrees of freedom: P(> 22.5) = 1e-3
}

TEST_CASE("ziggurat exponential: chi2 over 20 equal-probability bins and the tail beyond r - mean and variance 1", "[dsmc]") {
  Rng rng(11, 0);
  const int N = 2000000, B = 20;
  const double r = exp_ziggurat.x[1];  // the ziggurat's tail start, 7.697: its own code path
  std::vector<double> hits(B + 1, 0.0), p(B + 1);
  double s = 0, s2 = 0;
  int negative = 0;
  for (int j = 0; j < N; ++j) {
    const double x = rng.standard_exponential();
    negative += x < 0.0;
    s += x, s2 += x * x;
    // Bin b < B: [-ln(1 - b/B), -ln(1 - (b+1)/B)) (the last one ends at r); bin B: [r, ∞).
    const auto b = static_cast<std::size_t>(B * (1.0 - std::exp(-x)));
    ++hits[x >= r ? B : std::min<std::size_t>(b, B - 1)];
  }
  for (int b = 0; b < B; ++b) p[b] = 1.0 / B;
  p[B - 1] -= std::exp(-r), p[B] = std::exp(-r);
  double chi2 = 0;
  for (int b = 0; b <= B; ++b) chi2 += std::pow(hits[b] - N * p[b], 2) / (N * p[b]);
  std::printf("ziggurat exponential: chi2 = %.1f (20 dof), tail %g of %g expected, mean %.5f\n", chi2, hits[B], N * p[B], s / N);
  CHECK(negative == 0);
  CHECK(chi2 < 45.3);  // χ² with 20 degrees of freedom: P(> 45.3) = 1e-3
  // Mean 1 (sd 1/√N) and second moment 2 (sd √(20/N): E x⁴ = 24): z bound 4.
  CHECK(std::abs(s / N - 1) < 4 / std::sqrt(double(N)));
  CHECK(std::abs(s2 / N - 2) < 4 * std::sqrt(20.0 / N));
}

TEST_CASE("streams: same (seed - replica) repeat - different ones differ", "[dsmc]") {
  Rng a(7, 3), b(7, 3), c(7, 4), d(8, 3);
  const double x = a.uniform();
  CHECK(x == b.uniform());
  CHECK(x != c.uniform());
  CHECK(x != d.uniform());
}

TEST_CASE("sum tree: sampling frequencies and updates", "[dsmc]") {
  std::vector<double> w = {0.5, 0.0, 2.0, 1.0, 0.25};
  SumTree t(w);
  CHECK(t.total() == Approx(3.75));
  t.set(1, 1.25);
  w[1] = 1.25;
  CHECK(t.total() == Approx(5.0));
  Rng rng(3, 0);
  const int N = 500000;
  std::vector<int> hits(w.size(), 0);
  for (int j = 0; j < N; ++j) ++hits[t.sample(rng.uniform())];
  double chi2 = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const double expect = N * w[i] / 5.0;
    chi2 += std::pow(hits[i] - expect, 2) / expect;
  }
  CHECK(chi2 < 18.5);  // 4 degrees of freedom: P(> 18.5) = 1e-3
  t.set(2, 0.0);
  for (int j = 0; j < 10000; ++j) CHECK(t.sample(rng.uniform()) != 2);
}

TEST_CASE("initial state with single-particle species: zero total momentum and exact T_k", "[dsmc]") {
  // A single particle keeps its own velocity; the others drift to cancel its momentum. Without that
  // the centre-of-mass energy is never dissipated (a temperature floor in v1 Fig. 8).
  const model::Mixture mix({{1.0, 1.0, 0.1}, {8.0, 2.0, 1e-3}, {27.0, 3.0, 1e-4}, {64.0, 4.0, 1e-4}});
  const std::vector<std::size_t> counts = {1000, 10, 1, 1};
  const std::vector<double> T = {1.0, 2.0, 3.0, 4.0};
  Rng rng(5, 0);
  const Particles p = maxwellian_particles(mix, counts, T, false, true, rng);
  double px = 0, py = 0, pz = 0, scale = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    CHECK(species_temperature(p, k) == Approx(T[k]).epsilon(1e-13));  // rounding of one rescale
    for (std::size_t j = p.begin(k); j < p.end(k); ++j) {
      px += p.mass[k] * p.v[j].x, py += p.mass[k] * p.v[j].y, pz += p.mass[k] * p.v[j].z;
      scale += p.mass[k] * std::abs(p.v[j].x);
    }
  }
  const double worst = std::max({std::abs(px), std::abs(py), std::abs(pz)}) / scale;
  std::printf("single-particle species: |P| / sum |m v| = %.2e, T_k exact\n", worst);
  CHECK(worst < 1e-13);  // momentum zero to rounding (sum of ~1000 terms)
}
