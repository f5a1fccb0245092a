// The kinetic level's temperatures at Sonine order 3 (sonine_moment_cooling.hpp, the H(p; source) table of
// scripts/derive_sonine_moments.py): the table against a quadrature written here from the definition,
// order 2 against MG's first Sonine (SonineCooling), the one-species fixed point of order 3 against the
// second-Sonine HCS of Brilliantov & Pöschel (sonine_second_order.hpp: another derivation, other variables), and
// the order-3 HCS of mixtures (sonine_hcs) against the long-time state of the order-3 temperature ODE.
#include <catch2/catch.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "model/enskog.hpp"
#include "model/mixture.hpp"
#include "model/mixture_generators.hpp"
#include "model/restitution.hpp"
#include "theory/rates/collision_rates.hpp"
#include "theory/sonine/sonine_cooling.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_moment_cooling.hpp"
#include "theory/sonine/sonine_moment_table.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"
#include "theory/sonine/sonine_second_order.hpp"
#include "theory/histories/temperature_history.hpp"
#include "gauss_rules.hpp"
#include "scalar_sonine.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;
using std::numbers::pi;

namespace {

// H(p; source) by quadrature over both Maxwellians and σ̂ in the variables of test_sonine_modes.cpp's C_pq
// quadrature (relative speed Gauss–Laguerre, centre part Gauss–Hermite, σ̂ Gauss–Legendre × trapezoid), the
// partner's velocity v − g ẑ: exact rules for these polynomial integrands (degree ≤ 18 per variable). The sources in
// the table's order: Maxwell, own a₂, a₃, a₄, partner's a₂, a₃, a₄.
constexpr int P = sonine_moment_max, S = sonine_moment_sources;
std::array<double, P * S> quadrature_H(double mu, double eps, double Ak, double Ai) {
  const double V = Ak + Ai, a = Ak / V, sG = std::sqrt(2.0 * Ak * Ai / V), beta = mu * (1 + eps);
  static const test::Rule H = test::hermite(10), L = test::laguerre(14), Q = test::legendre01(12);
  const int nphi = 24;
  std::array<double, P * S> sum{};
  for (std::size_t iu = 0; iu < L.x.size(); ++iu) {
    const double g = std::sqrt(2.0 * V * L.x[iu]), wu = L.w[iu] * std::sqrt(L.x[iu]) / (0.5 * std::sqrt(pi));
    for (std::size_t i = 0; i < H.x.size(); ++i)
      for (std::size_t j = 0; j < H.x.size(); ++j)
        for (std::size_t l = 0; l < H.x.size(); ++l) {
          const double wG = wu * H.w[i] * H.w[j] * H.w[l] / std::pow(pi, 1.5);
          const double v[3] = {sG * H.x[i], sG * H.x[j], sG * H.x[l] + a * g};
          const double c2 = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / (2 * Ak);
          const double ci2 = (v[0] * v[0] + v[1] * v[1] + (v[2] - g) * (v[2] - g)) / (2 * Ai);
          using test::scalar_sonine;
          const double W[S] = {1.0, scalar_sonine(2, c2), scalar_sonine(3, c2), scalar_sonine(4, c2), scalar_sonine(2, ci2), scalar_sonine(3, ci2), scalar_sonine(4, ci2)};
          for (std::size_t t = 0; t < Q.x.size(); ++t) {
            const double ct = Q.x[t], st = std::sqrt(1 - ct * ct), gs = g * ct;
            for (int f = 0; f < nphi; ++f) {
              const double phi = 2 * pi * f / nphi, s[3] = {st * std::cos(phi), st * std::sin(phi), ct};
              double vp2 = 0;
              for (int d = 0; d < 3; ++d) vp2 += std::pow(v[d] - beta * gs * s[d], 2);
              const double cp2 = vp2 / (2 * Ak), weight = wG * Q.w[t] * (2 * pi / nphi) * gs;
              for (int p = 1; p <= P; ++p) {
                const double gain = std::pow(cp2, p) - std::pow(c2, p);
                for (int src = 0; src < S; ++src) sum[(p - 1) * S + src] += weight * W[src] * gain;
              }
            }
          }
        }
  }
  return sum;
}

}  // namespace

TEST_CASE("Sonine moments: the H(p, source) table equals a quadrature over both Maxwellians and sigma, p = 1..4", "[theory]") {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 2; ++trial) {
    const double mu = 0.05 + 0.9 * u(rng), eps = u(rng), Ak = std::pow(10.0, u(rng) - 0.5), Ai = std::pow(10.0, u(rng) - 0.5);
    const std::array<double, P * S> table = sonine_moment_pair(1.0, mu, eps, Ak, Ai), quad = quadrature_H(mu, eps, Ak, Ai);
    for (int e = 0; e < P * S; ++e) {
      INFO("p = " << e / S + 1 << ", source = " << e % S << ", mu = " << mu << ", eps = " << eps << ", Ak = " << Ak << ", Ai = " << Ai);
      // Exact rules: rounding only. A coefficient off by 1% moves an entry by >= 1e-3 of its row's scale.
      CHECK(quad[e] == Approx(table[e]).epsilon(1e-9).margin(1e-11 * std::abs(table[(e / S) * S])));
    }
  }
}

TEST_CASE("Sonine moments: the order-3 table is the full table's entries of p <= 3 and a2, a3, bit for bit, the rest NaN", "[theory]") {
  // The order-3 closure evaluates a table of the rows it carries alone (75 of 176 groups): each entry must be the same
  // terms summed in the same order as in the full table, and the entries order 3 does not carry (⟨c⁸⟩, the a₄
  // sources) NaN, so that a closure reading one would show it.
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const double mu = 0.02 + 0.96 * u(rng), eps = u(rng), Ak = std::pow(10.0, 2 * u(rng) - 1), Ai = std::pow(10.0, 2 * u(rng) - 1);
    const std::array<double, P * S> full = sonine_moment_pair(1.0, mu, eps, Ak, Ai), third = sonine_moment_pair(1.0, mu, eps, Ak, Ai, 3);
    for (int e = 0; e < P * S; ++e) {
      const int p = e / S + 1, source = e % S;  // sources: Maxwell, own a2 a3 a4, partner's a2 a3 a4
      INFO("p = " << p << ", source = " << source);
      if (p <= 3 && source != 3 && source != 6)
        CHECK(third[e] == full[e]);
      else
        CHECK(std::isnan(third[e]));
    }
  }
}

TEST_CASE("Sonine moments: order 2 is MG's first Sonine (SonineCooling, relaxing) to rounding, rates and cumulant equations", "[theory]") {
  // Three species, unequal masses, diameters, densities and a restitution per pair; random temperatures and cumulants.
  // The viscoelastic law takes both closures through the quadrature over the impact speed, by different integrals
  // (the first Sonine's ⟨v²⟩, ⟨v⁴⟩ rates, the moment closure's ⟨c²⟩, ⟨c⁴⟩ ones, sonine_quadrature.hpp).
  const model::Mixture mix({{1.0, 1.0, 0.1}, {7.0, 2.0, 0.05}, {60.0, 3.5, 0.02}});
  const model::Restitution laws[2] = {model::Restitution::constant_matrix({{0.5, 0.7, 0.8}, {0.7, 0.9, 0.6}, {0.8, 0.6, 0.3}}),
                                      model::Restitution::viscoelastic(mix, 0.3, model::ViscoelasticForm::pade)};
  for (const model::Restitution& law : laws) {
    const CollisionRates rates(mix, law, model::dilute_contact_values(3));
    const SonineCooling mg(rates, CumulantMode::relaxing);
    const SonineMomentCooling two(rates, 2);
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 5; ++trial) {
      const double T[3] = {std::pow(10.0, 2 * u(rng) - 1), std::pow(10.0, 2 * u(rng) - 1), std::pow(10.0, 2 * u(rng) - 1)};
      const double c[3] = {0.4 * u(rng) - 0.2, 0.4 * u(rng) - 0.2, 0.4 * u(rng) - 0.2};
      double xi_mg[3], dz_mg[3], xi[3], dz[3];
      mg.rates(T, c, xi_mg, dz_mg);
      two.rates(T, c, xi, dz);
      for (int k = 0; k < 3; ++k) {
        INFO((law.is_viscoelastic() ? "viscoelastic" : "constant") << ", trial " << trial << ", species " << k);
        // Rounding: at constant ε two closed forms, at the viscoelastic law two quadratures on the same u nodes.
        CHECK(xi[k] == Approx(xi_mg[k]).epsilon(1e-11));
        CHECK(dz[k] == Approx(dz_mg[k]).epsilon(1e-10).margin(1e-12 * std::abs(xi_mg[k])));
      }
    }
  }
}

TEST_CASE("Sonine moments: one species at order 3 settles at the second-Sonine HCS of Brilliantov & Poschel (a2, a3)", "[theory]") {
  for (double alpha : {0.3, 0.6, 0.9}) {
    const model::Mixture mix({{1.0, 1.0, 0.1}});
    const model::Restitution law = model::Restitution::constant(1, alpha);
    const CollisionRates rates(mix, law, model::dilute_contact_values(1));
    const double T = 0.37;
    const std::vector<double> z = SonineMomentCooling(rates, 3).steady_state(&T);  // (c, a₃) steady at T
    const SonineHcs hcs = sonine_hcs(mix, law, model::dilute_contact_values(1), false, SonineSolver::automatic, 3);
    const SecondSonine bp = second_sonine_hcs(alpha);
    INFO("alpha = " << alpha << ": a2 " << z[0] / 2 << " vs " << bp.a2 << ", a3 " << z[1] << " vs " << bp.a3);
    // Different derivations of the same linear scheme: equal to rounding. At alpha = 0.6, a2 = 0.0339 and a3 = -0.0047:
    // an error of 1% in any coefficient of either table shows.
    CHECK(z[0] / 2 == Approx(bp.a2).epsilon(1e-9));
    CHECK(z[1] == Approx(bp.a3).epsilon(1e-8));
    CHECK(hcs.c[0] / 2 == Approx(bp.a2).epsilon(1e-9));
    CHECK(hcs.a3[0] == Approx(bp.a3).epsilon(1e-8));
  }
}

TEST_CASE("Sonine HCS at order 3: the long-time state of the order-3 temperature ODE, both root solvers", "[theory]") {
  // Two mixtures where the order-3 correction to the first-Sonine ratios is large enough to resolve: MG's
  // mu = 4, delta = 1/4 binary at alpha = 0.3 (gamma 3.4499 -> 3.4730, +0.67%) and a three-species mixture.
  struct Case {
    model::Mixture mix;
    double alpha;
  };
  const std::vector<Case> cases = {{model::montanero_garzo_binary(4, 0.25, 1, 0), 0.3},
                                   {model::Mixture({{1, 1, 0.1}, {10, std::cbrt(10.0), 0.05}, {50, std::cbrt(50.0), 0.02}}), 0.5}};
  for (const Case& c : cases) {
    const std::size_t N = c.mix.size();
    const auto chi = model::dilute_contact_values(N);
    const model::Restitution law = model::Restitution::constant(N, c.alpha);
    const SonineHcs three = sonine_hcs(c.mix, law, chi, false, SonineSolver::automatic, 3);
    const SonineHcs first = sonine_hcs(c.mix, law, chi);
    const CollisionRates r(c.mix, law, chi);
    TemperatureOptions o;
    auto model = std::make_shared<SonineMomentCooling>(r, 3);
    o.cooling = model;
    const TemperatureHistory h(r, std::vector<double>(N, 1.0), 1e12, o);
    std::vector<double> T(N), z(model->state_size());
    h.temperatures(1e12, T.data());
    h.states(1e12, z.data());
    double ratio_gap = 0.0, a_gap = 0.0, correction = 0.0;
    for (std::size_t k = 1; k < N; ++k) {
      ratio_gap = std::max(ratio_gap, std::abs((T[k] / T[0]) / (three.T[k] / three.T[0]) - 1.0));
      correction = std::max(correction, std::abs((three.T[k] / three.T[0]) / (first.T[k] / first.T[0]) - 1.0));
    }
    for (std::size_t k = 0; k < N; ++k) a_gap = std::max({a_gap, std::abs(z[k] - three.c[k]), std::abs(z[N + k] - three.a3[k])});
    std::printf("order-3 HCS, %zu species: ODE at t = 1e12 against the root: ratios %.1e, a's %.1e; order 3 moves the ratios by %.2e\n", N,
                ratio_gap, a_gap, correction);
    // Exponential settling in ln t: at 1e12 only CVODE's accumulated error (~1e-9) is left.
    CHECK(ratio_gap < 1e-6);
    CHECK(a_gap < 1e-6);
    CHECK(correction > 3e-3);  // the bounds resolve what order 3 changes
    if (N == 2) {  // bracketing in ln gamma against gsl's hybrids
      const SonineHcs multi = sonine_hcs(c.mix, law, chi, false, SonineSolver::multiroot, 3);
      CHECK(multi.gamma() == Approx(three.gamma()).epsilon(1e-10));
    }
  }
}

TEST_CASE("Sonine HCS at order 4: MG binaries against scripts/mg_gamma_sonine_orders.py, and the order-4 ODE settles there", "[theory]") {
  // The script solves the binary HCS at Sonine order K by its own assembly of the rates (sympy's H(p; q, r), the
  // moments' Sonine weights from their definition) and Newton (python3 scripts with hcs_gamma(mu, delta, alpha, 4)):
  // gamma and c_1. Order 4 moves gamma by −0.74% at the first point and c_1 by +32%: a wrong a₄ term
  // (its ⟨c⁸⟩ weights, a source in the wrong slot) moves both by far more than the bounds.
  struct Case {
    double mu, delta, alpha, gamma3, gamma4, c1_4;
  };
  for (const Case& c : {Case{4, 0.25, 0.3, 3.4730407320, 3.4473569551, 0.2507019971}, Case{2, 2, 0.5, 1.3480473310, 1.3465901530, 0.1193073843},
                        Case{0.1, 2, 0.8, 0.4573105873, 0.4574336933, -0.0180996705}}) {
    const model::Mixture mix = model::montanero_garzo_binary(c.mu, c.delta, 1, 0);
    const auto chi = model::dilute_contact_values(2);
    const model::Restitution law = model::Restitution::constant(2, c.alpha);
    const SonineHcs three = sonine_hcs(mix, law, chi, false, SonineSolver::automatic, 3), four = sonine_hcs(mix, law, chi, false, SonineSolver::automatic, 4);
    std::printf("MG mu = %g, delta = %g, alpha = %g: gamma order 3 %.8f, order 4 %.8f (script %.8f), c1 %.6f (script %.6f)\n", c.mu, c.delta, c.alpha,
                three.gamma(), four.gamma(), c.gamma4, four.c[0], c.c1_4);
    CHECK(three.gamma() == Approx(c.gamma3).epsilon(1e-8));
    CHECK(four.gamma() == Approx(c.gamma4).epsilon(1e-8));
    CHECK(four.c[0] == Approx(c.c1_4).epsilon(1e-6));
    REQUIRE(four.a4.size() == 2);
  }
  // The order-4 temperature ODE from equal temperatures settles at that root (the first case).
  const model::Mixture mix = model::montanero_garzo_binary(4, 0.25, 1, 0);
  const auto chi = model::dilute_contact_values(2);
  const model::Restitution law = model::Restitution::constant(2, 0.3);
  const SonineHcs four = sonine_hcs(mix, law, chi, false, SonineSolver::automatic, 4);
  const CollisionRates r(mix, law, chi);
  TemperatureOptions o;
  auto model = std::make_shared<SonineMomentCooling>(r, 4);
  o.cooling = model;
  const TemperatureHistory h(r, {1.0, 1.0}, 1e12, o);
  std::vector<double> T(2), z(model->state_size());
  h.temperatures(1e12, T.data());
  h.states(1e12, z.data());
  REQUIRE(z.size() == 6);
  CHECK((T[0] / T[1]) / four.gamma() == Approx(1.0).epsilon(1e-6));
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(z[k] == Approx(four.c[k]).margin(1e-6));
    CHECK(z[2 + k] == Approx(four.a3[k]).margin(1e-6));
    CHECK(z[4 + k] == Approx(four.a4[k]).margin(1e-6));
  }
}

TEST_CASE("Sonine moments: four pairs per vector give each pair's closed forms bit for bit, and a species' row its pairs'", "[theory]") {
  // SonineMomentCooling assembles a species' pair terms four partners at a time (sonine_moment_pairs4_from, through
  // SoninePairTerms::moments_row); each lane must be the one-pair evaluation's number exactly, at every order, for any
  // count of live lanes, so that the closure's results do not depend on how the partners were grouped.
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(0, 1);
  for (int order : {2, 3, 4}) {
    const std::size_t groups = sonine_moment_beta_polynomials(0.5, order).size();
    for (int trial = 0; trial < 10; ++trial) {
      double w[4], beta[4], Ak[4], Ai[4];
      std::vector<double> polys4(4 * groups);
      for (std::size_t l = 0; l < 4; ++l) {
        w[l] = 0.1 + u(rng), beta[l] = (0.02 + 0.96 * u(rng)) * (1.0 + u(rng));
        Ak[l] = std::pow(10.0, 2 * u(rng) - 1), Ai[l] = std::pow(10.0, 2 * u(rng) - 1);
        const std::vector<double> p = sonine_moment_beta_polynomials(beta[l], order);
        for (std::size_t j = 0; j < groups; ++j) polys4[4 * j + l] = p[j];
      }
      const std::size_t lanes = std::size_t(trial % 4) + 1;
      std::array<SonineMomentRates, 4> four{};
      sonine_moment_pairs4_from(polys4.data(), groups, w, beta, Ak, Ai, order, four.data(), lanes);
      for (std::size_t l = 0; l < lanes; ++l) {
        const SonineMomentRates one = sonine_moment_pair_from(sonine_moment_beta_polynomials(beta[l], order), w[l], beta[l], Ak[l], Ai[l], order);
        INFO("order " << order << ", lane " << l);
        CHECK(std::memcmp(one.data(), four[l].data(), sizeof(one)) == 0);  // bitwise (NaN entries included)
      }
    }
  }
  // A species' row, 7 partners (a block of four and one of three): each its pair's moments().
  const model::Mixture mix = test::power_law(7);
  const std::size_t N = mix.size();
  const model::Restitution law = model::Restitution::constant(N, 0.7);
  const std::shared_ptr<const SoninePairTerms> terms = make_sonine_pair_terms(law);
  std::vector<double> m(N), T(N), weight(N);
  for (std::size_t i = 0; i < N; ++i) m[i] = mix[i].mass, T[i] = 1.0 + 0.3 * double(i), weight[i] = 0.2 + 0.1 * double(i);
  for (int order : {3, 4})
    for (std::size_t k : {std::size_t(0), N - 1}) {
      std::vector<SonineMomentRates> row(N);
      terms->moments_row(k, N, weight.data(), m.data(), T.data(), order, row.data());
      for (std::size_t i = 0; i < N; ++i) {
        const SonineMomentRates one = terms->moments(k, i, weight[i], m[k], m[i], T[k], T[i], order);
        INFO("order " << order << ", k " << k << ", i " << i);
        CHECK(std::memcmp(one.data(), row[i].data(), sizeof(one)) == 0);
      }
    }
}

TEST_CASE("Sonine moments: 43 species' rates the same on one thread and on two (pair terms assembled in parallel)", "[theory]") {
  // SonineMomentCooling assembles its pair terms species by species on OpenMP threads from parallel_moment_species;
  // each species' sums run on one thread in a fixed order, so ζ_k and the a's rates must not depend on the thread
  // count, bitwise (granmix's reproducibility rule). v1 Fig. 8's mixture at order 3.
  const model::Mixture mix = test::power_law(43);
  const std::size_t N = mix.size();
  REQUIRE(N >= parallel_moment_species);
  const CollisionRates r(mix, model::Restitution::constant(N, 0.5), model::dilute_contact_values(N));
  std::vector<double> T(N), z(2 * N);
  for (std::size_t k = 0; k < N; ++k) T[k] = 1.0 + 0.05 * double(k), z[k] = 0.1 - 0.003 * double(k), z[N + k] = -0.01 + 0.0005 * double(k);
  auto run = [&] {
    const SonineMomentCooling model(r, 3);
    std::vector<double> out(3 * N);
    model.rates(T.data(), z.data(), out.data(), out.data() + N);
    return out;
  };
  const std::vector<double> one = test::with_threads(1, run), two = test::with_threads(2, run);
  CHECK(one == two);
  for (double x : one) CHECK(std::isfinite(x));
}
