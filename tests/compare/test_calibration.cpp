// granmix validate --seeds (compare/calibration.hpp, docs/validation.md "Held-out calibration"): the chance a point
// falls outside z·σ, the count a quantity may fail by chance, and the command's files.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "compare/calibration.hpp"
#include "model/errors.hpp"
#include "run_cli.hpp"
#include "toy_scene.hpp"

using namespace granmix;
using namespace granmix::compare;

namespace {

// P(|t_ν| > z) by Simpson's rule on the density of Student's t (an independent evaluation of Boost's cdf).
double student_tail(double nu, double z) {
  const double c = std::tgamma((nu + 1) / 2) / (std::sqrt(nu * M_PI) * std::tgamma(nu / 2));
  auto f = [&](double x) { return c * std::pow(1 + x * x / nu, -(nu + 1) / 2); };
  const int n = 200000;
  const double h = z / n;
  double s = f(0) + f(z);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(i * h);
  return 1.0 - 2.0 * s * h / 3.0;
}

SceneOutcome outcome(std::size_t replicas, std::size_t judged, std::size_t failed) {
  SceneOutcome o;
  o.scene = "toy", o.replicas = replicas;
  QuantityResult q{};
  q.spec.name = "T", q.spec.z = 4.0;
  q.judged = q.points = judged, q.failed = failed;
  for (std::size_t i = 0; i < judged; ++i) q.bound_ratios.push_back(i < failed ? 1.5 : 0.5 * double(i) / double(judged));
  o.quantities.push_back(q);
  return o;
}

SeedRun run(std::uint64_t seed, SceneOutcome o) {
  SeedRun r;
  r.seed = seed, r.scenes = {std::move(o)};
  return r;
}

}  // namespace

TEST_CASE("calibration: a point's chance outside z = 4 is Student's two-sided tail with R - 1 degrees of freedom", "[compare]") {
  for (std::size_t r : {4, 8, 16, 32}) {
    const std::vector<CalibrationRow> rows = calibrate({run(101, outcome(r, 100, 0))});
    REQUIRE(rows.size() == 1);
    INFO(r << " replicas");
    CHECK(rows[0].chance == Approx(student_tail(double(r - 1), 4.0)).epsilon(1e-6));
  }
}

TEST_CASE("calibration: a quantity is judged by its failed seeds - within the binomial bound consistent, beyond it TOO MANY", "[compare]") {
  // 16 replicas, z = 4: p = 1.16e-3 per point; a seed of 100 points fails by chance with probability at most
  // q = 1 - (1 - p)^100 = 0.110. Two seeds: P(X <= 1) = 1 - q^2 = 0.988 < 0.999, so both may fail (allowed 2).
  const std::vector<SeedRun> ok = {run(101, outcome(16, 100, 4)), run(102, outcome(16, 100, 0))};
  const std::vector<CalibrationRow> a = calibrate(ok);
  CHECK(a[0].seeds == 2);
  CHECK(a[0].seeds_failed == 1);
  CHECK(a[0].points == 200);
  CHECK(a[0].outside == 4);
  const double q = 1.0 - std::pow(1.0 - a[0].chance, 100.0);
  CHECK(a[0].seed_chance == Approx(q).epsilon(1e-12));
  CHECK(a[0].seeds_allowed == 2.0);
  // 4 points outside in one seed: more than 200 independent points would allow (the 99.9% Poisson quantile of 0.23 is
  // 3), but the points of a seed are correlated and the seed count is the test.
  CHECK(a[0].allowed == 3.0);
  CHECK(a[0].consistent());
  CHECK(a[0].ratio_max == 1.5);
  // 20 seeds, 8 failing: the 99.9% quantile of Binomial(20, 0.110) by summing its terms here.
  std::vector<SeedRun> many;
  for (std::uint64_t s = 0; s < 20; ++s) many.push_back(run(101 + s, outcome(16, 100, s < 8 ? 1 : 0)));
  const std::vector<CalibrationRow> b = calibrate(many);
  double cdf = 0.0, quantile = -1.0;
  for (int k = 0; k <= 20 && quantile < 0.0; ++k) {
    cdf += std::tgamma(21.0) / (std::tgamma(k + 1.0) * std::tgamma(21.0 - k)) * std::pow(q, k) * std::pow(1.0 - q, 20 - k);
    if (cdf >= 0.999) quantile = k;
  }
  CHECK(b[0].seeds_allowed == quantile);
  CHECK(quantile < 8.0);
  CHECK_FALSE(b[0].consistent());
  CHECK(calibration_summary({}, b).find("TOO MANY") != std::string::npos);
}

TEST_CASE("calibration: correlated points fail a seed no more often than 1 - (1 - p)^n (independent Monte Carlo of Sidak's bound)",
          "[compare]") {
  // Each replica's value along 30 points is a random walk (as an MSD or a temperature carries a deviation on to every
  // later time); a point's t statistic over 8 replicas; a seed fails when any |t| > 4. Its frequency over 20000 seeds
  // must stay below q = 1 - (1 - p)^30 (by 4 binomial sigmas) and above p, the chance of one point.
  const std::size_t R = 8, n = 30, seeds = 20000;
  std::mt19937_64 gen(20261207);
  std::normal_distribution<double> normal;
  std::size_t failed = 0;
  std::vector<double> walk(R);
  for (std::size_t s = 0; s < seeds; ++s) {
    std::fill(walk.begin(), walk.end(), 0.0);
    bool fail = false;
    for (std::size_t i = 0; i < n; ++i) {
      double mean = 0.0, sq = 0.0;
      for (double& w : walk) w += normal(gen), mean += w;
      mean /= double(R);
      for (double w : walk) sq += (w - mean) * (w - mean);
      fail = fail || std::abs(mean) / std::sqrt(sq / double(R - 1) / double(R)) > 4.0;
    }
    failed += fail;
  }
  const double p = student_tail(double(R - 1), 4.0), q = 1.0 - std::pow(1.0 - p, double(n));
  const double f = double(failed) / double(seeds);
  INFO("p " << p << ", q " << q << ", measured " << f);
  CHECK(f < q - 4.0 * std::sqrt(q * (1.0 - q) / double(seeds)));
  CHECK(f > p);
  const std::vector<CalibrationRow> rows = calibrate({run(101, outcome(R, n, 0))});
  CHECK(rows[0].seed_chance == Approx(q).epsilon(1e-6));
}

TEST_CASE("calibration: --seeds takes A-B or A within [0, 2^53] - anything else exit 2 naming it", "[compare]") {
  CHECK(parse_seed_range("101-103") == std::vector<std::uint64_t>{101, 102, 103});
  CHECK(parse_seed_range("7") == std::vector<std::uint64_t>{7});
  for (const char* bad : {"3-1", "x", "1-", "-4", "0-5000", "9007199254740993"}) CHECK_THROWS_AS(parse_seed_range(bad), InputError);
}

TEST_CASE("calibration: validate --seeds runs the suite at each seed and writes calibration.tsv and .json", "[compare][dsmc]") {
  const auto d = test::fresh_dir("calibration");
  std::filesystem::create_directories(d / "scenes");
  test::write_file(d / "scenes" / "own.toml", test::toy_binary_scene("own"));
  const auto r = test::run_granmix("validate --seeds 101-102 --scenes " + (d / "scenes").string() + " --out " + (d / "out").string());
  INFO(r.output);
  CHECK(r.code <= 1);
  CHECK(std::filesystem::exists(d / "out" / "seed-101" / "own" / "dsmc.tsv"));
  CHECK(std::filesystem::exists(d / "out" / "seed-102" / "summary.json"));
  std::ifstream in(d / "out" / "calibration.json");
  const auto j = nlohmann::json::parse(in);
  REQUIRE(j["quantities"].size() == 1);
  CHECK(j["quantities"][0]["seeds"] == 2);
  CHECK(j["seeds"][1]["seed"] == 102);
  std::ifstream t(d / "out" / "calibration.tsv");
  std::stringstream text;
  text << t.rdbuf();
  CHECK(text.str().find("# seed: 101-102") != std::string::npos);
  CHECK(text.str().find("scene\tquantity\treplicas\tz\tseeds") != std::string::npos);
  CHECK(r.output.find("calibration: 2 seeds, 1 quantities") != std::string::npos);
  const auto both = test::run_granmix("validate --seeds 1-2 --seed 3 --out " + (d / "both").string());
  CHECK(both.code == 2);
}
