// Mixtures, power-law generator and Enskog contact values.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "model/scene.hpp"

using namespace granmix::model;

TEST_CASE("pair quantities of a mixture", "[model]") {
  const Mixture mix({{1, 1, 0.1}, {100, 4, 0.3}});
  CHECK(mix.sigma(0, 1) == 2.5);
  CHECK(mix.reduced_mass(0, 1) == Approx(100.0 / 101.0).epsilon(1e-15));
  CHECK(mix.effective_diameter(0, 1) == Approx(0.8).epsilon(1e-15));
  CHECK(mix.total_density() == Approx(0.4));
  CHECK(mix.mean_temperature({1.0, 3.0}) == Approx((0.1 + 0.9) / 0.4));
  CHECK_THROWS_AS(Mixture({{-1, 1, 1}}), std::invalid_argument);
  CHECK_THROWS_AS(Mixture({}), std::invalid_argument);
}

TEST_CASE("power law: n_k = n1 k^-theta - m_k = k - sigma_k = k^(1/3) - cut at one particle", "[model]") {
  PowerLaw p;
  p.n1 = 0.1, p.theta = 3, p.n1_particles = 1e6;
  const Mixture mix = power_law_mixture(p);
  CHECK(mix.size() == 100);  // 1e6 k^-3 >= 1 up to k = 100 exactly
  CHECK(mix[99].mass == 100.0);
  CHECK(mix[99].density == Approx(0.1e-6).epsilon(1e-12));
  CHECK(mix[7].diameter == Approx(2.0).epsilon(1e-15));
  p.diameter_exponent = 0.0;
  p.max_species = 10;
  const Mixture equal = power_law_mixture(p);
  CHECK(equal.size() == 10);
  CHECK(equal[9].diameter == 1.0);
}

TEST_CASE("Enskog contact value of one species is Carnahan-Starling", "[model]") {
  // MG Eq. (26) reduces to (1 − ν/2)/(1 − ν)³ for one species: algebra, so rounding only.
  for (double n : {0.01, 0.3, 0.9}) {  // ν up to 0.47: inside the fluid range
    const Mixture mix({{1, 1, n}});
    const double nu = std::numbers::pi / 6 * n;
    CHECK(enskog_contact_values(mix)[0][0] == Approx((1 - nu / 2) / std::pow(1 - nu, 3)).epsilon(1e-14));
  }
  const Mixture dilute({{1, 1, 1e-12}, {2, 3, 1e-12}});
  const auto chi = enskog_contact_values(dilute);
  CHECK(chi[0][1] == Approx(1.0).epsilon(1e-10));
  CHECK(chi[0][1] == chi[1][0]);
  CHECK_THROWS_WITH(enskog_contact_values(Mixture({{1, 1, 1.0}})), Catch::Contains("fluid range"));  // ν = 0.52
}

TEST_CASE("Montanero-Garzo binary parameters", "[model]") {
  const Mixture mix = montanero_garzo_binary(10, 2, 2, 0.1);
  CHECK(mix[0].mass / mix[1].mass == Approx(10));
  CHECK(mix[0].density / mix[1].density == Approx(2));
  CHECK(mix[0].diameter / mix[1].diameter == Approx(2));
  CHECK(mix.total_density() * std::pow(mix.sigma(0, 1), 3) == Approx(0.1).epsilon(1e-14));
}

TEST_CASE("exponential mixture of v2 Fig. 6: 691 species - counts floor(999 e^-0.01(k-1)) - n = 0.1", "[model]") {
  const Mixture mix = exponential_mixture(Exponential{});
  REQUIRE(mix.size() == 691);
  double N = 0.0;  // the paper's count, summed here independently of the generator
  for (int k = 1; k <= 691; ++k) N += std::floor(999.0 * std::exp(-0.01 * (k - 1)));
  CHECK(N == 99966.0);
  CHECK(mix.total_density() == Approx(0.1).epsilon(1e-14));
  for (int k : {1, 2, 100, 691}) {
    CHECK(mix[k - 1].mass == Approx(k));
    CHECK(mix[k - 1].diameter == Approx(std::cbrt(double(k))).epsilon(1e-14));
    // n_k / n = N_k / N: the particle count a DSMC of N particles gives species k.
    CHECK(mix[k - 1].density / 0.1 * N == Approx(std::floor(999.0 * std::exp(-0.01 * (k - 1)))).epsilon(1e-12));
  }
  // Counts that floor to zero end the list: N1 = 5, decay 1 keeps 5, 1 (e^-1 5 = 1.84), then 0.
  CHECK(exponential_mixture(Exponential{5, 1.0, 10, 0.1}).size() == 2);
}

TEST_CASE("sweep point along n*: n sigma12^3 = n* - Enskog on - ratios kept - n* = 0 is the dilute gas", "[model]") {
  Scene s;
  s.mixture = montanero_garzo_binary(2, 0.5, 2, 0);
  s.restitution = Restitution::constant(2, 0.6);
  s.theory.sweep = Sweep{Sweep::Parameter::n_star, 0, {0.0, 0.3}};
  const Scene p = sweep_point(s, 0.3), q = sweep_point(s, 0.0);
  CHECK(p.enskog);
  CHECK(!q.enskog);
  CHECK(!p.theory.sweep);
  CHECK(p.mixture.total_density() * std::pow(p.mixture.sigma(0, 1), 3) == Approx(0.3).epsilon(1e-14));
  CHECK(p.mixture[0].density / p.mixture[1].density == Approx(0.5).epsilon(1e-14));
  CHECK(q.mixture.total_density() == s.mixture.total_density());
}
