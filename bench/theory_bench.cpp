// Theory benchmark: cost and accuracy of the pieces a scene uses, side by side. Speed is
// measured here, never asserted in tests. Prints one line per case: what, seconds (median of 3),
// and an accuracy figure for the same run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "theory/diffusion.hpp"
#include "theory/msd.hpp"
#include "theory/settled_ratios.hpp"
#include "theory/temperature_history.hpp"

using namespace granmix;

namespace {

double median_seconds(const std::function<void()>& f) {
  std::vector<double> s;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(s.begin(), s.end());
  return s[1];
}

theory::CollisionRates power_law_rates(std::size_t M) {
  model::PowerLaw p;
  p.n1 = 0.1, p.theta = 3, p.n1_particles = 1e30, p.max_species = M;
  const model::Mixture mix = model::power_law_mixture(p);
  return theory::CollisionRates(mix, model::Restitution::constant(M, 0.5), model::dilute_contact_values(M));
}

}  // namespace

int main() {
  std::printf("%-58s %12s  %s\n", "case", "seconds", "accuracy");
  const model::Mixture bin({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}});
  const theory::CollisionRates rb(bin, model::Restitution::constant(2, 0.5), model::dilute_contact_values(2));
  // Equal start (a transient the solver must resolve) against a reference at rtol 1e-13.
  auto msd_curve = [&](double rtol) {
    theory::TemperatureOptions o;
    o.rtol = rtol, o.reduced_time = true;
    const theory::TemperatureHistory h(rb, {1.0, 1.0}, 1e12, o);
    std::vector<double> v;
    for (double t = 1e-3; t <= 1e12; t *= 10)
      for (std::size_t k = 0; k < 2; ++k) v.push_back(theory::msd_eq17(h, k, t));
    return v;
  };
  const std::vector<double> ref = msd_curve(1e-13);
  for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    std::vector<double> v;
    const double secs = median_seconds([&] { v = msd_curve(rtol); });
    double err = 0.0;
    for (std::size_t j = 0; j < v.size(); ++j) err = std::max(err, std::abs(v[j] / ref[j] - 1));
    std::printf("binary, equal start: T + Eq.(17) MSD at 16 times, rtol %-6.0e %10.5f  max rel. error %.1e vs rtol 1e-13\n", rtol,
                secs, err);
  }
  for (std::size_t M : {200, 500}) {
    const theory::CollisionRates r = power_law_rates(M);
    long steps = 0;
    const double secs = median_seconds([&] { steps = theory::TemperatureHistory(r, std::vector<double>(M, 1.0), 1e12).stats().steps; });
    std::printf("%-4zu-species power law: temperatures to t = 1e12          %12.5f  (%ld CVODE steps)\n", M, secs, steps);
    double res = 0.0;
    const double s2 = median_seconds([&] { res = theory::settled_temperatures(r).residual; });
    std::printf("%-4zu-species power law: settled ratios                   %12.5f  residual %.1e\n", M, s2, res);
  }
  return 0;
}
