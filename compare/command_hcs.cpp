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
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "commands.hpp"
#include "model/enskog.hpp"
#include "model/errors.hpp"
#include "model/mixture_generators.hpp"
#include "theory/grid/converged_hcs.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/sonine/sonine2_diffusion.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_truncation.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/grid/tracer_temperature.hpp"

namespace granmix::compare {

namespace {

// The converged tracer problem costs ~1 ms per species and partner (its change comes from the leading block of the
// same assembly): up to this many species (a 20-species gas, 0.5 s).
constexpr std::size_t max_converged_species = 20;
// The converged HCS: N² pair grids per pass, ~25 ms each.
constexpr std::size_t max_converged_hcs_species = 10;

struct HcsOptions {
  std::vector<double> mass, diameter, density;
  double eps = -1.0, nstar = 0.0;
  double mu = 0, delta = 0, w = 0, alpha = -1, alpha11 = -1, alpha22 = -1, alpha12 = -1;
  bool json = false, converged = false;
};

void require(bool ok, const std::string& msg) {
  if (!ok) throw InputError("hcs: " + msg);
}

model::Mixture listed_mixture(const HcsOptions& o) {
  require(!o.mass.empty() && o.mass.size() == o.diameter.size() && o.mass.size() == o.density.size(),
          "--mass, --diameter and --density need one value per species each");
  std::vector<model::Species> s;
  for (std::size_t k = 0; k < o.mass.size(); ++k) {
    require(o.mass[k] > 0 && o.diameter[k] > 0 && o.density[k] > 0,
            "species " + std::to_string(k + 1) + ": mass, diameter and density must be positive");
    s.push_back({o.mass[k], o.diameter[k], o.density[k]});
  }
  model::Mixture mix(std::move(s));
  if (o.nstar > 0) mix = model::with_reduced_density(mix, o.nstar);
  return mix;
}

model::Restitution mg_restitution(const HcsOptions& o) {
  const bool pairs = o.alpha11 >= 0 || o.alpha22 >= 0 || o.alpha12 >= 0;
  if (!pairs) {
    require(o.alpha >= 0 && o.alpha <= 1, "--alpha must lie in [0, 1]");
    return model::Restitution::constant(2, o.alpha);
  }
  require(o.alpha < 0, "give either --alpha or all of --alpha11, --alpha22, --alpha12");
  for (double a : {o.alpha11, o.alpha22, o.alpha12}) require(a >= 0 && a <= 1, "--alpha11/22/12 must each lie in [0, 1]");
  return model::Restitution::constant_matrix({{o.alpha11, o.alpha12}, {o.alpha12, o.alpha22}});
}

int run(const HcsOptions& o) {
  const bool listed = !o.mass.empty() || !o.diameter.empty() || !o.density.empty();
  const bool mg = o.mu > 0 || o.delta > 0 || o.w > 0;
  require(listed != mg, "use one form: --mass/--diameter/--density/--eps, or --mu/--delta/--w/--alpha");
  require(o.nstar >= 0 && o.nstar < 1.9, "--nstar must lie in [0, 1.9) (n σ_12³ below close packing)");
  if (listed) require(o.eps >= 0 && o.eps <= 1, "--eps must lie in [0, 1]");
  if (mg) require(o.mu > 0 && o.delta > 0 && o.w > 0, "--mu, --delta and --w must all be positive");
  const model::Mixture mix = listed ? listed_mixture(o) : model::montanero_garzo_binary(o.mu, o.delta, o.w, o.nstar);
  const model::Restitution law = listed ? model::Restitution::constant(mix.size(), o.eps) : mg_restitution(o);
  auto chi = o.nstar > 0 ? model::enskog_contact_values(mix) : model::dilute_contact_values(mix.size());
  const theory::CollisionRates rates(mix, law, chi);
  const theory::SettledDiffusion d = theory::settled_diffusion(rates);
  const theory::SonineHcs sonine = theory::sonine_hcs(mix, law, chi);
  // Sonine order 3 (a₂ and a₃ of every species, the level kinetic-cooling3's HCS): the next correction of the
  // first-Sonine ratios and cumulants, up to as many species as that level carries a₃ for.
  std::optional<theory::SonineHcs> third;
  if (mix.size() <= 100) third = theory::sonine_hcs(mix, law, chi, false, theory::SonineSolver::automatic, 3);
  // τ₀ needs an absolute density: it is omitted for the dilute MG form and for a gas that does not cool.
  const bool has_tau0 = std::isfinite(d.tau0) && (listed || o.nstar > 0);
  // NaN where the second-Sonine tracer problem has no diffusive solution (sonine2_diffusion.hpp).
  std::vector<double> sonine2(mix.size());
  std::vector<std::vector<double>> orders(mix.size());
  for (std::size_t k = 0; k < mix.size(); ++k) {
    for (std::size_t M = 1; M <= theory::max_sonine_modes; ++M) {
      const double f = theory::sonine_factor(rates, k, d.T.data(), M);
      if (!std::isfinite(f)) break;
      orders[k].push_back(f);
    }
    sonine2[k] = orders[k].size() > 1 ? orders[k][1] : std::numeric_limits<double>::quiet_NaN();
  }
  // The same problem converged (NaN: no diffusive solution).
  std::vector<double> converged(mix.size(), std::numeric_limits<double>::quiet_NaN()), change = converged;
  if (mix.size() <= max_converged_species)
    for (std::size_t k = 0; k < mix.size(); ++k) {
      const theory::ConvergedDiffusion c = theory::converged_tracer_diffusion(rates, k, d.T.data());
      converged[k] = c.factor;
      if (std::isfinite(converged[k])) change[k] = theory::converged_diffusion_change(c);
    }
  // A binary's species 2 as a tracer (NaN where its stationary problem has no solution).
  // And at its own density, its heating of species 1 included (theory/grid/tracer_temperature.hpp).
  theory::TracerTemperature tracer, intruder;
  if (mix.size() == 2) {
    try {
      tracer = theory::converged_tracer_temperature(rates);
      intruder = theory::converged_intruder_temperature(rates, tracer);
    } catch (const NumericalError&) {  // the grid or the gas's rate did not settle: omitted
    }
  }
  // The HCS without the Sonine truncation, on request (theory/grid/converged_hcs.hpp).
  std::optional<theory::ConvergedHcs> grid;
  if (o.converged) {
    require(mix.size() <= max_converged_hcs_species, "--converged: at most " + std::to_string(max_converged_hcs_species) + " species (N² speed grids per pass; " +
                                                         std::to_string(mix.size()) + " given)");
    grid = theory::converged_hcs(rates, true);
  }
  // The one-species second Sonine needs a single constant restitution (not MG's per-pair alphas).
  const double eps_one = listed ? o.eps : o.alpha;
  std::optional<theory::SonineTruncation> trunc;
  if (eps_one >= 0) trunc = theory::sonine_truncation(eps_one);
  if (o.json) {
    nlohmann::ordered_json j;  // keys in the order of docs/architecture.md §3
    j["species"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < mix.size(); ++k) {
      nlohmann::ordered_json s{{"T_ratio_maxwell", d.T[k] / d.T[0]},
                               {"T_ratio_sonine", sonine.T[k] / sonine.T[0]},
                               {"c", sonine.c[k]},
                               {"D_ratio", d.D_ratio[k]}};
      // 2β_k/ζ* is infinite for an elastic gas (ζ* = 0, no exponential tail): omitted, never null.
      if (std::isfinite(sonine.tail_exponent(k))) s["tail_exponent"] = sonine.tail_exponent(k);
      if (std::isfinite(sonine2[k])) s["D_sonine2_factor"] = sonine2[k];
      if (!orders[k].empty()) s["D_sonine_factors"] = orders[k];
      if (std::isfinite(converged[k])) s["D_converged_factor"] = converged[k], s["D_converged_change"] = change[k];
      if (trunc && mix.size() == 1) s["a2_sonine2"] = trunc->linear.a2, s["a3_sonine2"] = trunc->linear.a3;
      if (third) s["T_ratio_sonine3"] = third->T[k] / third->T[0], s["c_sonine3"] = third->c[k], s["a3_sonine3"] = third->a3[k];
      if (grid) s["T_ratio_converged"] = grid->hcs.T[k] / grid->hcs.T[0], s["c_converged"] = grid->hcs.c[k], s["a3_converged"] = grid->hcs.a3[k];
      if (k == 1 && std::isfinite(tracer.theta))
        s["T_ratio_tracer_converged"] = tracer.theta, s["T_ratio_tracer_converged_change"] = tracer.change;
      if (k == 1 && std::isfinite(intruder.theta))
        s["T_ratio_intruder_converged"] = intruder.theta, s["T_ratio_intruder_converged_change"] = intruder.change,
        s["xi12_intruder_converged"] = intruder.xi12;
      j["species"].push_back(s);
    }
    if (has_tau0) j["tau0"] = d.tau0;
    j["zeta_star"] = sonine.zeta_star;
    if (third) j["zeta_star_sonine3"] = third->zeta_star;
    if (grid) {
      j["zeta_star_converged"] = grid->hcs.zeta_star;
      nlohmann::ordered_json e{{"T_ratio", grid->grid_change.T + grid->partner_truncation.T}};
      const double c_error = grid->grid_change.a2 + grid->partner_truncation.a2;  // relative: not finite where a c is exactly 0
      if (std::isfinite(c_error)) e["c"] = c_error;
      j["converged_error"] = e;
      j["converged_passes"] = grid->passes;
    }
    if (trunc && mix.size() > 1) {
      nlohmann::ordered_json t{{"eps", eps_one}, {"a2_sonine1", trunc->a2_first}, {"a2_sonine2", trunc->linear.a2}, {"a3_sonine2", trunc->linear.a3},
                               {"a3_given_a2_sonine1", trunc->a2_fixed.a3}};
      if (std::isfinite(trunc->a2_relative())) t["a2_relative_change"] = trunc->a2_relative();  // 0/0 at ε = 1
      j["one_species_truncation"] = t;
    }
    std::printf("%s\n", j.dump().c_str());
    return 0;
  }
  std::printf("%-8s %-12s %-12s %-12s %-21s %-21s %-21s %-21s %-12s %-16s\n", "species", "mass", "diameter", "density",
              "T_ratio_maxwell", "T_ratio_sonine", "c", "D_ratio", "tail_exponent", "D_sonine2_factor");
  for (std::size_t k = 0; k < mix.size(); ++k)
    std::printf("%-8zu %-12.8g %-12.8g %-12.8g %-21.17g %-21.17g %-21.17g %-21.17g %-12.8g %-16s\n", k + 1, mix[k].mass, mix[k].diameter,
                mix[k].density, d.T[k] / d.T[0], sonine.T[k] / sonine.T[0], sonine.c[k], d.D_ratio[k], sonine.tail_exponent(k),
                std::isfinite(sonine2[k]) ? fmt::format("{:.8g}", sonine2[k]).c_str() : "-");
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
  if (std::isfinite(tracer.theta))
    std::printf("species 2 as a tracer in species 1, converged: T_ratio %.10g (a2 %.6g, a3 %.6g; change with a step 3/2 as long %.3g)\n",
                tracer.theta, tracer.a2, tracer.a3, tracer.change);
  if (std::isfinite(intruder.theta))
    std::printf("species 2 at its density, heating species 1 (xi12 %.6g), converged: T_ratio %.10g (a2 %.6g; change %.3g)\n", intruder.xi12,
                intruder.theta, intruder.a2, intruder.change);
  if (trunc)
    std::printf("second Sonine, one species at eps = %.8g%s: a2[1] = %.10g  a2[2] = %.10g  a3[2] = %.10g  |a2[2]-a2[1]|/|a2[1]| = %.6g\n",
                eps_one, mix.size() > 1 ? " (one-species proxy)" : "", trunc->a2_first, trunc->linear.a2, trunc->linear.a3, trunc->a2_relative());
  if (has_tau0)
    std::printf("tau0 = %.17g   (Haff time 2/xi at <T> = 1)\n", d.tau0);
  else
    std::printf("tau0 not given (%s)\n", std::isfinite(d.tau0) ? "dilute MG form: no absolute density" : "no cooling");
  return 0;
}

}  // namespace

std::function<int()> add_hcs_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("hcs", "settled (HCS) temperature ratios, diffusion ratios and τ0 of a mixture");
  auto o = std::make_shared<HcsOptions>();
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
  cmd->add_flag("--json", o->json, "one JSON object on stdout");
  cmd->add_flag("--converged", o->converged, "also the HCS without the Sonine truncation (~0.1-1 s for a binary)");
  return [o]() { return run(*o); };
}

}  // namespace granmix::compare
