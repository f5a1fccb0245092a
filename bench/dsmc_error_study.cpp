// Study `dsmc-error`: the statistical error of T_k and MSD_k against CPU time as
// particles × replicas grow, on the binary 1:100 of v1 Fig. 2 (ε = 0.5, equal start, t = 100).
// The standard error over replicas should fall as 1/√work; the fitted exponent is reported, and the
// figure draws the line err ∝ work^(−1/2) through the largest run.
#include <fmt/format.h>

#include <cmath>

#include "study.hpp"
#include "systems.hpp"

namespace granmix::bench {

StudyResult dsmc_error_study(const StudyOptions& o) {
  StudyResult out;
  out.name = "dsmc-error";
  out.table.columns = {"series", "particles", "replicas", "cpu_seconds", "rel_err", "collisions"};
  out.figure = {"cpu_seconds", "rel_err", "CPU seconds (all replicas)", "relative standard error at t = 100", true, true,
                {"T_1", "T_2", "MSD_1", "MSD_2"}, {}};
  struct Size {
    std::size_t particles, replicas;
  };
  const std::vector<Size> sizes = o.quick ? std::vector<Size>{{1000, 4}, {4000, 8}}
                                          : std::vector<Size>{{1000, 8}, {2000, 8}, {5000, 8}, {10000, 16}, {20000, 16}, {50000, 32}};
  double fit[4][4] = {};  // least squares of ln err on ln work: Σx, Σy, Σxx, Σxy per series
  for (const Size& z : sizes) {
    dsmc::DsmcSetup s = binary_1_100(z.particles).setup;
    s.times = {100.0}, s.msd = true, s.replicas = z.replicas, s.seed = o.seed, s.threads = 0;
    const dsmc::DsmcResult r = dsmc::run_ensemble(s);
    const double cpu = r.seconds_setup + r.seconds_loop + r.seconds_sample;
    const double rel[4] = {r.T.err[0] / r.T.mean[0], r.T.err[1] / r.T.mean[1], r.msd.err[0] / r.msd.mean[0], r.msd.err[1] / r.msd.mean[1]};
    for (int q = 0; q < 4; ++q) {
      out.table.rows.push_back({double(q), double(z.particles), double(z.replicas), cpu, rel[q], double(r.accepted)});
      const double x = std::log(cpu), y = std::log(rel[q]);
      fit[q][0] += x, fit[q][1] += y, fit[q][2] += x * x, fit[q][3] += x * y;
      out.json.push_back(fmt::format("{{\"quantity\": \"{}\", \"particles\": {}, \"replicas\": {}, \"cpu_seconds\": {:.4g}, \"rel_err\": {:.4g}}}",
                                     out.figure.series[q], z.particles, z.replicas, cpu, rel[q]));
    }
    if (o.progress)
      o.progress(fmt::format("{:>6} particles x {:>2} replicas: {:7.2f} CPU s, rel. errors T1 {:.1e} T2 {:.1e} MSD1 {:.1e} MSD2 {:.1e}", z.particles,
                             z.replicas, cpu, rel[0], rel[1], rel[2], rel[3]));
  }
  const double n = double(sizes.size());
  for (int q = 0; q < 4; ++q) {
    const double slope = (n * fit[q][3] - fit[q][0] * fit[q][1]) / (n * fit[q][2] - fit[q][0] * fit[q][0]);
    out.summary.push_back(fmt::format("{}: error ~ work^{:.2f} (1/sqrt(work) is -0.5)", out.figure.series[q], slope));
  }
  // Guide: err ∝ work^(−1/2) through the last point of T_1.
  const auto& last = out.table.rows[out.table.rows.size() - 4];
  out.figure.extra.push_back(fmt::format("{}*sqrt({}/x) with lines dt 3 lc rgb 'black' title 'work^(-1/2)'", last[4], last[3]));
  return out;
}

}  // namespace granmix::bench
