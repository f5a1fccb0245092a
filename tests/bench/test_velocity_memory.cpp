// The measurement helpers of `granmix bench gaps` (bench/velocity_memory.hpp, replica_z_null.hpp)
// against exact results: the settled-HCS closed form of the first-Sonine MSD (docs/physics-beyond.md §2),
// the rate a window recovers from exact ⟨v²⟩ and Q, the jackknife of a mean, and Student's t.
#include <catch2/catch.hpp>

#include <cmath>

#include "bench/gaps_parts.hpp"
#include "bench/replica_z_null.hpp"
#include "bench/velocity_memory.hpp"

using namespace granmix::bench;

namespace {

// Settled HCS: T = T0/x², x = 1 + t/τ0, ν = β/(τ0 x) (β = 2ν/ζ). With T0/m = 1, τ0 = 1:
// M = [6/(β−1)] [ln x − (1 − x^(1−β))/(β−1)] and Q = M'/2 = [3/(β−1)] [1 − x^(1−β)]/x.
double M_exact(double beta, double t) {
  const double x = 1.0 + t;
  return 6.0 / (beta - 1.0) * (std::log(x) - (1.0 - std::pow(x, 1.0 - beta)) / (beta - 1.0));
}
double Q_exact(double beta, double t) {
  const double x = 1.0 + t;
  return 3.0 / (beta - 1.0) * (1.0 - std::pow(x, 1.0 - beta)) / x;
}

}  // namespace

TEST_CASE("msd_from_memory reproduces the settled-HCS closed form of the first-Sonine MSD", "[theory]") {
  const std::vector<double> t = log_grid(1e-6, 1e6, 24);  // ν t[0] <= 1.5e-5: the ballistic start is exact enough
  for (double beta : {1.2, 2.0, 15.0}) {
    std::vector<double> v2, nu;
    for (double x : t) v2.push_back(3.0 / ((1 + x) * (1 + x))), nu.push_back(beta / (1 + x));
    const std::vector<double> M = msd_from_memory(t, v2, nu);
    double worst = 0.0;
    // From t = 1e-3: below, the closed form itself loses digits (ln x − (1 − x^(1−β))/(β−1) cancels).
    for (std::size_t j = index_of(t, 1e-3); j < t.size(); ++j) worst = std::max(worst, std::abs(M[j] / M_exact(beta, t[j]) - 1.0));
    INFO("beta " << beta);
    // Power-law interpolation of (1+t)^-2 between grid points is the only approximation (1.8e-4 at
    // t = 1 for β = 1.2, falling 4x per halving of the spacing). Dropping the
    // offset −1/(β−1) (v1 Eq. 21) would change M at t = 10 by 3% (β = 15) to 79% (β = 1.2).
    CHECK(worst < 5e-4);
  }
}

TEST_CASE("effective_rate recovers the rate from exact <v^2> and Q", "[theory]") {
  const std::vector<double> t = log_grid(1.0, 1e4, 8);
  const double beta = 3.7;
  std::vector<double> v2, Q, nuQ;
  for (double x : t) v2.push_back(3.0 / ((1 + x) * (1 + x))), Q.push_back(Q_exact(beta, x)), nuQ.push_back(beta / (1 + x) * Q.back());
  const std::size_t a = index_of(t, 10.0), b = index_of(t, 100.0);
  // ν_eff over the window equals the Q-weighted mean of ν: Simpson error only (about 1e-5 at 8 per decade).
  CHECK(effective_rate(t, v2, Q, a, b) == Approx(integral_log_grid(t, nuQ, a, b) / integral_log_grid(t, Q, a, b)).epsilon(1e-4));
}

TEST_CASE("the jackknife of a mean is its standard error", "[theory]") {
  const std::vector<double> x = {1.0, 3.0, 2.0, 7.0, 4.0};
  const auto jk = jackknife(5, [&](std::size_t e) {
    double s = 0.0, n = 0.0;
    for (std::size_t i = 0; i < 5; ++i)
      if (i != e) s += x[i], n += 1.0;
    return s / n;
  });
  // mean 3.4, sample variance 5.3: standard error √(5.3/5)
  CHECK(jk.first == Approx(3.4));
  CHECK(jk.second == Approx(std::sqrt(5.3 / 5.0)).epsilon(1e-12));
}

TEST_CASE("z_null: Student's t for many particles per replica, a long low tail for one", "[theory]") {
  // n = 300: one replica's estimate is nearly Gaussian, so z follows t with R − 1 = 7 degrees of
  // freedom, 97.5% quantile 2.365 (Monte Carlo error of the quantile with 8000 trials ≈ 0.04).
  const ZNull many = z_null(300, 8, 8000, 7);
  CHECK(many.q975 == Approx(2.365).margin(0.15));
  CHECK(many.q025 == Approx(-2.365).margin(0.15));
  // n = 1 (χ² with 3 degrees of freedom): z below −4 is common, above +4 rare.
  const ZNull one = z_null(1, 8, 8000, 7);
  CHECK(one.q025 < -3.0);
  CHECK(one.q975 < 2.0);
  CHECK(one.p_below4 > 0.01);
  CHECK(one.p_above4 < 0.002);
}
