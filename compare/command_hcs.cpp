// granmix hcs: the settled (HCS) state of a mixture (docs/architecture.md §3), in two forms:
//   --mass m1,m2,… --diameter … --density … --eps E [--nstar N] [--json]
//   --mu μ --delta δ --w w --alpha α [--alpha11 --alpha22 --alpha12] [--nstar N] [--json]
// Fields: T_ratio_maxwell (v1 Eq. A2), T_ratio_sonine and c (first-Sonine, MG App. A, any number of
// species), D_ratio (v1 Eq. 19), tail_exponent 2β_k/ζ* (MG Eqs. 20, 30), D_sonine2_factor = D_k[2]/D_k[1]
// (second-Sonine tracer diffusion at the settled Maxwellian ratios, docs/physics-beyond.md §3) and
// D_sonine_factors = [D_k[1]/D_k[1], …, D_k[5]/D_k[1]] (the Sonine orders 1–5, up to the first without a
// diffusive solution; the kinetic level uses order 4), D_converged_factor = D_k/D_k[1] of the same tracer problem
// solved without the Sonine truncation and D_converged_change, its change from one basis function fewer
// (theory/grid/tracer_diffusion_galerkin.hpp; up to max_converged_species species, ~1 ms per species and partner),
// T_ratio_tracer_converged (binaries: species 2 as an intruder in species 1's own HCS, its stationary distribution
// without the Sonine truncation on a speed grid, theory/grid/tracer_temperature.hpp) and T_ratio_tracer_converged_change
// (the grid's own estimate: a step 3/2 as long), T_ratio_intruder_converged with its _change and
// xi12_intruder_converged (the same at species 2's own density, its heating of species 1 self-consistent), tau0 = 2/ξ
// at ⟨T⟩ = 1, zeta_star in MG units. With one constant restitution (--eps, or MG's --alpha) also the
// one-species second Sonine HCS (theory/sonine/sonine_truncation.hpp), the computed truncation estimate of the
// first-Sonine c: for one species a2_sonine2, a3_sonine2 in its species object; for a mixture the top-level
// "one_species_truncation" {eps, a2_sonine1, a2_sonine2, a3_sonine2, a3_given_a2_sonine1, a2_relative_change} of one species at
// that ε (a proxy for near-equal species, not a mixture calculation). Fields that cannot be computed are
// omitted, never filled. With --converged (up to max_converged_hcs_species species) also the HCS without the Sonine
// truncation (theory/grid/converged_hcs.hpp, ~1 s for a binary, ~4 s with its error estimate): per species
// T_ratio_converged, c_converged, a3_converged; zeta_star_converged; converged_error {T_ratio, c} (the grid's and the
// partners' truncation, summed: relative, the largest over the species) and converged_passes.
// Then "warnings" (where the first Sonine breaks down, hcs_warnings.hpp: in the text form one line each on stderr),
// "inputs" (the options as given), "version" and "git_sha".
// The computation and the JSON object live in hcs_summary.hpp, shared with the Python module's granmix.hcs.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>

#include "commands.hpp"
#include "hcs_summary.hpp"

namespace granmix::compare {

namespace {

struct HcsCommand {
  HcsOptions hcs;
  bool json = false;
};

// What `granmix hcs --help` lists under its options (the full meanings: docs/user-guide.md, "granmix hcs").
constexpr const char* output_fields =
    "Output (docs/user-guide.md, \"granmix hcs\"; ratios relative to species 1):\n"
    "  text columns: species mass diameter density T_ratio_maxwell T_ratio_sonine c D_ratio tail_exponent D_sonine2_factor;\n"
    "    then zeta_star, Sonine order 3, the converged HCS (--converged), a binary's tracer and intruder, the one-species\n"
    "    second Sonine, tau0; warnings on stderr, one line each: \"granmix: warning: hcs [code] species k: ...\"\n"
    "  --json keys: species [{T_ratio_maxwell, T_ratio_sonine, c, D_ratio, tail_exponent, D_sonine2_factor,\n"
    "    D_sonine_factors, D_converged_factor, D_converged_change, T_ratio_sonine3, c_sonine3, a3_sonine3, ...}], tau0,\n"
    "    zeta_star, zeta_star_sonine3, one_species_truncation, (--converged) zeta_star_converged, converged_error,\n"
    "    converged_passes; warnings [{code, species, message}], inputs, version, git_sha\n"
    "  warning codes: c_large, c_orders_disagree, T_ratio_orders_disagree, sonine3_no_steady_state, non_finite\n"
    "    (exit code 0: the numbers are printed, the warning says where the first Sonine is not to be trusted)";

int run(const HcsCommand& command) {
  const HcsSummary h = compute_hcs(command.hcs);
  if (command.json) {
    std::printf("%s\n", hcs_json(h).dump().c_str());
    return 0;
  }
  const model::Mixture& mix = h.mix;
  const auto& d = h.d;
  const auto& sonine = h.sonine;
  const auto& third = h.third;
  const auto& grid = h.grid;
  const auto& trunc = h.trunc;
  std::printf("%-8s %-12s %-12s %-12s %-21s %-21s %-21s %-21s %-12s %-16s\n", "species", "mass", "diameter", "density",
              "T_ratio_maxwell", "T_ratio_sonine", "c", "D_ratio", "tail_exponent", "D_sonine2_factor");
  for (std::size_t k = 0; k < mix.size(); ++k)
    std::printf("%-8zu %-12.8g %-12.8g %-12.8g %-21.17g %-21.17g %-21.17g %-21.17g %-12.8g %-16s\n", k + 1, mix[k].mass, mix[k].diameter,
                mix[k].density, d.T[k] / d.T[0], sonine.T[k] / sonine.T[0], sonine.c[k], d.D_ratio[k], sonine.tail_exponent(k),
                std::isfinite(h.sonine2[k]) ? fmt::format("{:.8g}", h.sonine2[k]).c_str() : "-");
  std::printf("zeta_star = %.17g   (first-Sonine reduced cooling rate, MG units n sigma12^2 v0)\n", sonine.zeta_star);
  if (third) {
    std::printf("Sonine order 3 (a2, a3 per species):");
    for (std::size_t k = 0; k < mix.size(); ++k)
      std::printf("  %zu: T_ratio %.10g c %.8g a3 %.8g", k + 1, third->T[k] / third->T[0], third->c[k], third->a3[k]);
    std::printf("  zeta_star %.12g\n", third->zeta_star);
  }
  if (grid) {
    std::printf("converged HCS (no Sonine truncation of the species' own distributions):");
    for (std::size_t k = 0; k < mix.size(); ++k)
      std::printf("  %zu: T_ratio %.10g c %.8g a3 %.8g", k + 1, grid->hcs.T[k] / grid->hcs.T[0], grid->hcs.c[k], grid->hcs.a3[k]);
    std::printf("  zeta_star %.12g; relative error T_ratio %.2g, c %.2g (grid + partners' truncation)\n", grid->hcs.zeta_star,
                grid->grid_change.T + grid->partner_truncation.T, grid->grid_change.a2 + grid->partner_truncation.a2);
  }
  if (std::isfinite(h.tracer.theta))
    std::printf("species 2 as a tracer in species 1, converged: T_ratio %.10g (a2 %.6g, a3 %.6g; change with a step 3/2 as long %.3g)\n",
                h.tracer.theta, h.tracer.a2, h.tracer.a3, h.tracer.change);
  if (std::isfinite(h.intruder.theta))
    std::printf("species 2 at its density, heating species 1 (xi12 %.6g), converged: T_ratio %.10g (a2 %.6g; change %.3g)\n", h.intruder.xi12,
                h.intruder.theta, h.intruder.a2, h.intruder.change);
  if (trunc)
    std::printf("second Sonine, one species at eps = %.8g%s: a2[1] = %.10g  a2[2] = %.10g  a3[2] = %.10g  |a2[2]-a2[1]|/|a2[1]| = %.6g\n",
                h.eps_one, mix.size() > 1 ? " (one-species proxy)" : "", trunc->a2_first, trunc->linear.a2, trunc->linear.a3, trunc->a2_relative());
  if (h.has_tau0)
    std::printf("tau0 = %.17g   (Haff time 2/xi at <T> = 1)\n", d.tau0);
  else
    std::printf("tau0 not given (%s)\n", std::isfinite(d.tau0) ? "dilute MG form: no absolute density" : "no cooling");
  // In the JSON the warnings are its "warnings" list; in the text form they go to stderr, after the table.
  std::fflush(stdout);
  for (const HcsWarning& w : h.warnings) std::fprintf(stderr, "granmix: warning: hcs [%s] %s\n", w.code.c_str(), w.message.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_hcs_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("hcs", "settled (HCS) temperature ratios, diffusion ratios and τ0 of a mixture");
  auto c = std::make_shared<HcsCommand>();
  HcsOptions* o = &c->hcs;
  cmd->add_option("--mass", o->mass, "masses m1,m2,…")->delimiter(',');
  cmd->add_option("--diameter", o->diameter, "diameters σ1,σ2,…")->delimiter(',');
  cmd->add_option("--density", o->density, "number densities n1,n2,…")->delimiter(',');
  cmd->add_option("--eps", o->eps, "restitution coefficient (all pairs)");
  cmd->add_option("--mu", o->mu, "MG mass ratio m1/m2");
  cmd->add_option("--delta", o->delta, "MG concentration ratio n1/n2");
  cmd->add_option("--w", o->w, "MG size ratio σ11/σ22");
  cmd->add_option("--alpha", o->alpha, "MG restitution coefficient (all pairs)");
  cmd->add_option("--alpha11", o->alpha11, "MG restitution 1-1");
  cmd->add_option("--alpha22", o->alpha22, "MG restitution 2-2");
  cmd->add_option("--alpha12", o->alpha12, "MG restitution 1-2");
  cmd->add_option("--nstar", o->nstar, "reduced density n σ12³ (Enskog χ from MG Eq. 26); 0 = dilute");
  cmd->add_flag("--json", c->json, "one JSON object on stdout");
  cmd->add_flag("--converged", o->converged, "also the HCS without the Sonine truncation (~0.1-1 s for a binary)");
  cmd->footer(output_fields);
  return [c]() { return run(*c); };
}

}  // namespace granmix::compare
