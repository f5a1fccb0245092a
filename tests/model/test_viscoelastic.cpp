// Viscoelastic restitution ε(y): the exact contact problem against the values of docs/physics.md §5,
// the table against direct solves, and the series and Padé forms against the exact one.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "model/restitution.hpp"
#include "model/viscoelastic.hpp"

using namespace granmix::model;

TEST_CASE("exact contact problem reproduces the published values", "[model]") {
  // docs/physics.md §5 gives six digits; the solver runs at 1e-13, so 1e-6 is the rounding of the list.
  const std::pair<double, double> values[] = {{0.1, 0.988547}, {0.3, 0.902852}, {0.5, 0.760037}, {1.0, 0.393931}, {2.0, 0.093000}};
  for (auto [y, eps] : values) {
    INFO("y = " << y);
    CHECK(std::abs(restitution_contact_solve(y) - eps) <= 0.6e-6);
  }
}

TEST_CASE("(1-eps)/b tends to 1.153448 as b -> 0", "[model]") {
  // (1−ε)/b = 1.153448 − 0.79826 b − h_5 y³ + …  At y = 0.01 the y³ term is 2.7e-7, the rounding of
  // 1.153448 is 5e-7 and the solver's absolute 1e-13 on ε is 1e-9 after division by b: bound 1e-6.
  // (Smaller y does not help: 1 − ε itself falls to the solver's absolute error.)
  const double y = 0.01, b = y * y;
  CHECK(std::abs((1.0 - restitution_contact_solve(y)) / b - (1.153448 - 0.79826 * b)) <= 1e-6);
}

TEST_CASE("exact table matches direct solves to 1e-9", "[model]") {
  double worst = 0.0;
  for (double y = 0.0007; y < viscoelastic_table_y_max; y *= 1.093) {
    worst = std::max(worst, std::abs(restitution_exact(y) - restitution_contact_solve(y)));
  }
  std::printf("viscoelastic table: max |table - direct| = %.3g over [0.0007, 16]\n", worst);
  CHECK(worst <= 1e-9);  // measured about 1e-11
  CHECK(restitution_exact(0.0) == Approx(1.0).margin(1e-12));
}

TEST_CASE("Padé form within 1e-6 of the exact one for y <= 0.5", "[model]") {
  double worst = 0.0;
  for (double y = 0.0; y <= 0.5; y += 0.005) worst = std::max(worst, std::abs(restitution_pade(y) - restitution_exact(y)));
  std::printf("Padé [3/6]: max |pade - exact| = %.3g for y <= 0.5\n", worst);
  CHECK(worst <= 1e-6);  // the accuracy docs/physics.md states for this Padé
}

TEST_CASE("truncated series: accurate for small y - parts from the exact curve above y ~ 0.5", "[model]") {
  // With h_1..h_9 the truncation error is O(y^10) and the h_5..h_9 uncertainties O(y^5).
  CHECK(std::abs(restitution_series(0.1) - restitution_exact(0.1)) <= 1e-6);
  CHECK(std::abs(restitution_series(0.3) - restitution_exact(0.3)) <= 1e-5);
  // Where it parts: report the first y at which the error exceeds 1e-3.
  double y = 0.0;
  while (std::abs(restitution_series(y) - restitution_exact(y)) < 1e-3) y += 0.001;
  std::printf("series vs exact: |difference| reaches 1e-3 at y = %.3f\n", y);
  CHECK(y > 0.4);
  CHECK(y < 0.8);
  CHECK(std::abs(restitution_series(1.0) - restitution_exact(1.0)) > 0.1);  // diverged
}

TEST_CASE("exact table refuses impacts beyond its range with a clear error", "[model]") {
  CHECK_THROWS_WITH(restitution_exact(20.0), Catch::Contains("outside the exact table"));
}

TEST_CASE("viscoelastic law scales Akappa^(2/5) per pair with sqrt(sigma_eff)/m_eff", "[model]") {
  const Mixture mix({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}});
  const Restitution r = Restitution::viscoelastic(mix, 0.09, ViscoelasticForm::exact);
  CHECK(r.akappa(0, 0) == Approx(0.09).epsilon(1e-15));
  const double k11 = std::sqrt(0.5) / 0.5;
  const double s = std::cbrt(100.0);
  const double k12 = std::sqrt(s / (1 + s)) / (100.0 / 101.0);
  CHECK(r.akappa(0, 1) == Approx(0.09 * std::pow(k12 / k11, 0.4)).epsilon(1e-14));
  CHECK(r.akappa(1, 0) == r.akappa(0, 1));
  // ε at zero impact speed is 1; at speed u it equals ε(y) with y = sqrt(Aκ^(2/5)) u^(1/10).
  CHECK(r.eps_at(0, 0, 0.0) == Approx(1.0));
  CHECK(r.eps_at(0, 0, 1e4) == Approx(restitution_exact(0.3 * std::pow(1e4, 0.1))).epsilon(1e-14));
}

TEST_CASE("restitution_deficit is 1 - eps, without the cancellation at small y", "[model]") {
  // Where 1 − ε is large, the deficit is 1 − restitution() up to the rounding of that difference.
  for (auto form : {ViscoelasticForm::exact, ViscoelasticForm::series, ViscoelasticForm::pade})
    for (double y = 0.05; y <= 1.0; y += 0.05) {
      INFO(to_string(form) << ", y = " << y);
      CHECK(std::abs(restitution_deficit(form, y) - (1.0 - restitution(form, y))) <= 4e-16);
    }
  // At y = 1e-6, 1 − ε = 1.15e-12 and 1 − restitution() keeps 4 digits; the deficit keeps them all:
  // series −h₂y² − h₄y⁴ (next term h₅y⁵, relative 2e-25), Padé (1.72765 − 0.574198) y² (1 + O(y)).
  const double y = 1e-6;
  CHECK(std::abs(restitution_deficit(ViscoelasticForm::series, y) / (1.15344 * y * y - 0.79826 * y * y * y * y) - 1) <= 1e-15);
  CHECK(std::abs(restitution_deficit(ViscoelasticForm::pade, y) / ((1.72765 - 0.574198) * y * y) - 1) <= 3 * y);
}
