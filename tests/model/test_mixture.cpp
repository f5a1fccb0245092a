// Mixtures, power-law generator and Enskog contact values.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"

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
