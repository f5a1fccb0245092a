// Second-Sonine tracer diffusion (docs/physics-beyond.md §3): the closed-form collision integrals
// against an independent quadrature and a plain Monte Carlo over both Maxwellians and σ̂; the
// exact limits (elastic Lorentz gas 13/12, elastic self-diffusion 59/58); and D[2] against a Monte
// Carlo of the tagged-particle Boltzmann–Lorentz problem itself (elastic and inelastic HCS, and
// the light species of the 1:100 mixture of v1 Fig. 2).
#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "model/enskog.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/sonine/sonine2_diffusion.hpp"
#include "gauss_rules.hpp"
#include "tagged_particle_mc.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;
using namespace granmix::test;
using std::numbers::pi;

namespace {

// ψ_q(c)·[ψ_p(c) − ψ_p(c′)], ψ_p = c S_p(c²), c = v/√(2A_k): the integrand of C_pq.
double psi_integrand(int p, int q, const Vec& v, const Vec& vp, double Ak) {
  const double s = 1.0 / (2.0 * Ak), c2 = dot(v, v) * s, cp2 = dot(vp, vp) * s;
  auto S = [](int n, double x) { return n == 0 ? 1.0 : 2.5 - x; };
  return S(q, c2) * s * (dot(v, v) * S(p, c2) - dot(v, vp) * S(p, cp2));
}

// C_pq/weight by quadrature, written from the definition: v ~ N(0, A_k), w ~ N(0, A_i) rewritten as
// g = v − w ~ N(0, V) and v = (A_k/V) g + G, G ~ N(0, A_k A_i/V) independent of g; by isotropy g = |g| ẑ.
// |g| (Maxwell, Gauss–Laguerre in u = |g|²/2V), G (Gauss–Hermite), cos θ (Gauss–Legendre), φ (trapezoid):
// the integrand is a polynomial in each, so every rule is exact at these orders.
double quadrature_C(int p, int q, double mu, double eps, double Ak, double Ai) {
  const double V = Ak + Ai, a = Ak / V, sG = std::sqrt(2.0 * Ak * Ai / V), beta = mu * (1 + eps);
  const test::Rule H = test::hermite(6), L = test::laguerre(8), P = test::legendre01(8);
  const int nphi = 16;
  double sum = 0.0;
  for (std::size_t iu = 0; iu < L.x.size(); ++iu) {
    const double g = std::sqrt(2.0 * V * L.x[iu]);
    // E[h(|g|)] = ∫ h(√(2Vu)) √u e^{−u} du / Γ(3/2): the √u goes into the integrand.
    const double wu = L.w[iu] * std::sqrt(L.x[iu]) / (0.5 * std::sqrt(pi));
    for (std::size_t i = 0; i < H.x.size(); ++i)
      for (std::size_t j = 0; j < H.x.size(); ++j)
        for (std::size_t l = 0; l < H.x.size(); ++l) {
          const double wG = wu * H.w[i] * H.w[j] * H.w[l] / std::pow(pi, 1.5);
          const Vec v = {sG * H.x[i], sG * H.x[j], sG * H.x[l] + a * g};
          for (std::size_t t = 0; t < P.x.size(); ++t)
            for (int f = 0; f < nphi; ++f) {
              const double ct = P.x[t], st = std::sqrt(1 - ct * ct), phi = 2 * pi * f / nphi;
              const Vec sigma = {st * std::cos(phi), st * std::sin(phi), ct};
              const double gs = g * ct;  // g·σ̂ > 0 on the hemisphere
              const Vec vp = axpy(-beta * gs, sigma, v);
              sum += wG * P.w[t] * (2 * pi / nphi) * gs * psi_integrand(p, q, v, vp, Ak);
            }
        }
  }
  return sum;
}

// The same by plain Monte Carlo from v, w and a uniform σ̂ (no change of variables): mean and error.
std::pair<double, double> monte_carlo_C(int p, int q, double mu, double eps, double Ak, double Ai, long n, std::mt19937_64& rng) {
  std::normal_distribution<double> N01;
  double s = 0, s2 = 0;
  for (long j = 0; j < n; ++j) {
    Vec v, w, sigma;
    for (int d = 0; d < 3; ++d) v[d] = std::sqrt(Ak) * N01(rng), w[d] = std::sqrt(Ai) * N01(rng), sigma[d] = N01(rng);
    const double norm = std::sqrt(dot(sigma, sigma));
    for (double& x : sigma) x /= norm;
    const double gs = dot(axpy(-1.0, w, v), sigma);
    double x = 0.0;
    if (gs > 0) x = 4 * pi * gs * psi_integrand(p, q, v, axpy(-mu * (1 + eps) * gs, sigma, v), Ak);
    s += x, s2 += x * x;
  }
  const double mean = s / n;
  return {mean, std::sqrt((s2 / n - mean * mean) / n)};
}

// D[1], D[2] of species k and the Monte Carlo of the same tracer problem (ζ = ξ_k, the cooling rate
// of the scaled problem; in these HCS states ξ_k is the common ζ).
// within_z4: also require |z| < 4 against D[2] (where the truncation error of D[2] is below the
// Monte Carlo error).
void check_against_tagged_mc(const CollisionRates& r, std::size_t k, const std::vector<double>& T, double correlation_times, std::uint64_t seed,
                             const char* label, bool within_z4) {
  const model::Mixture& mix = r.mixture();
  std::vector<Partner> partners;
  for (std::size_t i = 0; i < mix.size(); ++i) {
    const double s = mix.sigma(k, i), mu = mix[i].mass / (mix[i].mass + mix[k].mass);
    partners.push_back({mix[i].density * s * s * r.chi(k, i), std::sqrt(T[i] / mix[i].mass), mu * (1 + r.law().eps(k, i))});
  }
  const double zeta = r.xi_species(k, T.data()), inv_tau = r.inv_tau_v_species(k, T.data());
  const double D1 = T[k] / (mix[k].mass * inv_tau), D2 = D1 * sonine_factor(r, k, T.data(), 2);
  const McDiffusion mc = tagged_particle_mc(partners, zeta, std::sqrt(T[k] / mix[k].mass), 1.0 / inv_tau, correlation_times, seed);
  const double z2 = (mc.D - D2) / mc.err, z1 = (mc.D - D1) / mc.err;
  std::printf("%s: D[1] = %.5f, D[2] = %.5f (D[2]/D[1] = %.5f), Monte Carlo %.5f ± %.5f (%ld collisions): MC/D[1] = %.4f, "
              "z vs D[2] = %.2f, z vs D[1] = %.2f\n",
              label, D1, D2, D2 / D1, mc.D, mc.err, mc.collisions, mc.D / D1, z2, z1);
  // Discriminating: the Monte Carlo resolves the D[2] − D[1] gap (four errors below it), and then
  // D[2] is the closer of the two.
  CHECK(4 * mc.err < std::abs(D2 - D1));
  CHECK(std::abs(mc.D - D2) < std::abs(mc.D - D1));
  if (within_z4) CHECK(std::abs(z2) < 4.0);
}

}  // namespace

TEST_CASE("sonine2: closed-form C_pq equal an exact quadrature over both Maxwellians and the collision direction", "[theory]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 6; ++trial) {
    const double mu = 0.01 + 0.98 * u(rng), eps = u(rng), Ak = std::pow(10.0, 2 * u(rng) - 1), Ai = std::pow(10.0, 2 * u(rng) - 1);
    const SonineCollisionIntegrals c = sonine2_pair_integrals(1.0, mu, eps, Ak, Ai);
    const double closed[2][2] = {{c(0, 0), c(0, 1)}, {c(1, 0), c(1, 1)}};
    for (int p = 0; p < 2; ++p)
      for (int q = 0; q < 2; ++q) {
        // Polynomial integrands, exact rules: rounding only (1e-10 asked, 1e-3 required).
        CHECK(quadrature_C(p, q, mu, eps, Ak, Ai) == Approx(closed[p][q]).epsilon(1e-10).margin(1e-12 * std::abs(c(0, 0))));
      }
  }
}

TEST_CASE("sonine2: closed-form C_pq agree with a plain Monte Carlo (z < 4)", "[theory]") {
  std::mt19937_64 rng(12);
  const double mu = 0.3, eps = 0.6, Ak = 0.8, Ai = 0.25;  // unequal masses and temperatures, inelastic
  const SonineCollisionIntegrals c = sonine2_pair_integrals(1.0, mu, eps, Ak, Ai);
  const double closed[2][2] = {{c(0, 0), c(0, 1)}, {c(1, 0), c(1, 1)}};
  for (int p = 0; p < 2; ++p)
    for (int q = 0; q < 2; ++q) {
      const auto [mean, err] = monte_carlo_C(p, q, mu, eps, Ak, Ai, 2000000, rng);
      const double z = (mean - closed[p][q]) / err;
      std::printf("C_%d%d: closed %.6f, Monte Carlo %.6f ± %.6f, z = %.2f\n", p, q, closed[p][q], mean, err, z);
      CHECK(std::abs(z) < 4.0);
      CHECK(4 * err < 0.05 * std::max(std::abs(closed[p][q]), c(0, 0)));  // z < 4 then pins each C_pq to 5% (of C₀₀ at least)
    }
}

TEST_CASE("sonine2: C_00 = (3/2) nu, the identity tau_v^-1 = nu - xi/2 (docs/physics-beyond.md §1), nu_eff from the library rates", "[theory]") {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 30; ++trial) {
    const double m2 = std::pow(10.0, 4 * u(rng) - 2), s2 = 0.2 + 5 * u(rng), e = u(rng);
    const model::Mixture mix({{1, 1, 0.1}, {m2, s2, 0.05 + u(rng)}});
    const double c12 = 1 + u(rng);
    const std::vector<std::vector<double>> chi = {{1 + u(rng), c12}, {c12, 1 + u(rng)}};
    const CollisionRates r(mix, model::Restitution::constant(2, e), chi);
    const double T[2] = {0.1 + u(rng), std::pow(10.0, 4 * u(rng) - 2)};
    for (std::size_t k = 0; k < 2; ++k) {
      double nu = 0;
      for (std::size_t i = 0; i < 2; ++i) {
        const double mk = mix[k].mass, mi = mix[i].mass, s = mix.sigma(k, i), mu = mi / (mi + mk);
        // ν_ki = (4/3)√(2π) n_i σ_ki² χ_ki μ_ik (1+ε) v_ki (docs/physics-beyond.md §1)
        const double nu_ki = 4.0 / 3 * std::sqrt(2 * pi) * mix[i].density * s * s * chi[k][i] * mu * (1 + e) * std::sqrt(T[k] / mk + T[i] / mi);
        CHECK(r.inv_tau_v(k, i, T[k], T[i]) == Approx(nu_ki - 0.5 * r.xi(k, i, T[k], T[i])).epsilon(1e-12));
        nu += nu_ki;
      }
      CHECK(sonine2_collision_integrals(r, k, T)(0, 0) == Approx(1.5 * nu).epsilon(1e-13));
      // The one-pass ξ_k and ν_eff against CollisionRates' own ξ_k and τ_v,k⁻¹.
      const double xi = r.xi_species(k, T), factor = sonine_factor(r, k, T, 2);
      CHECK(sonine2_tracer_sums(r, k, T).xi == Approx(xi).epsilon(1e-12).margin(1e-14 * nu));
      CHECK(kinetic_velocity_decay_rate(r, k, T, 2) == Approx(0.5 * xi + r.inv_tau_v_species(k, T) / factor).epsilon(1e-12));
    }
  }
}

TEST_CASE("sonine2: elastic Lorentz gas D[2]/D[1] = 13/12, elastic self-diffusion 59/58", "[theory]") {
  // Light tracer among infinitely heavy scatterers at rest (A_i = 0): a = 1, β = 2.
  CHECK(sonine_factor(sonine2_pair_integrals(1.0, 1.0, 1.0, 1.0, 0.0), 0.0) == Approx(13.0 / 12).epsilon(1e-15));
  // Elastic, equal temperatures (A_k m_k = A_i m_i, so a = μ): the collision operator is self-adjoint
  // in the Maxwellian weight, so C₀₁ = C₁₀ for every mass ratio (inelastic or T_i ≠ T_k they differ).
  for (double mu : {0.01, 0.3, 0.5, 0.9, 0.999}) {
    const SonineCollisionIntegrals c = sonine2_pair_integrals(1.0, mu, 1.0, mu, 1.0 - mu);
    CHECK(c(1, 0) == Approx(c(0, 1)).epsilon(1e-13));
  }
  // The same through the mixture: scatterers of mass 1e12, equal temperatures, a tracer density of 1e-20.
  const CollisionRates lorentz = test::constant_rates({{1, 1, 1e-20}, {1e12, 1, 1}}, 1.0);
  const double T2[2] = {1.0, 1.0};
  CHECK(sonine_factor(lorentz, 0, T2, 2) == Approx(13.0 / 12).epsilon(1e-11));
  // One species: a = 1/2, β = 1: C₀₀ = 2, C₀₁ = C₁₀ = −1/2, C₁₁ = 59/8, so D[2]/D[1] = 1/(1 − 1/59):
  // Chapman–Cowling's second approximation for rigid spheres (Δ = (6C*−5)²/(55−12B*+16A*) at
  // A* = B* = C* = 1); not 1 + 1/56 (Kihara's approximation) nor 1 + 1/48.
  for (double n : {0.1, 2.0}) {
    const CollisionRates one = test::constant_rates({{3, 0.7, n}}, 1.0);
    const double T[1] = {0.4};
    CHECK(sonine_factor(one, 0, T, 2) == Approx(59.0 / 58).epsilon(1e-14));
    // ν_eff = ν (58/59): the VACF rate that reproduces D[2].
    const double nu = one.inv_tau_v_species(0, T);  // ξ = 0
    CHECK(kinetic_velocity_decay_rate(one, 0, T, 2) == Approx(nu * 58 / 59).epsilon(1e-14));
  }
  // Enskog χ enters as a factor of every C_pq: the ratio does not change.
  const model::Mixture mix({{1, 1, 0.3}, {5, 2, 0.1}});
  const CollisionRates dilute(mix, model::Restitution::constant(2, 0.7), model::dilute_contact_values(2));
  const CollisionRates dense(mix, model::Restitution::constant(2, 0.7), {{2.0, 2.0}, {2.0, 2.0}});
  const double T[2] = {1.0, 3.0};
  CHECK(sonine_factor(dense, 1, T, 2) == Approx(sonine_factor(dilute, 1, T, 2)).epsilon(1e-14));
  CHECK(sonine2_collision_integrals(dense, 1, T)(1, 1) == Approx(2 * sonine2_collision_integrals(dilute, 1, T)(1, 1)).epsilon(1e-14));
}

TEST_CASE("sonine2: D[2] against a Monte Carlo of the tagged-particle problem - one species, elastic and inelastic HCS", "[theory]") {
  // Elastic: the converged Chapman–Enskog value is 1.019 D[1] for hard spheres, D[2] = (59/58) D[1].
  // ε = 0.5: D[2]/D[1] = 0.958. (ε = 0.8, 0.995, is not resolved: its gap is 0.5%.)
  check_against_tagged_mc(test::constant_rates({{1, 1, 1}}, 1.0), 0, {0.5}, 2e6, 21, "one species, eps = 1", true);
  check_against_tagged_mc(test::constant_rates({{1, 1, 1}}, 0.5), 0, {0.5}, 1e6, 22, "one species, eps = 0.5", true);
}

TEST_CASE("sonine2: D[2] against a Monte Carlo of the tagged-particle problem - light species of v1 Fig. 2", "[theory]") {
  // D[2]/D[1] = 0.921; the tracer problem's exact value lies between (0.940 measured): D[2] is the
  // closer one but still 2% low, its truncation error, far above the Monte Carlo error.
  const CollisionRates r = test::constant_rates(test::bo_binary(), 0.5);
  check_against_tagged_mc(r, 0, settled_temperatures(r).T, 1e6, 23, "bo1-fig02 light species", false);
}
