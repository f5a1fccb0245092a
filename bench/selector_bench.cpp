// DSMC selector benchmark (issue 3): accepted collisions per second, trial pairs per second and
// acceptance of each selector on
//   binary:  m = 1, 100; σ = 1, 100^(1/3); n = 0.1, 0.1; ε = 0.5; 1e5 particles; t = 10
//   poly691: N_k = floor(999 e^(−0.01(k−1))), k = 1…691 (~1e5 particles), m_k = k, σ_k = k^(1/3),
//            n = 0.1, all T = 1, ε = 0.99, t = 10 (the system of the v2 paper's Fig. 6 / Table 1)
// One replica on one thread, the median of --repeats runs. Prints a table, or with --json one
// object per line: {"selector", "system", "species", "particles", "collisions", "trials", "seconds",
// "collisions_per_second", "acceptance"} (design.md §3).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "dsmc/ensemble.hpp"

using namespace granmix;

namespace {

dsmc::DsmcSetup binary() {
  dsmc::DsmcSetup s;
  s.mixture = model::Mixture({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}});
  s.law = model::Restitution::constant(2, 0.5);
  s.counts = {50000, 50000};
  s.T0 = {1, 1};
  return s;
}

dsmc::DsmcSetup poly691() {
  std::vector<model::Species> sp;
  std::vector<std::size_t> counts;
  std::size_t N = 0;
  for (int k = 1; k <= 691; ++k) counts.push_back(static_cast<std::size_t>(std::floor(999 * std::exp(-0.01 * (k - 1))))), N += counts.back();
  for (int k = 1; k <= 691; ++k) sp.push_back({double(k), std::cbrt(double(k)), 0.1 * double(counts[k - 1]) / double(N)});
  dsmc::DsmcSetup s;
  s.mixture = model::Mixture(sp);
  s.law = model::Restitution::constant(691, 0.99);
  s.counts = counts;
  s.T0.assign(691, 1.0);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  bool json = false;
  int repeats = 3;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--json")) json = true;
    else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc) repeats = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--system") && i + 1 < argc) only = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--json] [--repeats N] [--system binary|poly691]\n", argv[0]);
      return 2;
    }
  }
  if (!json) std::printf("%-8s %-8s %8s %10s %12s %12s %9s %14s %10s\n", "system", "selector", "species", "particles", "collisions",
                         "trials", "seconds", "collisions/s", "acceptance");
  for (const char* system : {"binary", "poly691"}) {
    if (!only.empty() && only != system) continue;
    for (dsmc::Method m : {dsmc::Method::direct, dsmc::Method::lowrank, dsmc::Method::bird}) {
      dsmc::DsmcSetup s = std::string(system) == "binary" ? binary() : poly691();
      if (m == dsmc::Method::direct && s.mixture.size() > 8) continue;  // M² table: for few species
      s.method = m, s.times = {10.0}, s.replicas = 1, s.threads = 1;
      std::vector<dsmc::DsmcResult> runs;
      for (int r = 0; r < repeats; ++r) runs.push_back(dsmc::run_ensemble(s));
      std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.seconds < b.seconds; });
      const dsmc::DsmcResult& r = runs[runs.size() / 2];
      if (json)
        std::printf("{\"selector\": \"%s\", \"system\": \"%s\", \"species\": %zu, \"particles\": %zu, \"collisions\": %llu, "
                    "\"trials\": %llu, \"seconds\": %.6f, \"collisions_per_second\": %.1f, \"acceptance\": %.5f}\n",
                    dsmc::to_string(m), system, r.species, r.particles, static_cast<unsigned long long>(r.accepted),
                    static_cast<unsigned long long>(r.trials), r.seconds, r.collisions_per_second(), r.acceptance());
      else
        std::printf("%-8s %-8s %8zu %10zu %12llu %12llu %9.3f %14.4g %10.4f\n", system, dsmc::to_string(m), r.species, r.particles,
                    static_cast<unsigned long long>(r.accepted), static_cast<unsigned long long>(r.trials), r.seconds,
                    r.collisions_per_second(), r.acceptance());
      std::fflush(stdout);
    }
  }
  return 0;
}
