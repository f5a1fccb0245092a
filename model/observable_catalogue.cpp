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
       "replicas' spread", true, [](const Observables& o) { return o.temperatures; }, {"temperature T_k  [T_u]"}},
      {"msd", {"msd"}, "t", "partial mean-squared displacements <R_k^2(t)> (species 0: the total, v1 Eq. 16)",
       "the level's MSD method (theory/histories/msd.hpp; VACF ODE, closed form)", "unwrapped displacements (dsmc/particles.hpp)",
       "replicas' spread; the total by the jackknife",
       true, [](const Observables& o) { return o.msd; }, {"MSD ⟨R_k^2⟩  [σ_u^2]"}},
      {"msd_ratio", {"msd_ratio"}, "t", "<R_k^2>/<R_1^2> (v1 Fig. 8)", "the ratio of the level's MSDs", "the ratio of the replica means",
       "jackknife over replicas", true, [](const Observables& o) { return o.msd_ratio; }, {"⟨R_k^2⟩/⟨R_1^2⟩"}},
      {"gamma", {"gamma", "gamma_ratio"}, "t, or the swept value", "gamma = T_1/T_2 (MG); along an n_star sweep also gamma(n*)/gamma(0)",
       "in time the level's temperature history; along a sweep its HCS (theory/sonine/sonine_hcs.hpp, theory/grid/converged_hcs.hpp)", "the temperature ratio, averaged over the settled samples",
       "replicas' spread; the dilute reference run for gamma_ratio", true, [](const Observables& o) { return o.gamma; }, {"γ = T_1/T_2", "γ(n^*)/γ(0)"}},
      {"cumulant", {"c"}, "t, or the swept value", "the fourth cumulant c_k = 2[(3/5)<v^4>/<v^2>^2 - 1]", "the level's HCS (Sonine or converged); none in time",
       "velocity moments at the sample times", "replicas' spread", true, [](const Observables& o) { return o.cumulant; }, {"fourth cumulant c_k"}},
      {"d_ratio", {"D_ratio"}, "t, or the swept value", "D_k/D_1 (v1 Figs. 4, 5, 7)",
       "the level's D (theory/rates/diffusion.hpp, theory/grid/converged_hcs_diffusion.hpp); D_ratio_increment: MSD increments",
       "MSD increments between the first and last sample", "jackknife over replicas", true, [](const Observables& o) { return o.d_ratio; }, {"D_k/D_1"}},
      {"tamsd", {"tamsd"}, "lag", "time-averaged MSD of the tracers over [0, measurement_time] (v2)",
       "the tracer form (theory/grid/tracer_form.hpp, theory/histories/tamsd.hpp)", "tracer trajectories averaged over windows", "replicas' spread",
       true, [](const Observables& o) { return o.tamsd; }, {"TAMSD ⟨δ^2(Δ)⟩  [σ_u^2]"}},
      {"rescaled_time", {"t_s"}, "t", "the reduced time t_s = integral of sqrt(T_1/T_1(0)) dt (v1 Fig. 1)", "the level's temperature history",
       "the DSMC's own temperature history", "replicas' spread", false, [](const Observables& o) { return o.rescaled_time; }, {"rescaled time t_s  [t_u]"}},
      {"distribution", {"phi", "delta", "G"}, "v (bin centres)", "speed distributions Phi_k(v*): histograms in time (distribution.tsv), or settled with Delta_k, G_k (MG Figs. 3, 7)",
       "settled: the level's settled distribution, shell-averaged per bin (theory/levels/theory_level.hpp)",
       "speed histograms at the samples, or averaged over them when settled",
       "replicas' spread", true, [](const Observables& o) { return o.distribution_bins > 0; },
       {"speed distribution Φ_k(v^*)", "Δ_k(v^*) = (2/c_k)(Φ_k/Φ_{M,k} - 1)", "G_k(v^*) = e^{2β_kv^*/ζ^*} Φ_k"}},
  };
  return catalogue;
}

std::string axis_label(const std::string& column, bool time_unit_mg) {
  // The location columns of the tables (the catalogue's axes) and the sweep parameters.
  static const std::vector<std::pair<std::string, std::string>> locations = {
      {"t", "time t  [t_u]"},
      {"lag", "lag Δ  [t_u]"},
      {"v", "reduced speed v^* = v/v_0(t)"},
      {"eps", "restitution coefficient ε"},
      {"density", "swept number density n_k  [σ_u^{-3}]"},
      {"n_star", "reduced density n^*"},
      {"species", "species k"},
  };
  std::string label = column;
  for (const auto& [name, text] : locations)
    if (name == column) label = text;
  for (const ObservableDescriptor& d : observable_catalogue())
    for (std::size_t i = 0; i < d.quantities.size() && i < d.labels.size(); ++i)
      if (d.quantities[i] == column) label = d.labels[i];
  // [time] unit = "mg": every time column is in Montanero and Garzó's t_0 (docs/scenes.md, [time]).
  const std::size_t u = label.find("[t_u]");
  if (time_unit_mg && u != std::string::npos) label.replace(u, 5, "[t_0 = λ_{11}/v_{01}(0)]");
  return label;
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
