// Study `theory`: error against CPU time of the theory's pieces.
//   series 0, 1: CVODE relative tolerance 1e-4 … 1e-12, error against a 1e-13 reference, for a binary
//                (T and Eq. 17 MSD from an equal start, 16 times to 1e12) and a 200-species power law
//                (temperatures at 16 times to 1e12);
//   series 2, 3: the MSD by the Eq. (17) quadrature and by the VACF ODE (binary, to 1e4): error of
//                each against its own reference at 1e-13; how far the two models lie apart is a summary
//                line (the VACF ODE relaxes the tagged velocity at the momentum rate, docs/physics.md §3);
//   series 4–6: viscoelastic rates (v1 Fig. 9 binary, Aκ^(2/5) = 0.09, temperatures at 16 times to
//                1e8): exact ε by quadrature at rtol 1e-6 … 1e-12, the paper's series (v1 A3/A4) and
//                the Padé form, error against the exact quadrature at 1e-13.
// Targets: 500-species temperatures and MSD to 1e12 under 1 s (Eq. 17 quadrature, and the VACF MSD
// integrated with the temperatures), 5000 species with the VACF MSD under 60 s; a γ(α) curve of 100
// points < 10 ms; every kinetic scene's curves at the kinetic level under 1 s, each beside the
// paper level's cost and the size of what the kinetic level changes (max |kinetic − paper|/max(|kinetic|,
// |paper|) over the scene's value columns; its gap to DSMC is in docs/validation.md).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "model/model_error.hpp"
#include "model/scene.hpp"
#include "study.hpp"
#include "theory/grid/converged_hcs.hpp"
#include "theory/histories/msd.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/histories/temperature_history.hpp"

namespace granmix::bench {

namespace {

double median_seconds(int repeats, const std::function<void()>& f) {
  std::vector<double> s;
  for (int r = 0; r < std::max(1, repeats); ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(s.begin(), s.end());
  return s[s.size() / 2];
}

double max_rel(const std::vector<double>& a, const std::vector<double>& ref) {
  double e = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) e = std::max(e, std::abs(a[j] / ref[j] - 1.0));
  return e;
}

theory::CollisionRates power_law_rates(std::size_t M, double eps) {
  model::PowerLaw p;
  p.n1 = 0.1, p.theta = 3, p.n1_particles = 1e30, p.max_species = M;
  return theory::CollisionRates(model::power_law_mixture(p), model::Restitution::constant(M, eps), model::dilute_contact_values(M));
}

std::vector<double> log_times(double from, double to, int n) {
  std::vector<double> t;
  for (int j = 0; j < n; ++j) t.push_back(from * std::pow(to / from, double(j) / double(n - 1)));
  return t;
}

}  // namespace

StudyResult theory_study(const StudyOptions& o) {
  StudyResult out;
  out.name = "theory";
  out.table.columns = {"series", "rtol", "seconds", "error", "steps"};
  out.figure = {"seconds", "error", "CPU seconds", "max relative error", true, true,
                {"binary: T + Eq. 17 MSD to 1e12 (rtol)", "200 species: T to 1e12 (rtol)", "Eq. 17 quadrature (rtol)",
                 "VACF ODE (rtol)", "viscoelastic: exact eps quadrature (rtol)", "viscoelastic: series A3/A4", "viscoelastic: Pade"},
                {}};
  auto row = [&](int series, double rtol, double secs, double err, long steps) {
    out.table.rows.push_back({double(series), rtol, secs, err, double(steps)});
    out.json.push_back(fmt::format("{{\"case\": \"{}\", \"rtol\": {:g}, \"seconds\": {:.6g}, \"error\": {:.3g}, \"steps\": {}}}",
                                   out.figure.series[series], rtol, secs, err, steps));
    if (o.progress) o.progress(fmt::format("{:<45} rtol {:<7.0e} {:10.5f} s  error {:.1e}", out.figure.series[series], rtol, secs, err));
  };
  const std::vector<double> rtols = o.quick ? std::vector<double>{1e-4, 1e-8} : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

  // Binary, equal start: temperatures and Eq. (17) MSD.
  const model::Mixture bin({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}});
  const theory::CollisionRates rb(bin, model::Restitution::constant(2, 0.5), model::dilute_contact_values(2));
  const std::vector<double> times = log_times(1e-3, 1e12, 16);
  auto binary_curve = [&](double rtol, long& steps) {
    theory::TemperatureOptions opt;
    opt.rtol = rtol, opt.reduced_time = true;
    const theory::TemperatureHistory h(rb, {1.0, 1.0}, times.back(), opt);
    steps = h.stats().steps;
    std::vector<double> v;
    for (double t : times)
      for (std::size_t k = 0; k < 2; ++k) v.push_back(h.temperature(t, k)), v.push_back(theory::msd_eq17(h, k, t));
    return v;
  };
  long steps = 0;
  const std::vector<double> ref_bin = binary_curve(1e-13, steps);
  for (double rtol : rtols) {
    std::vector<double> v;
    const double secs = median_seconds(o.repeats, [&] { v = binary_curve(rtol, steps); });
    row(0, rtol, secs, max_rel(v, ref_bin), steps);
  }
  // 200-species power law: temperatures to 1e12.
  const theory::CollisionRates r200 = power_law_rates(o.quick ? 50 : 200, 0.5);
  auto poly_curve = [&](double rtol, long& steps) {
    theory::TemperatureOptions opt;
    opt.rtol = rtol;
    const theory::TemperatureHistory h(r200, std::vector<double>(r200.size(), 1.0), times.back(), opt);
    steps = h.stats().steps;
    std::vector<double> v(r200.size());
    std::vector<double> all;
    for (double t : times) h.temperatures(t, v.data()), all.insert(all.end(), v.begin(), v.end());
    return all;
  };
  const std::vector<double> ref_poly = poly_curve(1e-13, steps);
  for (double rtol : rtols) {
    std::vector<double> v;
    const double secs = median_seconds(o.repeats, [&] { v = poly_curve(rtol, steps); });
    row(1, rtol, secs, max_rel(v, ref_poly), steps);
  }
  // Eq. (17) quadrature against the VACF ODE, binary to t = 1e4.
  const std::vector<double> t4 = log_times(1e-2, 1e4, 16);
  auto msd_curve = [&](double rtol, bool vacf, long& steps) {
    theory::TemperatureOptions opt;
    opt.rtol = rtol, opt.reduced_time = !vacf, opt.vacf = vacf, opt.t_first = t4.front();
    const theory::TemperatureHistory h(rb, {1.0, 1.0}, t4.back(), opt);
    steps = h.stats().steps;
    std::vector<double> v;
    for (double t : t4)
      for (std::size_t k = 0; k < 2; ++k) v.push_back(vacf ? h.msd_vacf(t, k) : theory::msd_eq17(h, k, t));
    return v;
  };
  const std::vector<double> ref_msd[2] = {msd_curve(1e-13, false, steps), msd_curve(1e-13, true, steps)};
  for (int vacf = 0; vacf < 2; ++vacf)
    for (double rtol : rtols) {
      std::vector<double> v;
      const double secs = median_seconds(o.repeats, [&] { v = msd_curve(rtol, vacf, steps); });
      row(2 + vacf, rtol, secs, max_rel(v, ref_msd[vacf]), steps);
    }
  out.summary.push_back(fmt::format("MSD by the VACF ODE against Eq. 17 (binary, t = 1e-2 .. 1e4): the models differ by up to {:.2g} (relative)",
                                    max_rel(ref_msd[1], ref_msd[0])));
  // Viscoelastic restitution: exact ε (quadrature) against the series and Padé forms.
  const std::vector<double> t8 = log_times(1e-2, 1e8, 16);
  auto visco_curve = [&](model::ViscoelasticForm form, theory::MomentMethod m, double rtol, long& steps) {
    const theory::CollisionRates r(bin, model::Restitution::viscoelastic(bin, 0.09, form), model::dilute_contact_values(2), m);
    theory::TemperatureOptions opt;
    opt.rtol = rtol;
    const theory::TemperatureHistory h(r, {1.0, 1.0}, t8.back(), opt);
    steps = h.stats().steps;
    std::vector<double> v;
    for (double t : t8)
      for (std::size_t k = 0; k < 2; ++k) v.push_back(h.temperature(t, k));
    return v;
  };
  using F = model::ViscoelasticForm;
  using MM = theory::MomentMethod;
  const std::vector<double> ref_visco = visco_curve(F::exact, MM::quadrature, 1e-13, steps);
  for (double rtol : rtols) {
    std::vector<double> v;
    const double secs = median_seconds(o.repeats, [&] { v = visco_curve(F::exact, MM::quadrature, rtol, steps); });
    row(4, rtol, secs, max_rel(v, ref_visco), steps);
  }
  for (int f = 0; f < 2; ++f) {
    std::vector<double> v;
    const F form = f == 0 ? F::series : F::pade;
    const MM m = f == 0 ? MM::series : MM::quadrature;
    const double secs = median_seconds(o.repeats, [&] { v = visco_curve(form, m, 1e-10, steps); });
    row(5 + f, 1e-10, secs, max_rel(v, ref_visco), steps);
  }

  // Targets.
  const std::size_t M = o.quick ? 100 : 500;
  const theory::CollisionRates r500 = power_law_rates(M, 0.5);
  const double s500 = median_seconds(o.repeats, [&] {
    theory::TemperatureOptions opt;
    opt.rtol = 1e-8, opt.reduced_time = true;
    const theory::TemperatureHistory h(r500, std::vector<double>(M, 1.0), 1e12, opt);
    const theory::Eq17Msd eq17(h);
    double sink = 0.0;
    for (double t : times)
      for (std::size_t k = 0; k < M; ++k) sink += eq17(k, t);
    if (!std::isfinite(sink)) throw std::runtime_error("bench: non-finite MSD");
  });
  out.summary.push_back(fmt::format("{} species, temperatures and Eq. 17 MSD at 16 times to t = 1e12 (rtol 1e-8): {:.3f} s (target < 1 s)", M, s500));
  // The MSD as part of the ODE (VACF: 3 unknowns per species, one pair pass per right-hand side),
  // error against the same at rtol 1e-11.
  auto vacf_curve = [&](const theory::CollisionRates& r, double rtol) {
    theory::TemperatureOptions opt;
    opt.rtol = rtol, opt.vacf = true, opt.t_first = times.front();
    const theory::TemperatureHistory h(r, std::vector<double>(r.size(), 1.0), 1e12, opt);
    std::vector<double> v;
    for (double t : times)
      for (std::size_t k = 0; k < r.size(); ++k) v.push_back(h.msd_vacf(t, k));
    return v;
  };
  std::vector<double> v500;
  const double s500v = median_seconds(o.repeats, [&] { v500 = vacf_curve(r500, 1e-8); });
  const double e500v = max_rel(v500, vacf_curve(r500, 1e-11));
  out.summary.push_back(fmt::format("{} species, temperatures and VACF MSD (ODE) at 16 times to t = 1e12 (rtol 1e-8): {:.3f} s, "
                                    "max relative error {:.1e} against rtol 1e-11 (target < 1 s)", M, s500v, e500v));
  // 5000 species the same way, one run (about 25 CPU s; not in --quick).
  double s5000v = 0.0;
  if (!o.quick) {
    const theory::CollisionRates r5000 = power_law_rates(5000, 0.5);
    s5000v = median_seconds(1, [&] { vacf_curve(r5000, 1e-8); });
    out.summary.push_back(fmt::format("5000 species, temperatures and VACF MSD (ODE) at 16 times to t = 1e12 (rtol 1e-8): {:.1f} s "
                                      "(target < 60 s)", s5000v));
  }
  const model::Mixture mg = model::montanero_garzo_binary(10, 2, 1, 0);
  const double sg = median_seconds(o.repeats, [&] {
    for (int j = 0; j < 100; ++j) {
      const double alpha = 0.01 + 0.99 * j / 99.0;
      if (!std::isfinite(theory::sonine_hcs(mg, model::Restitution::constant(2, alpha), model::dilute_contact_values(2)).gamma()))
        throw std::runtime_error("bench: non-finite gamma");
    }
  });
  out.summary.push_back(fmt::format("gamma(alpha) of MG Fig. 4 (mu = 10), 100 points, first Sonine: {:.2f} ms (target < 10 ms)", 1e3 * sg));
  out.json.push_back(fmt::format("{{\"case\": \"{} species T + MSD to 1e12\", \"seconds\": {:.6g}}}", M, s500));
  out.json.push_back(fmt::format("{{\"case\": \"{} species T + VACF MSD to 1e12\", \"seconds\": {:.6g}, \"error\": {:.3g}}}", M, s500v, e500v));
  if (!o.quick) out.json.push_back(fmt::format("{{\"case\": \"5000 species T + VACF MSD to 1e12\", \"seconds\": {:.6g}}}", s5000v));
  out.json.push_back(fmt::format("{{\"case\": \"gamma(alpha) 100 points\", \"seconds\": {:.6g}}}", sg));

  // The two levels scene by scene (the scenes of the scene folder at a kinetic level, each at its own — kinetic,
  // kinetic-converged or kinetic-converged-cooling3 — against the paper level; --quick: the first three).
  std::vector<std::filesystem::path> files;
  if (!o.scenes_folder.empty() && std::filesystem::is_directory(o.scenes_folder))
    for (const auto& e : std::filesystem::directory_iterator(o.scenes_folder))
      if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  double slowest = 0.0;
  std::string slowest_scene;
  std::size_t measured = 0;
  for (const auto& f : files) {
    const model::Scene s = theory::load_scene(f.string());
    if (theory::find_level(s.theory.level).reported_beside_others || (o.quick && measured == 3)) continue;
    ++measured;
    theory::TheoryResult kin, pap;
    // Each repeat cold, as a run of `granmix theory`: the distributions' solve is kept per process (converged_hcs.hpp).
    const double sk = median_seconds(o.repeats, [&] {
      theory::forget_converged_distributions();
      kin = theory::run_level(s, s.theory.level);
    });
    const double sp = median_seconds(o.repeats, [&] { pap = theory::run_level(s, "paper"); });
    double change = 0.0;  // same rows and columns at both levels
    for (std::size_t r = 0; r < kin.table.rows.size() && r < pap.table.rows.size(); ++r)
      for (std::size_t c = 1; c < kin.table.columns.size() && c < pap.table.columns.size(); ++c) {
        const std::string& col = kin.table.columns[c];
        if (col == "species" || col == "lag") continue;
        const double a = kin.table.rows[r][c], b = pap.table.rows[r][c];
        // Relative to the larger of the two: bo1-fig04's sweep reaches a heavy tracer at the Santos–Dufty edge,
        // where the levels' D ratios differ 3.6× (103 against 370).
        if (std::isfinite(a) && std::isfinite(b) && (a != 0.0 || b != 0.0))
          change = std::max(change, std::abs(a - b) / std::max(std::abs(a), std::abs(b)));
      }
    // The judged level's error beside its cost: its computed model error (model/model_error.hpp, the tolerance's model
    // part that validate applies), the largest over the scene's judged points and quantities — from the scene's whole
    // theory run (the level and the companions its corrections name), timed apart.
    theory::TheoryResult full;
    const double sf = median_seconds(1, [&] {
      theory::forget_converged_distributions();
      full = theory::run_theory(s);
    });
    double model_error = 0.0;
    for (const model::CompareQuantity& q : s.compare) model_error = std::max(model_error, model::max_model_error(q, full.table));
    if (sk > slowest) slowest = sk, slowest_scene = s.name;
    if (o.progress)
      o.progress(fmt::format("{:<45} {} {:8.3f} s  model error <= {:.2f}% ({:.2f} s with its companions)  paper {:8.3f} s  "
                             "levels differ by up to {:.1f}%",
                             s.name, s.theory.level, sk, 100 * model_error, sf, sp, 100 * change));
    out.json.push_back(fmt::format("{{\"case\": \"levels: {}\", \"kinetic_seconds\": {:.6g}, \"paper_seconds\": {:.6g}, \"kinetic_change\": {:.4g}, "
                                   "\"level\": \"{}\", \"kinetic_model_error\": {:.4g}, \"kinetic_seconds_with_companions\": {:.6g}}}",
                                   s.name, sk, sp, change, s.theory.level, model_error, sf));
  }
  if (measured > 0)
    out.summary.push_back(fmt::format("kinetic level of {} scenes: slowest {} at {:.2f} s (target < 1 s)", measured, slowest_scene, slowest));
  return out;
}

}  // namespace granmix::bench
