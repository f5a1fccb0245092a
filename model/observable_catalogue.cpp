#include "observable_catalogue.hpp"

#include <fmt/format.h>

#include "scene.hpp"

namespace granmix::model {

const std::vector<ObservableDescriptor>& observable_catalogue() {
  // Columns are written by theory/scene_theory.cpp (level_table, sweep_table, distribution tables) and
  // dsmc/scene_dsmc.cpp (make_table), each from the estimators named here; errors are over replicas
  // (dsmc/ensemble.cpp: the replicas' spread, the jackknife for ratios; docs/dsmc.md §8).
  static const std::vector<ObservableDescriptor> catalogue = {
      {"temperatures", {"T"}, "t", "partial temperatures T_k(t) (species 0: the mean <T>)",
       "the level's temperature history (theory/histories/temperature_history.hpp)", "per-species mean kinetic energy at the sample times",
       "replicas' spread", true, [](const Observables& o) { return o.temperatures; }},
      {"msd", {"msd"}, "t", "partial mean-squared displacements <R_k^2(t)> (species 0: the total, v1 Eq. 16)",
       "the level's MSD method (theory/histories/msd.hpp; VACF ODE, closed form)", "unwrapped displacements (dsmc/particles.hpp)",
       "replicas' spread; the total by the jackknife",
       true, [](const Observables& o) { return o.msd; }},
      {"msd_ratio", {"msd_ratio"}, "t", "<R_k^2>/<R_1^2> (v1 Fig. 8)", "the ratio of the level's MSDs", "the ratio of the replica means",
       "jackknife over replicas", true, [](const Observables& o) { return o.msd_ratio; }},
      {"gamma", {"gamma", "gamma_ratio"}, "t, or the swept value", "gamma = T_1/T_2 (MG); along an n_star sweep also gamma(n*)/gamma(0)",
       "in time the level's temperature history; along a sweep its HCS (theory/sonine/sonine_hcs.hpp, theory/grid/converged_hcs.hpp)", "the temperature ratio, averaged over the settled samples",
       "replicas' spread; the dilute reference run for gamma_ratio", true, [](const Observables& o) { return o.gamma; }},
      {"cumulant", {"c"}, "t, or the swept value", "the fourth cumulant c_k = 2[(3/5)<v^4>/<v^2>^2 - 1]", "the level's HCS (Sonine or converged); none in time",
       "velocity moments at the sample times", "replicas' spread", true, [](const Observables& o) { return o.cumulant; }},
      {"d_ratio", {"D_ratio"}, "t, or the swept value", "D_k/D_1 (v1 Figs. 4, 5, 7)",
       "the level's D (theory/rates/diffusion.hpp, theory/grid/converged_hcs_diffusion.hpp); D_ratio_increment: MSD increments",
       "MSD increments between the first and last sample", "jackknife over replicas", true, [](const Observables& o) { return o.d_ratio; }},
      {"tamsd", {"tamsd"}, "lag", "time-averaged MSD of the tracers over [0, measurement_time] (v2)",
       "the tracer form (theory/grid/tracer_form.hpp, theory/histories/tamsd.hpp)", "tracer trajectories averaged over windows", "replicas' spread",
       true, [](const Observables& o) { return o.tamsd; }},
      {"rescaled_time", {"t_s"}, "t", "the reduced time t_s = integral of sqrt(T_1/T_1(0)) dt (v1 Fig. 1)", "the level's temperature history",
       "the DSMC's own temperature history", "replicas' spread", false, [](const Observables& o) { return o.rescaled_time; }},
      {"distribution", {"phi", "delta", "G"}, "v (bin centres)", "speed distributions Phi_k(v*): histograms in time (distribution.tsv), or settled with Delta_k, G_k (MG Figs. 3, 7)",
       "settled: the level's settled distribution, shell-averaged per bin (theory/levels/theory_level.hpp)",
       "speed histograms at the samples, or averaged over them when settled",
       "replicas' spread", true, [](const Observables& o) { return o.distribution_bins > 0; }},
  };
  return catalogue;
}

std::vector<std::string> observable_quantities() {
  std::vector<std::string> out;
  for (const ObservableDescriptor& d : observable_catalogue()) out.insert(out.end(), d.quantities.begin(), d.quantities.end());
  return out;
}

std::vector<std::string> plotted_quantities() {
  std::vector<std::string> out;
  for (const ObservableDescriptor& d : observable_catalogue())
    if (d.plotted_on_y) out.insert(out.end(), d.quantities.begin(), d.quantities.end());
  return out;
}

std::vector<std::string> observable_keys() {
  std::vector<std::string> out;
  for (const ObservableDescriptor& d : observable_catalogue()) out.push_back(d.key);
  return out;
}

std::string observable_listing(bool markdown) {
  std::string out;
  auto joined = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  };
  if (markdown) {
    out += "| [observables] key | quantities | axis | what it is | theory | DSMC estimator | DSMC error |\n|---|---|---|---|---|---|---|\n";
    for (const ObservableDescriptor& d : observable_catalogue())
      out += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", d.key, joined(d.quantities), d.axis, d.summary, d.theory, d.dsmc, d.error);
    return out;
  }
  for (const ObservableDescriptor& d : observable_catalogue())
    out += fmt::format("{:<14} {:<22} {}\n{:<14} {:<22} axis: {}; theory: {}; DSMC: {}; error: {}\n", d.key, joined(d.quantities), d.summary, "", "",
                       d.axis, d.theory, d.dsmc, d.error);
  return out;
}

}  // namespace granmix::model
