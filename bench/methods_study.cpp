// Study `methods`: the Montanero–Garzó time-step scheme's Δt bias against its cost, next
// to the exact event-driven run. MG Fig. 1 system (μ = 10, δ = 2, w = 1, α = 0.5), settled start,
// c_1 and γ at t = 50 t0 (t0 = λ11/v01(0)); Δt = factor · λ11/v01(t) for factors 0.3 … 0.003 (MG used
// 3e-3). The bias is the difference from the event-driven value; both carry replica errors.
#include <fmt/format.h>

#include <cmath>

#include "dsmc/ensemble.hpp"
#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "study.hpp"
#include "theory/histories/initial_state.hpp"
#include "theory/rates/time_unit.hpp"

namespace granmix::bench {

StudyResult methods_study(const StudyOptions& o) {
  StudyResult out;
  out.name = "methods";
  out.table.columns = {"series", "dt_factor", "cpu_seconds", "c1", "c1_err", "gamma", "gamma_err", "c1_bias", "gamma_bias"};
  out.figure = {"cpu_seconds", "c1", "CPU seconds (all replicas)", "c_1 at t = 50 t0", true, false,
                {"event-driven (exact in time)", "time-step scheme (labels: dt factor)"}, {}};
  const model::Mixture mix = model::montanero_garzo_binary(10, 2, 1, 0);
  const model::Restitution law = model::Restitution::constant(2, 0.5);
  const auto chi = model::dilute_contact_values(2);
  const theory::CollisionRates rates(mix, law, chi);
  dsmc::DsmcSetup s;
  s.mixture = mix, s.law = law;
  s.counts = dsmc::counts_for(mix, o.quick ? 2000 : 20000);
  model::InitialState settled;
  settled.kind = model::InitialState::Kind::hcs;
  s.T0 = theory::initial_temperatures(settled, rates);
  const double t0 = theory::mg_time_unit(mix, chi, s.T0[0]);
  s.times = {50.0 * t0};
  s.cumulant = true, s.replicas = o.quick ? 4 : 16, s.seed = o.seed;
  auto measure = [&](dsmc::Method m, double factor) {
    dsmc::DsmcSetup x = s;
    x.method = m, x.time_step_factor = factor;
    const dsmc::DsmcResult r = dsmc::run_ensemble(x);
    const auto [g, ge] = dsmc::replica_ratio(r.T, 0, r.T, 1);
    return std::array<double, 5>{r.seconds_setup + r.seconds_loop + r.seconds_sample, r.cumulant.mean[0], r.cumulant.err[0], g, ge};
  };
  const auto exact = measure(dsmc::Method::direct, 0.0);
  out.table.rows.push_back({0, 0, exact[0], exact[1], exact[2], exact[3], exact[4], 0, 0});
  out.summary.push_back(fmt::format("event-driven: c1 = {:.4f} +- {:.4f}, gamma = {:.4f} +- {:.4f}, {:.2f} CPU s", exact[1], exact[2], exact[3],
                                    exact[4], exact[0]));
  const std::vector<double> factors = o.quick ? std::vector<double>{0.3, 0.03} : std::vector<double>{0.3, 0.1, 0.03, 0.01, 0.003};
  for (double f : factors) {
    const auto a = measure(dsmc::Method::timestep, f);
    const double bc = a[1] - exact[1], bg = a[3] - exact[3];
    out.table.rows.push_back({1, f, a[0], a[1], a[2], a[3], a[4], bc, bg});
    const std::string line = fmt::format("time step {:<6g}: c1 = {:.4f} +- {:.4f} (bias {:+.4f}, {:.1f} sigma), gamma = {:.4f} (bias {:+.4f}), {:.2f} CPU s",
                                         f, a[1], a[2], bc, bc / std::hypot(a[2], exact[2]), a[3], bg, a[0]);
    out.summary.push_back(line);  // printed at the end with the others
    out.json.push_back(fmt::format("{{\"method\": \"timestep\", \"dt_factor\": {:g}, \"cpu_seconds\": {:.4g}, \"c1\": {:.5g}, \"c1_err\": {:.3g}, "
                                   "\"gamma\": {:.5g}, \"gamma_err\": {:.3g}}}", f, a[0], a[1], a[2], a[3], a[4]));
  }
  out.json.push_back(fmt::format("{{\"method\": \"event-driven\", \"cpu_seconds\": {:.4g}, \"c1\": {:.5g}, \"c1_err\": {:.3g}, \"gamma\": {:.5g}, "
                                 "\"gamma_err\": {:.3g}}}", exact[0], exact[1], exact[2], exact[3], exact[4]));
  out.figure.extra.push_back(fmt::format("{} with lines dt 3 lc rgb 'black' title 'event-driven c_1'", exact[1]));
  return out;
}

}  // namespace granmix::bench
