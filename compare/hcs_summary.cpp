#include "hcs_summary.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "granmix_version.hpp"
#include "model/enskog.hpp"
#include "model/errors.hpp"
#include "model/mixture_generators.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/sonine/sonine2_diffusion.hpp"

namespace granmix::compare {

namespace {

// The converged tracer problem costs ~1 ms per species and partner (its change comes from the leading block of the
// same assembly): up to this many species (a 20-species gas, 0.5 s).
constexpr std::size_t max_converged_species = 20;

void require(bool ok, const std::string& msg) {
  if (!ok) throw InputError("hcs: " + msg);
}

model::Mixture listed_mixture(const HcsOptions& o) {
  require(!o.mass.empty() && !o.diameter.empty() && !o.density.empty(),
          "--mass, --diameter and --density are required (one value per species each)");
  require(o.mass.size() == o.diameter.size() && o.mass.size() == o.density.size(),
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
  const bool pairs = o.alpha11 || o.alpha22 || o.alpha12;
  if (!pairs) {
    require(o.alpha.has_value(), "--alpha is required with --mu --delta --w (or all of --alpha11, --alpha22, --alpha12)");
    require(*o.alpha >= 0 && *o.alpha <= 1, "--alpha must lie in [0, 1]");
    return model::Restitution::constant(2, *o.alpha);
  }
  require(!o.alpha, "give either --alpha or all of --alpha11, --alpha22, --alpha12");
  require(o.alpha11 && o.alpha22 && o.alpha12, "--alpha11, --alpha22 and --alpha12 are all required when one is given");
  for (double a : {*o.alpha11, *o.alpha22, *o.alpha12}) require(a >= 0 && a <= 1, "--alpha11/22/12 must each lie in [0, 1]");
  return model::Restitution::constant_matrix({{*o.alpha11, *o.alpha12}, {*o.alpha12, *o.alpha22}});
}

model::Mixture checked_mixture(const HcsOptions& o, bool listed, bool mg) {
  require(listed != mg, "use one form: --mass/--diameter/--density/--eps, or --mu/--delta/--w/--alpha");
  require(o.nstar >= 0 && o.nstar < 1.9, "--nstar must lie in [0, 1.9) (n σ_12³ below close packing)");
  if (listed) {
    require(o.eps.has_value(), "--eps is required (or give the MG form --mu --delta --w --alpha)");
    require(*o.eps >= 0 && *o.eps <= 1, "--eps must lie in [0, 1]");
  }
  if (mg) {
    require(o.mu && o.delta && o.w, "--mu, --delta and --w are all required in the MG form (or give --mass --diameter --density --eps)");
    require(*o.mu > 0 && *o.delta > 0 && *o.w > 0, "--mu, --delta and --w must all be positive");
  }
  return listed ? listed_mixture(o) : model::montanero_garzo_binary(*o.mu, *o.delta, *o.w, o.nstar);
}

// The options as given, in the command line's flags (without the leading "--"): what the numbers were computed from.
nlohmann::ordered_json inputs_json(const HcsOptions& o) {
  nlohmann::ordered_json j;
  if (!o.mass.empty()) j["mass"] = o.mass, j["diameter"] = o.diameter, j["density"] = o.density, j["eps"] = *o.eps;
  for (const auto& [flag, value] : {std::pair{"mu", o.mu}, std::pair{"delta", o.delta}, std::pair{"w", o.w}, std::pair{"alpha", o.alpha},
                                    std::pair{"alpha11", o.alpha11}, std::pair{"alpha22", o.alpha22}, std::pair{"alpha12", o.alpha12}})
    if (value) j[flag] = *value;
  j["nstar"] = o.nstar;
  j["converged"] = o.converged;
  return j;
}

}  // namespace

HcsSummary compute_hcs(const HcsOptions& o) {
  const bool listed = !o.mass.empty() || !o.diameter.empty() || !o.density.empty() || o.eps;
  const bool mg = o.mu || o.delta || o.w || o.alpha || o.alpha11 || o.alpha22 || o.alpha12;
  HcsSummary h(o, checked_mixture(o, listed, mg));
  const model::Mixture& mix = h.mix;
  const model::Restitution law = listed ? model::Restitution::constant(mix.size(), *o.eps) : mg_restitution(o);
  auto chi = o.nstar > 0 ? model::enskog_contact_values(mix) : model::dilute_contact_values(mix.size());
  const theory::CollisionRates rates(mix, law, chi);
  h.d = theory::settled_diffusion(rates);
  const theory::SettledDiffusion& d = h.d;
  h.sonine = theory::sonine_hcs(mix, law, chi);
  // Sonine order 3 (a₂ and a₃ of every species, the level kinetic-cooling3's HCS): the next correction of the
  // first-Sonine ratios and cumulants, up to as many species as that level carries a₃ for. Where its closure has no
  // steady shape (extreme temperature ratios) it is omitted and the reason kept for the warnings.
  if (mix.size() <= 100) try {
      h.third = theory::sonine_hcs(mix, law, chi, false, theory::SonineSolver::automatic, 3);
    } catch (const NumericalError& e) {
      h.third_failure = e.what();
    }
  h.has_tau0 = std::isfinite(d.tau0) && (listed || o.nstar > 0);
  // NaN where the second-Sonine tracer problem has no diffusive solution (sonine2_diffusion.hpp).
  h.sonine2.resize(mix.size());
  h.orders.resize(mix.size());
  for (std::size_t k = 0; k < mix.size(); ++k) {
    for (std::size_t M = 1; M <= theory::max_sonine_modes; ++M) {
      const double f = theory::sonine_factor(rates, k, d.T.data(), M);
      if (!std::isfinite(f)) break;
      h.orders[k].push_back(f);
    }
    h.sonine2[k] = h.orders[k].size() > 1 ? h.orders[k][1] : std::numeric_limits<double>::quiet_NaN();
  }
  // The same problem converged (NaN: no diffusive solution).
  h.converged.assign(mix.size(), std::numeric_limits<double>::quiet_NaN()), h.change = h.converged;
  if (mix.size() <= max_converged_species)
    for (std::size_t k = 0; k < mix.size(); ++k) {
      const theory::ConvergedDiffusion c = theory::converged_tracer_diffusion(rates, k, d.T.data());
      h.converged[k] = c.factor;
      if (std::isfinite(h.converged[k])) h.change[k] = theory::converged_diffusion_change(c);
    }
  // A binary's species 2 as a tracer (NaN where its stationary problem has no solution).
  // And at its own density, its heating of species 1 included (theory/grid/tracer_temperature.hpp).
  if (mix.size() == 2) {
    try {
      h.tracer = theory::converged_tracer_temperature(rates);
      h.intruder = theory::converged_intruder_temperature(rates, h.tracer);
    } catch (const NumericalError&) {  // the grid or the gas's rate did not settle: omitted
    }
  }
  // The HCS without the Sonine truncation, on request (theory/grid/converged_hcs.hpp).
  if (o.converged) {
    require(mix.size() <= max_converged_hcs_species, "--converged: at most " + std::to_string(max_converged_hcs_species) + " species (N² speed grids per pass; " +
                                                         std::to_string(mix.size()) + " given)");
    h.grid = theory::converged_hcs(rates, true);
  }
  // The one-species second Sonine needs a single constant restitution (not MG's per-pair alphas).
  h.eps_one = listed ? *o.eps : o.alpha.value_or(-1.0);
  if (h.eps_one >= 0) h.trunc = theory::sonine_truncation(h.eps_one);
  h.warnings = hcs_warnings(h);
  return h;
}

nlohmann::ordered_json hcs_json(const HcsSummary& h) {
  const model::Mixture& mix = h.mix;
  const auto& d = h.d;
  const auto& sonine = h.sonine;
  const auto& third = h.third;
  const auto& grid = h.grid;
  const auto& trunc = h.trunc;
  nlohmann::ordered_json j;  // keys in the order of docs/architecture.md §3
  j["species"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < mix.size(); ++k) {
    nlohmann::ordered_json s{{"T_ratio_maxwell", d.T[k] / d.T[0]},
                             {"T_ratio_sonine", sonine.T[k] / sonine.T[0]},
                             {"c", sonine.c[k]},
                             {"D_ratio", d.D_ratio[k]}};
    // 2β_k/ζ* is infinite for an elastic gas (ζ* = 0, no exponential tail): omitted, never null.
    if (std::isfinite(sonine.tail_exponent(k))) s["tail_exponent"] = sonine.tail_exponent(k);
    if (std::isfinite(h.sonine2[k])) s["D_sonine2_factor"] = h.sonine2[k];
    if (!h.orders[k].empty()) s["D_sonine_factors"] = h.orders[k];
    if (std::isfinite(h.converged[k])) s["D_converged_factor"] = h.converged[k], s["D_converged_change"] = h.change[k];
    if (trunc && mix.size() == 1) s["a2_sonine2"] = trunc->linear.a2, s["a3_sonine2"] = trunc->linear.a3;
    if (third) s["T_ratio_sonine3"] = third->T[k] / third->T[0], s["c_sonine3"] = third->c[k], s["a3_sonine3"] = third->a3[k];
    if (grid) s["T_ratio_converged"] = grid->hcs.T[k] / grid->hcs.T[0], s["c_converged"] = grid->hcs.c[k], s["a3_converged"] = grid->hcs.a3[k];
    if (k == 1 && std::isfinite(h.tracer.theta))
      s["T_ratio_tracer_converged"] = h.tracer.theta, s["T_ratio_tracer_converged_change"] = h.tracer.change;
    if (k == 1 && std::isfinite(h.intruder.theta))
      s["T_ratio_intruder_converged"] = h.intruder.theta, s["T_ratio_intruder_converged_change"] = h.intruder.change,
      s["xi12_intruder_converged"] = h.intruder.xi12;
    j["species"].push_back(s);
  }
  if (h.has_tau0) j["tau0"] = d.tau0;
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
    nlohmann::ordered_json t{{"eps", h.eps_one}, {"a2_sonine1", trunc->a2_first}, {"a2_sonine2", trunc->linear.a2}, {"a3_sonine2", trunc->linear.a3},
                             {"a3_given_a2_sonine1", trunc->a2_fixed.a3}};
    if (std::isfinite(trunc->a2_relative())) t["a2_relative_change"] = trunc->a2_relative();  // 0/0 at ε = 1
    j["one_species_truncation"] = t;
  }
  j["warnings"] = hcs_warnings_json(h.warnings);
  j["inputs"] = inputs_json(h.options);
  j["version"] = granmix::version;
  j["git_sha"] = granmix::git_sha;
  return j;
}

}  // namespace granmix::compare
