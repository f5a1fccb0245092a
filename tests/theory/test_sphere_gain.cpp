// SphereGain (theory/grid/sphere_gain.hpp): the gain of a collision into the speed grid's cubic B-splines, Σ_p W_p ∫ N_m(s) sᵖ
// ds over a range of post-collision speeds, accumulated as per-interval power sums. Checked against the integrals done
// directly (Gauss–Legendre on every knot interval the range covers, exact for the polynomials there).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "gauss_rules.hpp"
#include "theory/grid/sphere_gain.hpp"

using namespace granmix::theory;

namespace {

// The cardinal cubic B-spline on [0, 4] (speed_grid.cpp's N_m(s) = spline(s/h − m + 3)), written out again.
double spline(double x) {
  if (x <= 0.0 || x >= 4.0) return 0.0;
  if (x < 1.0) return x * x * x / 6.0;
  if (x < 2.0) return (-3.0 * x * x * x + 12.0 * x * x - 12.0 * x + 4.0) / 6.0;
  if (x < 3.0) return (3.0 * x * x * x - 24.0 * x * x + 60.0 * x - 44.0) / 6.0;
  return (4.0 - x) * (4.0 - x) * (4.0 - x) / 6.0;
}

// Σ_p W_p ∫ N_m(s) sᵖ ds over [lo, min(hi, nb·h)] by 6-point Gauss–Legendre on each knot interval (degree ≤ 11 exact).
std::vector<double> direct(std::size_t nb, double h, const std::vector<std::array<double, 5>>& ranges) {
  const granmix::test::Rule gl = granmix::test::legendre01(6);
  std::vector<double> out(nb, 0.0);
  for (const auto& r : ranges) {
    const double lo = r[0], hi = std::min(r[1], double(nb) * h);
    for (std::size_t q = 0; q < nb; ++q) {
      const double a = std::max(lo, double(q) * h), b = std::min(hi, double(q + 1) * h);
      if (a >= b) continue;
      for (std::size_t g = 0; g < gl.x.size(); ++g) {
        const double s = a + (b - a) * gl.x[g], ws = (b - a) * gl.w[g];
        const double f = r[2] + r[3] * s + r[4] * s * s;
        for (std::size_t m = 0; m < nb; ++m) out[m] += ws * f * spline(s / h - double(m) + 3.0);
      }
    }
  }
  return out;
}

}  // namespace

TEST_CASE("sphere gain: the power sums give the ranges' spline integrals", "[theory]") {
  // Ranges within one knot interval, across many, from 0, reaching past the grid's end (their part beyond leaves it),
  // each p alone and all together; 200 at once as one speed's collisions are. A wrong spline piece, a missing interval
  // below an end or a wrong power is an error of order the integral itself.
  const std::size_t nb = 23;
  const double h = 0.37;
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<std::array<double, 5>> ranges;
    const std::size_t count = trial < 4 ? 1 : 200;
    for (std::size_t c = 0; c < count; ++c) {
      const double lo = trial == 0 ? 0.0 : U(rng) * h * double(nb);
      const double width = h * (trial == 1 ? 0.3 * U(rng) : trial == 2 ? 3.0 * double(nb) : 6.0 * U(rng));
      std::array<double, 5> r = {lo, lo + width, 0.0, 0.0, 0.0};
      for (std::size_t p = 0; p < 3; ++p) r[2 + p] = (trial == 3 && p != 1) ? 0.0 : U(rng) - 0.3;
      ranges.push_back(r);
    }
    SphereGain gain(nb, h);
    gain.clear();
    for (const auto& r : ranges) gain.add_range(r[0], r[1], {r[2], r[3], r[4]});
    const std::vector<double>& got = gain.finish();
    const std::vector<double> want = direct(nb, h, ranges);
    double scale = 0.0;
    for (double v : want) scale = std::max(scale, std::abs(v));
    for (std::size_t m = 0; m < nb; ++m) {
      INFO("trial " << trial << ", spline " << m);
      CHECK(std::abs(got[m] - want[m]) < 1e-12 * scale);
    }
    // clear() starts the next speed: the same ranges again give the same gains.
    const std::vector<double> first = got;
    gain.clear();
    for (const auto& r : ranges) gain.add_range(r[0], r[1], {r[2], r[3], r[4]});
    CHECK(gain.finish() == first);
  }
}
