// Second Sonine approximation of the one-species HCS (theory/sonine/sonine_second_order.hpp) and the first-Sonine
// truncation estimate built on it (theory/sonine/sonine_truncation.hpp): the nine collision-moment coefficients
// against an independent exact Gauss quadrature of the collision integral and a Monte Carlo over sampled
// velocity pairs and impact directions; the elastic limit; the first-Sonine limit against van Noije–Ernst
// and the HCS solver theory/ uses; the truncation estimates against the distributions written out here.
#include <catch2/catch.hpp>
#include <gsl/gsl_integration.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "model/errors.hpp"
#include "theory/sonine/sonine_second_order.hpp"
#include "theory/sonine/sonine_truncation.hpp"

using namespace granmix::theory;

namespace {

// Written out here, not taken from the library: L_n^(1/2)(x) with S_n(0) > 0.
double L2(double x) { return x * x / 2 - 5 * x / 2 + 15.0 / 8; }
double L3(double x) { return -x * x * x / 6 + 7 * x * x / 4 - 35 * x / 8 + 35.0 / 16; }

using Coefficients = std::array<std::array<double, 3>, 3>;  // [p = 2, 4, 6][a-free, a₂, a₃], divided by √(2π)

// The collision rule of two equal spheres, v₁′ = v₁ − ((1+α)/2)(v₁₂·σ̂)σ̂, v₂′ = v₂ + ((1+α)/2)(v₁₂·σ̂)σ̂, and the
// weighted change of c₁^p + c₂^p for one pair: adds  weight·Δ(c₁^p + c₂^p)·{1, S₂+S₂, S₃+S₃}  to acc.
void add_pair(const double* c1, const double* c2, const double* s, double alpha, double weight, Coefficients& acc) {
  double g_s = 0;
  for (int i = 0; i < 3; ++i) g_s += (c1[i] - c2[i]) * s[i];
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double d = 0.5 * (1 + alpha) * g_s * s[i], p1 = c1[i] - d, p2 = c2[i] + d;
    x1 += c1[i] * c1[i], x2 += c2[i] * c2[i], y1 += p1 * p1, y2 += p2 * p2;
  }
  const std::array<double, 3> w = {1.0, L2(x1) + L2(x2), L3(x1) + L3(x2)};
  const std::array<double, 3> dpsi = {y1 + y2 - x1 - x2, y1 * y1 + y2 * y2 - x1 * x1 - x2 * x2,
                                      y1 * y1 * y1 + y2 * y2 * y2 - x1 * x1 * x1 - x2 * x2 * x2};
  for (int p = 0; p < 3; ++p)
    for (int j = 0; j < 3; ++j) acc[p][j] += weight * dpsi[p] * w[j];
}

struct FixedRule {
  std::vector<double> x, w;
  FixedRule(const gsl_integration_fixed_type* type, std::size_t n) {
    gsl_integration_fixed_workspace* ws = gsl_integration_fixed_alloc(type, n, 0.0, 1.0, 0.0, 0.0);
    REQUIRE(ws != nullptr);
    x.assign(gsl_integration_fixed_nodes(ws), gsl_integration_fixed_nodes(ws) + n);
    w.assign(gsl_integration_fixed_weights(ws), gsl_integration_fixed_weights(ws) + n);
    gsl_integration_fixed_free(ws);
  }
};

// μ_p = −(1/2)∫dc₁dc₂ φφ W ∫dσ̂ Θ(−c₁₂·σ̂)|c₁₂·σ̂| Δψ, φ = π^(−3/2)e^(−c²). The σ̂ integral of the rest is the same
// for every σ̂ (rotation), so σ̂ = ẑ times 4π; reflecting z maps Θ(−g_z) onto Θ(g_z), so Θ → 1/2:
// μ_p = −π ∫ φφ W |g_z| Δψ. x and y components of c₁, c₂: Gauss–Hermite (e^(−c²)); z: C = (c₁z + c₂z)/2 with
// e^(−2C²) (Hermite in √2 C) and g = c₁z − c₂z with |g| e^(−g²/2) (Laguerre in t = g²/2, both signs of g).
// The integrand is a polynomial of degree ≤ 12 in each variable, so 7 Hermite and 4 Laguerre nodes are exact.
Coefficients quadrature_moments(double alpha) {
  static const FixedRule H(gsl_integration_fixed_hermite, 7), L(gsl_integration_fixed_laguerre, 4);
  Coefficients acc{};
  const double z_hat[3] = {0, 0, 1};
  for (std::size_t a = 0; a < 7; ++a)
    for (std::size_t b = 0; b < 7; ++b)
      for (std::size_t c = 0; c < 7; ++c)
        for (std::size_t d = 0; d < 7; ++d)
          for (std::size_t e = 0; e < 7; ++e)
            for (std::size_t t = 0; t < 4; ++t)
              for (double sign : {1.0, -1.0}) {
                const double Cz = H.x[e] / std::numbers::sqrt2, g = sign * std::sqrt(2 * L.x[t]);
                const double c1[3] = {H.x[a], H.x[b], Cz + g / 2}, c2[3] = {H.x[c], H.x[d], Cz - g / 2};
                add_pair(c1, c2, z_hat, alpha, H.w[a] * H.w[b] * H.w[c] * H.w[d] * H.w[e] * L.w[t], acc);
              }
  const double norm = -std::numbers::pi / std::pow(std::numbers::pi, 3) / std::numbers::sqrt2 / std::sqrt(2 * std::numbers::pi);
  for (auto& row : acc)
    for (double& v : row) v *= norm;
  return acc;
}

Coefficients closed_form(double alpha) {
  const HcsCollisionMoments m = hcs_collision_moments(alpha);
  return {m.mu2, m.mu4, m.mu6};
}

}  // namespace

TEST_CASE("second Sonine: the nine collision-moment coefficients equal an exact quadrature of the collision integral", "[theory]") {
  // Both sides are exact: the bound is rounding (sums of ~7e4 terms of size up to ~1e4 relative to results ~1).
  // A transcription slip in one coefficient of the polynomials (e.g. 12617 -> 12671) is a 1e-3 change.
  for (double alpha : {0.0, 0.3, 0.5, 0.7071, 0.8, 0.95, 1.0}) {
    const Coefficients q = quadrature_moments(alpha), c = closed_form(alpha);
    for (int p = 0; p < 3; ++p)
      for (int j = 0; j < 3; ++j) {
        INFO("alpha " << alpha << " mu_" << 2 * (p + 1) << " coefficient " << j << ": quadrature " << q[p][j] << " closed " << c[p][j]);
        CHECK(c[p][j] == Approx(q[p][j]).epsilon(1e-10).margin(1e-11));
      }
  }
}

TEST_CASE("second Sonine: a Monte Carlo of sampled pairs and impact directions agrees with the Maxwellian moments (|z| < 4)", "[theory]") {
  // Independent of the σ̂ = ẑ reduction of the quadrature (the factor 4π and Θ → 1/2): c₁, c₂ ~ φ, σ̂ uniform on
  // the sphere, μ_p = −(1/2)·4π·E[Θ(−c₁₂·σ̂)|c₁₂·σ̂| Δψ]. Only the a-free coefficients: the S₂, S₃-weighted
  // estimators are heavy-tailed (their errors are not reliable at any affordable N); the quadrature checks them.
  const double alpha = 0.5;
  const Coefficients c = closed_form(alpha);
  std::mt19937_64 rng(20260512);
  std::normal_distribution<double> normal(0.0, std::sqrt(0.5));
  const int N = 2000000;
  std::array<double, 3> sum{}, sum2{};
  for (int n = 0; n < N; ++n) {
    double c1[3], c2[3], s[3], norm = 0, g_s = 0;
    for (int i = 0; i < 3; ++i) c1[i] = normal(rng), c2[i] = normal(rng);
    for (double& si : s) si = normal(rng), norm += si * si;
    for (int i = 0; i < 3; ++i) s[i] /= std::sqrt(norm), g_s += (c1[i] - c2[i]) * s[i];
    if (g_s >= 0) continue;  // Θ(−c₁₂·σ̂): an approaching pair; a zero term otherwise (still counted in N)
    Coefficients one{};
    add_pair(c1, c2, s, alpha, -0.5 * 4 * std::numbers::pi * std::abs(g_s) / std::sqrt(2 * std::numbers::pi), one);
    for (int p = 0; p < 3; ++p) sum[p] += one[p][0], sum2[p] += one[p][0] * one[p][0];
  }
  for (int p = 0; p < 3; ++p) {
    const double mean = sum[p] / N, err = std::sqrt((sum2[p] / N - mean * mean) / (N - 1)), z = (mean - c[p][0]) / err;
    std::printf("MC mu_%d at a = 0: %.5f +- %.5f  closed %.5f  z = %+.2f\n", 2 * (p + 1), mean, err, c[p][0], z);
    INFO("mu_" << 2 * (p + 1));
    CHECK(std::abs(z) < 4.0);
    CHECK(err < 0.0075 * c[p][0]);  // discriminates: a 3% error (e.g. a wrong power of 2 in one term) is > 4 sigma
  }
}

TEST_CASE("second Sonine: elastic limit a2 = a3 = 0, and the solution satisfies both moment equations", "[theory]") {
  const SecondSonine elastic = second_sonine_hcs(1.0);
  CHECK(elastic.a2 == 0.0);
  CHECK(elastic.a3 == 0.0);
  // Quasi-elastic: both vanish linearly in 1 − α (the sources B₀ − 5A₀ and C₀ − (105/4)A₀ are ∝ 1 − α).
  const SecondSonine e1 = second_sonine_hcs(1 - 1e-4), e2 = second_sonine_hcs(1 - 2e-4);
  CHECK(e2.a2 / e1.a2 == Approx(2.0).epsilon(1e-3));
  CHECK(e2.a3 / e1.a3 == Approx(2.0).epsilon(1e-3));
  for (double alpha : {0.0, 0.3, 0.5, 0.6, 0.8, 0.9}) {
    const SecondSonine s = second_sonine_hcs(alpha);
    const HcsCollisionMoments m = hcs_collision_moments(alpha);
    auto mu = [&](const std::array<double, 3>& k) { return k[0] + k[1] * s.a2 + k[2] * s.a3; };
    // The linear scheme: products of a's dropped on both sides, so μ₄ − 5μ₂(1 + a₂) = −5A₂a₂² − 5A₃a₂a₃ exactly.
    const double A2 = m.mu2[1], A3 = m.mu2[2];
    INFO("alpha " << alpha);
    CHECK(mu(m.mu4) - 5 * mu(m.mu2) * (1 + s.a2) == Approx(-5 * (A2 * s.a2 + A3 * s.a3) * s.a2).margin(1e-14));
    CHECK(mu(m.mu6) - 105.0 / 4 * mu(m.mu2) * (1 + 3 * s.a2 - s.a3) ==
          Approx(-105.0 / 4 * (A2 * s.a2 + A3 * s.a3) * (3 * s.a2 - s.a3)).margin(1e-13));
  }
  CHECK_THROWS_AS(second_sonine_hcs(1.01), granmix::InputError);
  CHECK_THROWS_AS(second_sonine_hcs(-0.1), granmix::InputError);
}

TEST_CASE("first Sonine: a2 from these moments (a3 = 0) = van Noije-Ernst = the HCS solver of theory/", "[theory]") {
  // van Noije & Ernst, Granular Matter 1, 57 (1998): a₂ = 16(1−α)(1−2α²)/(81 − 17α + 30α²(1−α)) (published).
  for (int step = 0; step <= 20; ++step) {
    const double a = 0.05 * step;
    const HcsCollisionMoments m = hcs_collision_moments(a);
    const double from_moments = (m.mu4[0] - 5 * m.mu2[0]) / (5 * (m.mu2[0] + m.mu2[1]) - m.mu4[1]);
    const double vne = 16 * (1 - a) * (1 - 2 * a * a) / (81 - 17 * a + 30 * a * a * (1 - a));
    const double solver = sonine_truncation(a).a2_first;  // sonine_hcs, one species: c/2
    INFO("alpha " << a);
    CHECK(from_moments == Approx(vne).margin(1e-14));
    CHECK(solver == Approx(vne).margin(1e-13));
  }
}

TEST_CASE("truncation estimate: the second-order distributions, their measured cumulant and Delta, written out", "[theory]") {
  for (double alpha : {0.3, 0.5, 0.9}) {
    const SonineTruncation t = sonine_truncation(alpha);
    const SecondSonine s = second_sonine_hcs(alpha);
    INFO("alpha " << alpha);
    CHECK(t.linear.a2 == s.a2);
    CHECK(t.linear.a3 == s.a3);
    // The a₂-given variant solves the sixth-moment row alone: at a₂[2] it returns a₃[2]; at a₂[1] it is the scheme.
    CHECK(third_sonine_given_a2(alpha, s.a2) == Approx(s.a3).epsilon(1e-12));
    CHECK(t.a2_fixed.a2 == t.a2_first);
    CHECK(t.a2_fixed.a3 == third_sonine_given_a2(alpha, t.a2_first));
    CHECK(std::abs(t.a2_fixed.a3) < 0.7 * std::abs(s.a3));  // 0.59 (α = 0.5): the two schemes' spread
    CHECK(t.a2_relative() == Approx(std::abs(s.a2 / t.a2_first - 1)).epsilon(1e-14));
    for (SonineScheme scheme : {SonineScheme::linear, SonineScheme::a2_first}) {
      const SecondSonine f = t.second(scheme);
      INFO("scheme " << (scheme == SonineScheme::linear ? "linear" : "a2_first"));
      // Φ[2] and Φ[1] as distributions of c; the cumulant a DSMC would measure from Φ[2]:
      // a₂,meas = ⟨c⁴⟩/(15/4) − 1 by a 1-D quadrature in c (4π c² weight).
      auto phi_M = [](double c) { return std::pow(std::numbers::pi, -1.5) * std::exp(-c * c); };
      auto phi2 = [&](double c) { return phi_M(c) * (1 + f.a2 * L2(c * c) + f.a3 * L3(c * c)); };
      auto phi1 = [&](double c) { return phi_M(c) * (1 + t.a2_first * L2(c * c)); };
      double m0 = 0, m4 = 0;
      const double h = 1e-3;
      for (int i = 0; i < 12000; ++i) {  // midpoint rule to c = 12, error << 1e-9
        const double c = (i + 0.5) * h, w = 4 * std::numbers::pi * c * c * h * phi2(c);
        m0 += w, m4 += w * std::pow(c, 4);
      }
      CHECK(m0 == Approx(1.0).epsilon(1e-9));
      const double a2_meas = m4 / 3.75 - 1;
      CHECK(a2_meas == Approx(f.a2).epsilon(1e-8));  // S₃ leaves ⟨c⁴⟩ alone: the measured cumulant is the scheme's a₂
      for (double c : {0.3, 0.5, 1.0, 1.5, 2.5}) {
        INFO("c " << c);
        CHECK(t.phi_relative(c, scheme) == Approx(std::abs(phi2(c) / phi1(c) - 1)).epsilon(1e-12));
        CHECK(t.phi_a3_relative(c, scheme) == Approx(std::abs(f.a3 * L3(c * c) / (1 + t.a2_first * L2(c * c)))).epsilon(1e-14));
        // MG's Δ as the DSMC builds it, from the measured cumulant: (1/a₂,meas)(Φ/Φ_M − 1) = Δ[1] + shift.
        const double delta_meas = (phi2(c) / phi_M(c) - 1) / a2_meas;
        CHECK(L2(c * c) + t.delta_shift(c, scheme) == Approx(delta_meas).epsilon(1e-7));
        CHECK(t.delta_a3_relative(c, scheme) == Approx(std::abs(t.delta_shift(c, scheme) / L2(c * c))).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("truncation table for the lead (printed): first- and second-order a2 and a3 and the a3 share of Phi and Delta", "[theory]") {
  using enum SonineScheme;
  std::printf("%-5s %-10s %-10s %-10s %-10s %-7s | %-7s %-7s %-7s | %-7s %-7s %-7s | %-7s %-7s %-7s %-7s\n", "eps", "a2[1]", "a2[2]",
              "a3[2]", "a3|a2[1]", "d_a2", "Phi0.5", "Phi1", "Phi1.5", "Phi0.5'", "Phi1'", "Phi1.5'", "Dlt0", "Dlt0.5", "Dlt0'",
              "Dlt0.5'");
  for (double eps : {0.3, 0.5, 0.6, 0.8, 0.9}) {
    const SonineTruncation t = sonine_truncation(eps);
    std::printf("%-5.2f %-10.6f %-10.6f %-10.6f %-10.6f %-7.4f | %-7.5f %-7.5f %-7.5f | %-7.5f %-7.5f %-7.5f | %-7.4f %-7.4f %-7.4f %-7.4f\n",
                eps, t.a2_first, t.linear.a2, t.linear.a3, t.a2_fixed.a3, t.a2_relative(), t.phi_a3_relative(0.5, linear),
                t.phi_a3_relative(1.0, linear), t.phi_a3_relative(1.5, linear), t.phi_a3_relative(0.5, a2_first),
                t.phi_a3_relative(1.0, a2_first), t.phi_a3_relative(1.5, a2_first), t.delta_a3_relative(0.0, linear),
                t.delta_a3_relative(0.5, linear), t.delta_a3_relative(0.0, a2_first), t.delta_a3_relative(0.5, a2_first));
  }
  // Regression values from the exact rational solution (scripts/derive_sonine2_moments.py prints them):
  // α = 0.5, a₂[2] = 0.04499397800, a₃[2] = −0.01768416862.
  const SonineTruncation half = sonine_truncation(0.5);
  CHECK(half.linear.a2 == Approx(0.04499397800).epsilon(1e-9));
  CHECK(half.linear.a3 == Approx(-0.01768416862).epsilon(1e-9));
}
