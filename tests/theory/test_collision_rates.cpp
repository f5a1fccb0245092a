// Cooling rates ξ_ki and inverse velocity correlation times τ_v,ki⁻¹ (v1 Appendix A) against a
// literal transcription of the printed formulas, the one-species closed forms, and the
// quadrature with the exact viscoelastic ε(y).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "model/enskog.hpp"
#include "theory/rates/collision_rates.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;
using std::numbers::pi;

namespace {

// v1 Eqs. (A3), (A4) with B_n as printed: (Aκ)^(n/2) (2V)^(n/20) ((20+n)n/800) Γ(n/20).
double h(int n) { return n >= 1 && n <= 9 ? model::viscoelastic_h[n - 1] : 0.0; }
double An(int n) {
  double a = 4 * h(n);
  for (int j = 1; j < n; ++j) a += h(j) * h(n - j);
  return a;
}
double Bn(int n, double ak, double V) {
  return std::pow(ak, n / 2.0) * std::pow(2 * V, n / 20.0) * ((20.0 + n) * n / 800.0) * std::tgamma(n / 20.0);
}
double A3(double ni, double s, double Tk, double Ti, double mk, double mi, double ak) {
  const double V = (Tk * mi + Ti * mk) / (mi * mk);
  double sum = 0;
  for (int n = 1; n <= 18; ++n) sum += An(n) * Bn(n, ak, V);
  return 8 * std::sqrt(2 * pi) / 3 * ni * s * s * mi * (Tk * mi + Ti * mk) / (Tk * (mi + mk) * (mi + mk)) * std::sqrt(V) *
         (1 + 0.5 * sum);
}
double A4(double ni, double s, double Tk, double Ti, double mk, double mi, double ak) {
  const double V = (Tk * mi + Ti * mk) / (mi * mk);
  const double X = (Tk * mi + Ti * mk) / (Tk * (mi + mk));
  double sum = 0;
  for (int n = 1; n <= 18; ++n) sum += Bn(n, ak, V) * (h(n) - 0.5 * X * An(n));
  return 16.0 / 3 * std::sqrt(2 * pi) * ni * s * s * std::sqrt(V) * (mi / (mi + mk)) * (1 - X + sum);
}

}  // namespace

TEST_CASE("constant eps: rates equal v1 (A1) - (A2) as printed - any temperatures and masses", "[theory]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const double m2 = std::pow(10.0, 4 * u(rng) - 2), s2 = 0.2 + 5 * u(rng), e = u(rng);
    const model::Mixture mix({{1, 1, 0.1}, {m2, s2, 0.05 + u(rng)}});
    const double c12 = 1.0 + u(rng);  // χ values of a dense gas: the test is about where χ enters
    const std::vector<std::vector<double>> chi = {{1.0 + u(rng), c12}, {c12, 1.0 + u(rng)}};
    const CollisionRates r(mix, model::Restitution::constant(2, e), chi);
    const double T[2] = {0.1 + u(rng), std::pow(10.0, 4 * u(rng) - 2)};
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 2; ++i) {
        // Same formula rearranged: rounding only (1e-13 relative).
        const double n_i = mix[i].density, s = mix.sigma(k, i), mk = mix[k].mass, mi = mix[i].mass;
        CHECK(r.xi(k, i, T[k], T[i]) == Approx(test::printed_A2(n_i, s, chi[k][i], T[k], T[i], mk, mi, e)).epsilon(1e-13).margin(1e-300));
        CHECK(r.inv_tau_v(k, i, T[k], T[i]) == Approx(test::printed_A1(n_i, s, chi[k][i], T[k], T[i], mk, mi, e)).epsilon(1e-13));
      }
  }
}

TEST_CASE("one species: zeta - tau_v and tau0/tau_v(0) = (1+eps)/(1-eps)", "[theory]") {
  for (double e : {0.1, 0.5, 0.9, 0.99}) {
    const double n = 0.1, s = 1.3, m = 2.0, T = 0.7;
    const CollisionRates r(model::Mixture({{m, s, n}}), model::Restitution::constant(1, e), model::dilute_contact_values(1));
    // docs/physics.md §2, §3 closed forms: rounding only.
    CHECK(r.xi(0, 0, T, T) == Approx(4.0 / 3 * std::sqrt(pi) * (1 - e * e) * n * s * s * std::sqrt(T / m)).epsilon(1e-14));
    CHECK(r.inv_tau_v(0, 0, T, T) == Approx(2 * std::sqrt(pi) / 3 * (1 + e) * (1 + e) * n * s * s * std::sqrt(T / m)).epsilon(1e-14));
    const SettledDiffusion d = diffusion_at(r, {1.0});
    CHECK(d.tau0 == Approx(3 * std::sqrt(m) / (2 * std::sqrt(pi) * (1 - e * e) * n * s * s)).epsilon(1e-14));
    CHECK(d.tau0 / d.tau_v[0] == Approx((1 + e) / (1 - e)).epsilon(1e-14));
  }
}

TEST_CASE("elastic one species: D = 3/(8 n sigma^2) sqrt(T/(pi m))", "[theory]") {
  const double n = 0.2, s = 0.9, m = 3, T = 2;
  const CollisionRates r(model::Mixture({{m, s, n}}), model::Restitution::constant(1, 1.0), model::dilute_contact_values(1));
  CHECK(diffusion_at(r, {T}).D[0] == Approx(3 / (8 * n * s * s) * std::sqrt(T / (pi * m))).epsilon(1e-14));
  CHECK(r.xi(0, 0, T, T) == 0.0);
}

TEST_CASE("viscoelastic series: rates equal v1 (A3) - (A4) as printed", "[theory]") {
  const model::Mixture mix({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}});
  const CollisionRates r(mix, model::Restitution::viscoelastic(mix, 0.09, model::ViscoelasticForm::series),
                         model::dilute_contact_values(2), MomentMethod::series);
  for (double T1 : {1.0, 1e-3, 1e-9})
    for (double ratio : {0.3, 1.0, 40.0}) {
      const double T[2] = {T1, T1 * ratio};
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i) {
          const double ak = r.law().akappa(k, i), n_i = mix[i].density, s = mix.sigma(k, i);
          // Γ(2+n/20)/2 vs ((20+n)n/800)Γ(n/20): equal by Γ(x+1) = xΓ(x); rounding only.
          CHECK(r.xi(k, i, T[k], T[i]) == Approx(A4(n_i, s, T[k], T[i], mix[k].mass, mix[i].mass, ak)).epsilon(1e-12).margin(1e-300));
          CHECK(r.inv_tau_v(k, i, T[k], T[i]) == Approx(A3(n_i, s, T[k], T[i], mix[k].mass, mix[i].mass, ak)).epsilon(1e-12));
        }
    }
}

TEST_CASE("series moments equal the quadrature of the series restitution", "[theory]") {
  // Both are the moments of the same truncated ε(y): the difference is the quadrature error (1e-12 asked).
  for (double a : {0.01, 0.1, 0.3, 0.6}) {
    const CollisionMoments s = series_moments(a), q = quadrature_moments(a, model::ViscoelasticForm::series);
    CHECK(q.W2 == Approx(s.W2).epsilon(1e-11));
    CHECK(q.D == Approx(s.D).epsilon(1e-10));  // D ~ y² is small: the same absolute error weighs more
  }
}

TEST_CASE("viscoelastic: series and exact-quadrature rates agree where the series converges", "[theory]") {
  // a = (Aκ^(2/5))^(1/2)(2V)^(1/20) is the thermal y; the moments sample y up to about 1.1 a.
  // The series error grows like the first uncertain term, h_5 y^5: below a = 0.1 that is < 1e-5.
  double part = 0.0;
  for (double a = 0.005; a < 1.0; a *= 1.05) {
    const CollisionMoments s = series_moments(a), e = quadrature_moments(a, model::ViscoelasticForm::exact);
    const double rel = std::abs(s.D - e.D) / e.D;
    if (a < 0.1) CHECK(rel < 1e-3);  // first uncertain term h_5 y^5 against the leading 2|h_2| y²
    if (part == 0.0 && rel > 1e-2) part = a;
  }
  std::printf("series vs exact ε: the energy-loss moment ⟨1−ε²⟩ differs by 1%% at a = %.3f\n", part);
  CHECK(part > 0.1);
}

TEST_CASE("50 species: the pass over pairs equals the printed (A1) - (A2) summed per species", "[theory]") {
  // The all-pairs pass computes the rates in a factored form from per-species arrays (no pair
  // table); here against a literal per-species sum of the printed formulas, for the three
  // branches of the pass: one ε and χ = 1, Enskog χ (a row of χ per species), per-pair ε.
  // Bound: rounding only (≈ 50 terms of ≤ 1e-15 each, and at most 1e-13 of cancellation in ξ
  // relative to its largest term, which is why ξ is compared against the sum of |terms|).
  const std::size_t N = 50;
  const model::Mixture mix = test::power_law(N);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<std::vector<double>> eps(N, std::vector<double>(N));
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t i = k; i < N; ++i) eps[k][i] = eps[i][k] = 0.3 + 0.7 * u(rng);
  std::vector<double> T(N);
  for (double& t : T) t = std::exp(4 * u(rng) - 2);
  struct Case {
    const char* name;
    model::Restitution law;
    std::vector<std::vector<double>> chi;
  };
  const std::vector<Case> cases = {{"one eps, chi = 1", model::Restitution::constant(N, 0.6), model::dilute_contact_values(N)},
                                   {"one eps, Enskog chi", model::Restitution::constant(N, 0.6),
                                    model::enskog_contact_values(model::with_reduced_density(mix, 0.2))},
                                   {"per-pair eps", model::Restitution::constant_matrix(eps), model::dilute_contact_values(N)}};
  for (const Case& c : cases) {
    INFO(c.name);
    const CollisionRates r(mix, c.law, c.chi);
    std::vector<double> xi(N), tau(N), xi_only(N), tau_only(N);
    r.xi_and_inv_tau_v_all(T.data(), xi.data(), tau.data());
    r.xi_all(T.data(), xi_only.data());
    r.inv_tau_v_all(T.data(), tau_only.data());
    for (std::size_t k = 0; k < N; ++k) {
      double xi_ref = 0, xi_abs = 0, tau_ref = 0;
      for (std::size_t i = 0; i < N; ++i) {
        const double e = c.law.eps(k, i), s = mix.sigma(k, i);
        const double a2 = test::printed_A2(mix[i].density, s, c.chi[k][i], T[k], T[i], mix[k].mass, mix[i].mass, e);
        xi_ref += a2, xi_abs += std::abs(a2);
        tau_ref += test::printed_A1(mix[i].density, s, c.chi[k][i], T[k], T[i], mix[k].mass, mix[i].mass, e);
      }
      CHECK(std::abs(xi[k] - xi_ref) <= 1e-13 * xi_abs);
      CHECK(tau[k] == Approx(tau_ref).epsilon(1e-13));
      // One pass for both, either alone, and the single-species sums: the same numbers.
      CHECK(xi_only[k] == xi[k]);
      CHECK(tau_only[k] == tau[k]);
      CHECK(r.xi_species(k, T.data()) == xi[k]);
      CHECK(r.inv_tau_v_species(k, T.data()) == tau[k]);
    }
  }
}

TEST_CASE("50 species at eps = 1 and equal temperatures: every xi_k is exactly 0", "[theory]") {
  // ξ_k = c (D S_k − W2 U_k/T_k) with D = 0 and U_k a sum of terms ∝ (T_i − T_k) = 0: no rounding
  // residue, which at t = 1e12 would become a drift of ln T.
  const std::size_t N = 50;
  const CollisionRates r(test::power_law(N), model::Restitution::constant(N, 1.0),
                         model::enskog_contact_values(model::with_reduced_density(test::power_law(N), 0.2)));
  std::vector<double> T(N, 0.37), xi(N, 1.0);
  r.xi_all(T.data(), xi.data());
  for (std::size_t k = 0; k < N; ++k) CHECK(xi[k] == 0.0);
}

TEST_CASE("the rates refuse an asymmetric chi, naming it", "[theory]") {
  const model::Mixture mix({{1, 1, 0.1}, {2, 1.2, 0.1}});
  CHECK_THROWS_WITH(CollisionRates(mix, model::Restitution::constant(2, 0.5), {{1.0, 1.1}, {1.2, 1.0}}),
                    Catch::Contains("χ must be symmetric"));
}
