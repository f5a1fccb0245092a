// Garzó–Dufty first-Sonine HCS (MG App. A): exact limits, agreement with v1 (A2) at the
// Maxwellian level, symmetry, the published MG Fig. 1 value, the N-species generalisation, the
// distribution functions, and the hard parameter ranges.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "model/enskog.hpp"
#include "model/errors.hpp"
#include "model/mixture_generators.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/sonine/sonine_hcs.hpp"

using namespace granmix;
using namespace granmix::theory;

namespace {
SonineHcs mg(double mu, double delta, double w, double alpha, double nstar = 0.0, bool maxwell = false) {
  const model::Mixture mix = model::montanero_garzo_binary(mu, delta, w, nstar);
  const auto chi = nstar > 0 ? model::enskog_contact_values(mix) : model::dilute_contact_values(2);
  return sonine_hcs(mix, model::Restitution::constant(2, alpha), chi, maxwell);
}
}  // namespace

TEST_CASE("one species: c = 32(1-a)(1-2a^2)/(81 - 17a + 30a^2(1-a)) from alpha = 0.05 to 1", "[theory]") {
  for (int step = 1; step <= 20; ++step) {
    const double a = 0.05 * step;
    const SonineHcs s = sonine_hcs(model::Mixture({{1, 1, 0.1}}), model::Restitution::constant(1, a), model::dilute_contact_values(1));
    const double c = 32 * (1 - a) * (1 - 2 * a * a) / (81 - 17 * a + 30 * a * a * (1 - a));
    CHECK(s.c[0] == Approx(c).margin(1e-12));  // a 1×1 linear solve: rounding only
    // A species split in two halves (MG's "mechanically equivalent particles"): γ = 1, same c.
    const SonineHcs two = mg(1, 1, 1, a);
    CHECK(two.gamma() == Approx(1.0).epsilon(1e-12));
    CHECK(two.c[1] == Approx(c).margin(1e-12));
  }
  const SonineHcs elastic = mg(3, 2, 1.5, 1.0);
  CHECK(elastic.gamma() == Approx(1.0).epsilon(1e-12));  // α = 1: equipartition and a Maxwellian
  CHECK(elastic.c[0] == Approx(0.0).margin(1e-13));
  // Four species (v1 Fig. 7's mixture at ε = 1), orders 2 and 3: every ζ_k is 0, so a root finder's relative ζ
  // differences are 0/0 (GSL's hybrids throws); equal temperatures are the exact answer, and with them the cumulant
  // equations must give a Maxwellian.
  const model::Mixture four({{1, 1, 0.1}, {2, std::cbrt(2.0), 0.1}, {3, std::cbrt(3.0), 0.1}, {4, std::cbrt(4.0), 0.1}});
  for (int order : {2, 3}) {
    const SonineHcs s = sonine_hcs(four, model::Restitution::constant(4, 1.0), model::dilute_contact_values(4), false, SonineSolver::automatic, order);
    for (std::size_t k = 0; k < 4; ++k) {
      CHECK(s.T[k] == 1.0);
      CHECK(s.c[k] == Approx(0.0).margin(1e-13));
      if (order == 3) CHECK(s.a3[k] == Approx(0.0).margin(1e-13));
    }
  }
}

TEST_CASE("Maxwellian level (c = 0) equals the settled ratio of v1 (A2) for 20 random binaries", "[theory]") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0, 1);
  for (int trial = 0; trial < 20; ++trial) {
    const double mu = std::pow(10.0, 4 * u(rng) - 2), delta = std::pow(10.0, 2 * u(rng) - 1), w = 0.3 + 3 * u(rng);
    const double alpha = 0.05 + 0.95 * u(rng), nstar = trial % 2 ? 0.3 * u(rng) : 0.0;
    const model::Mixture mix = model::montanero_garzo_binary(mu, delta, w, nstar);
    const auto chi = nstar > 0 ? model::enskog_contact_values(mix) : model::dilute_contact_values(2);
    const SonineHcs s = sonine_hcs(mix, model::Restitution::constant(2, alpha), chi, true);
    const double v1 = settled_ratios(CollisionRates(mix, model::Restitution::constant(2, alpha), chi))[1];
    INFO("mu " << mu << " delta " << delta << " w " << w << " alpha " << alpha << " n* " << nstar);
    // MG Eq. (39) and v1 Eq. (A2) are the same function (docs/physics.md §6); both roots converge to
    // rounding, so the bound 1e-10 has room.
    CHECK(s.T[1] / s.T[0] == Approx(v1).epsilon(1e-10));
  }
}

TEST_CASE("swapping the species gives 1/gamma and swapped cumulants", "[theory]") {
  const SonineHcs a = mg(4, 0.5, 2, 0.6), b = mg(0.25, 2, 0.5, 0.6);
  CHECK(b.gamma() == Approx(1.0 / a.gamma()).epsilon(1e-10));
  CHECK(b.c[0] == Approx(a.c[1]).epsilon(1e-9));
  CHECK(b.c[1] == Approx(a.c[0]).epsilon(1e-9));
}

TEST_CASE("MG Fig. 1: mu = 10 - delta = 2 - w = 1 - alpha = 0.5 gives gamma close to 3.8", "[theory]") {
  const SonineHcs s = mg(10, 2, 1, 0.5);
  std::printf("MG Fig. 1: gamma = %.6f (Sonine), %.6f (Maxwellian); c1 = %.5f, c2 = %.5f, zeta* = %.5f\n", s.gamma(),
              mg(10, 2, 1, 0.5, 0, true).gamma(), s.c[0], s.c[1], s.zeta_star);
  CHECK(s.gamma() == Approx(3.8).margin(0.05));  // published "γ ≃ 3.8": two digits
}

TEST_CASE("N-species solver at N = 2 equals the binary bracketing solver", "[theory]") {
  for (double alpha : {0.2, 0.5, 0.9}) {
    const model::Mixture mix = model::montanero_garzo_binary(4, 0.5, 2, 0.2);
    const auto chi = model::enskog_contact_values(mix);
    const SonineHcs b = sonine_hcs(mix, model::Restitution::constant(2, alpha), chi);
    const SonineHcs m = sonine_hcs(mix, model::Restitution::constant(2, alpha), chi, false, SonineSolver::multiroot);
    CHECK(m.gamma() == Approx(b.gamma()).epsilon(1e-10));  // two root finders on one function, both to rounding
    CHECK(m.c[0] == Approx(b.c[0]).epsilon(1e-9));
    CHECK(m.c[1] == Approx(b.c[1]).epsilon(1e-9));
  }
}

TEST_CASE("N-species solver: a binary with one species split in two reproduces the binary", "[theory]") {
  const model::Mixture two({{4, 1.3, 0.02}, {1, 1, 0.04}});
  const model::Mixture three({{4, 1.3, 0.02}, {1, 1, 0.01}, {1, 1, 0.03}});
  const SonineHcs b = sonine_hcs(two, model::Restitution::constant(2, 0.4), model::dilute_contact_values(2));
  const SonineHcs t = sonine_hcs(three, model::Restitution::constant(3, 0.4), model::dilute_contact_values(3));
  // Brent on the binary, gsl_multiroot on three species: both to rounding (residual 1e-14).
  CHECK(t.T[1] / t.T[0] == Approx(b.T[1] / b.T[0]).epsilon(1e-10));
  CHECK(t.T[2] == Approx(t.T[1]).epsilon(1e-12));
  CHECK(t.c[0] == Approx(b.c[0]).epsilon(1e-9));
  CHECK(t.c[2] == Approx(b.c[1]).epsilon(1e-9));
  CHECK(t.zeta_star == Approx(b.zeta_star).epsilon(1e-10));
  const SonineHcs four = sonine_hcs(model::Mixture({{2, 1, 0.1}, {2, 1, 0.2}, {2, 1, 0.05}, {2, 1, 0.15}}),
                                    model::Restitution::constant(4, 0.3), model::dilute_contact_values(4));
  const double c = 32 * 0.7 * (1 - 0.18) / (81 - 17 * 0.3 + 30 * 0.09 * 0.7);
  for (std::size_t k = 0; k < 4; ++k) CHECK(four.c[k] == Approx(c).epsilon(1e-10));  // identical species: one-species limit
}

TEST_CASE("first-Sonine distribution: normalised and <v^4>/<v^2>^2 = (5/3)(1 + c/2)", "[theory]") {
  const SonineHcs s = mg(4, 0.5, 1, 0.5);
  for (std::size_t k = 0; k < 2; ++k) {
    double m0 = 0, m2 = 0, m4 = 0;
    const double h = 1e-3;
    for (double v = 0.5 * h; v < 12.0; v += h) {  // midpoint rule: error O(h²) ~ 1e-7 on smooth Gaussians
      const double w = 4 * std::numbers::pi * v * v * s.phi(k, v) * h;
      m0 += w, m2 += w * v * v, m4 += w * v * v * v * v;
    }
    CHECK(m0 == Approx(1.0).epsilon(1e-6));
    CHECK(m4 / (m2 * m2) == Approx(5.0 / 3.0 * (1 + s.c[k] / 2)).epsilon(1e-6));
    CHECK(s.G(k, 3.0) == Approx(std::exp(s.tail_exponent(k) * 3.0) * s.phi(k, 3.0)).epsilon(1e-14));
  }
}

TEST_CASE("hard cases: mass ratio 1e-3..1e3 - alpha 0.05 - n* to 0.5 - w 0.1..10: root found or a clear error", "[theory][hard]") {
  // Every case inside the fluid range of MG Eq. (26) (packing fraction < 0.5) must be solved; the
  // others must be refused with a message naming the packing-fraction limit.
  int solved = 0, refused = 0;
  for (double mu : {1e-3, 1e-2, 1.0, 1e2, 1e3})
    for (double w : {0.1, 1.0, 10.0})
      for (double nstar : {0.0, 0.5})
        for (double alpha : {0.05, 0.5}) {
          const model::Mixture mix = model::montanero_garzo_binary(mu, 1.0, w, nstar);
          const bool fluid = nstar == 0.0 || model::packing_fraction(mix) < model::max_packing_fraction;
          INFO("mu " << mu << " w " << w << " n* " << nstar << " alpha " << alpha);
          if (fluid) {
            const SonineHcs s = mg(mu, 1.0, w, alpha, nstar);
            CHECK(std::isfinite(s.gamma()));
            CHECK(std::isfinite(s.c[0]));
            CHECK(std::isfinite(s.c[1]));
            CHECK(s.zeta_star > 0);
            ++solved;
          } else {
            CHECK_THROWS_WITH(mg(mu, 1.0, w, alpha, nstar), Catch::Contains("fluid range"));
            ++refused;
          }
        }
  std::printf("hard Sonine grid: %d solved, %d refused (packing fraction >= 0.5)\n", solved, refused);
  CHECK(solved + refused == 60);
}
