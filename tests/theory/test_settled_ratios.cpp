// Settled (HCS) temperature ratios: residual ≤ 1e-12 for 2, 3, 4 and 200 species, agreement with
// the long-time solution of the temperature ODE, and the case that defeats a plain Newton solver.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "theory/rates/diffusion.hpp"
#include "theory/histories/initial_state.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/histories/temperature_history.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;

namespace {

double worst_relative_residual(const CollisionRates& r, const std::vector<double>& T) {
  std::vector<double> xi(T.size());
  r.xi_all(T.data(), xi.data());
  double worst = 0.0;
  for (std::size_t k = 1; k < T.size(); ++k) worst = std::max(worst, std::abs(xi[k] - xi[0]) / xi[0]);
  return worst;
}

void check_settled(const CollisionRates& r, const char* name, double ode_tol) {
  const SettledState s = settled_temperatures(r);
  const double res = worst_relative_residual(r, s.T);
  std::printf("%s: max |xi_k - xi_1|/xi_1 = %.2e, T_N/T_1 = %.6g\n", name, res, s.T.back() / s.T[0]);
  CHECK(res <= 1e-12);
  CHECK(r.mixture().mean_temperature(s.T) == Approx(1.0).epsilon(1e-14));
  // The temperature ODE from equal temperatures reaches the same ratios (its own tolerance 1e-11
  // per step, and the remaining transient at t = 1e12; see ode_tol per case).
  const TemperatureHistory h(r, std::vector<double>(r.size(), 1.0), 1e12);
  std::vector<double> T(r.size());
  h.temperatures(1e12, T.data());
  double worst = 0.0;
  for (std::size_t k = 1; k < T.size(); ++k) worst = std::max(worst, std::abs((T[k] / T[0]) / (s.T[k] / s.T[0]) - 1));
  std::printf("%s: ODE at t = 1e12 vs settled ratios: %.2e\n", name, worst);
  CHECK(worst <= ode_tol);
}

}  // namespace

TEST_CASE("settled ratios: binary that defeats a plain Newton solver", "[theory]") {
  check_settled(test::constant_rates({{1, 1, 0.1}, {100, 1, 0.1}}, 0.5), "m=1,100 sigma=1,1", 1e-8);
}

TEST_CASE("settled ratios: binary - ternary and 4-species mixtures of v1", "[theory]") {
  check_settled(test::constant_rates(test::bo_binary(), 0.5), "v1 Fig. 2 binary", 1e-8);
  check_settled(test::constant_rates(test::bo_ternary(), 0.5), "v1 Fig. 6 ternary", 1e-8);
  check_settled(test::constant_rates(test::bo_four(), 0.3), "v1 Fig. 7 four species", 1e-8);
}

TEST_CASE("settled ratios: 200-species power law", "[theory]") {
  const model::Mixture mix = test::power_law(200);
  const CollisionRates r(mix, model::Restitution::constant(200, 0.5), model::dilute_contact_values(200));
  // Large particles relax slowly (v1 Fig. 8 text): the ODE is still settling at t = 1e12.
  check_settled(r, "200-species power law", 1e-4);
}

TEST_CASE("swapping the species inverts the ratio", "[theory]") {
  const auto a = settled_ratios(test::constant_rates(test::bo_binary(), 0.3));
  auto swapped = test::bo_binary();
  std::swap(swapped[0], swapped[1]);
  const auto b = settled_ratios(test::constant_rates(swapped, 0.3));
  CHECK(b[1] == Approx(1.0 / a[1]).epsilon(1e-13));  // both roots converge to rounding
}

TEST_CASE("equal species give equal temperatures - eps = 1 gives equipartition", "[theory]") {
  const auto r = settled_ratios(test::constant_rates({{2, 1, 0.1}, {2, 1, 0.3}, {2, 1, 0.05}}, 0.4));
  CHECK(r[1] == Approx(1.0).epsilon(1e-13));
  CHECK(r[2] == Approx(1.0).epsilon(1e-13));
  const auto e = settled_ratios(test::constant_rates(test::bo_ternary(), 1.0));
  CHECK(e[1] == Approx(1.0).epsilon(1e-12));
  CHECK(e[2] == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("aged start: <T> = 1 and the ratio approaches the settled one as T_hot grows", "[theory]") {
  const CollisionRates r = test::constant_rates({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.001}}, 0.5);  // v1 Fig. 3
  const double settled = settled_ratios(r)[1];
  double previous_gap = settled - 1.0;  // equal start
  for (double hot : {1e2, 1e4, 1e8, 1e12}) {
    model::InitialState aged;
    aged.kind = model::InitialState::Kind::aged;
    aged.T_hot = hot;
    const std::vector<double> T = initial_temperatures(aged, r);
    CHECK(r.mixture().mean_temperature(T) == Approx(1.0).epsilon(1e-14));  // normalised after the root
    // The heavy intruder relaxes slowly (rate ~ (m1/m2) ν): after cooling by 1e4 the ratio is still
    // ~10% short (v1 Fig. 3: T1 != T2 at the start of the dashed curves). It must close in monotonically.
    const double gap = settled - T[1] / T[0];
    std::printf("aged from T_hot = %.0e: T2/T1 = %.6g (settled %.6g)\n", hot, T[1] / T[0], settled);
    CHECK(gap > 0.0);
    CHECK(gap < previous_gap);
    previous_gap = gap;
  }
  CHECK(previous_gap / settled < 1e-3);  // cooled by 1e12: settled to 0.1%
}

TEST_CASE("settled D ratio along the density of the heavy species (v1 Fig. 4)", "[theory]") {
  // v1 text: towards the intruder limit D2/D1 becomes several times larger; for one material it
  // barely depends on n2.
  auto ratio = [](double sigma2, double n2) {
    return settled_diffusion(test::constant_rates({{1, 1, 0.1}, {100, sigma2, n2}}, 0.5)).D_ratio[1];
  };
  CHECK(ratio(1.0, 1e-4) > 3.0 * ratio(1.0, 0.1));
  CHECK(ratio(1.0, 1e-4) > 1.0);
  const double s = std::cbrt(100.0);
  CHECK(ratio(s, 1e-4) / ratio(s, 0.1) < ratio(1.0, 1e-4) / ratio(1.0, 0.1));
}
