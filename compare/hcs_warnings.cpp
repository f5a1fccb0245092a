#include "hcs_warnings.hpp"

#include <fmt/format.h>

#include <cmath>

#include "hcs_summary.hpp"

namespace granmix::compare {

namespace {

// |c_k| above which the first-Sonine correction is not small. Φ_k = f_M[1 + (c_k/2)Δ_k] with Δ_k(0) = 15/8
// (docs/physics.md §6), so at v = 0 the correction is 15c_k/16: 47% of the Maxwellian at |c| = 0.5, and
// ⟨v⁴⟩/⟨v²⟩² = (5/3)(1 + c/2) 25% off Gaussian; MG's equations keep c only to first order. One species never gets
// there at any restitution: van Noije–Ernst's c peaks at 32/81 = 0.395 at α = 0 (§6); MG's and v1's mixtures at
// α ≥ 0.3 stay below 0.37. Beyond 0.5 the Sonine ansatz itself goes negative soon: 1 + a₂S₂ < 0 at v = 0 for c < −16/15.
constexpr double warn_c_above = 0.5;

// |c_k[order 3] − c_k[first Sonine]| above which the two orders disagree. Absolute, because c crosses zero (one species
// at α = 1/√2), where any relative change diverges (docs/physics-beyond.md §5.1). For one species order 3 is
// Brilliantov–Pöschel's second Sonine (§4.2), and 2|a₂[2] − a₂[1]| stays below 0.16 at every α (0.153 at α = 0, 0.059 at
// α = 0.3: §5.1's table): above 0.2 the mixture's truncation is larger than the one-species theory ever shows. MG's
// and v1's mixtures at α ≥ 0.3 stay below 0.14.
constexpr double warn_c_orders_apart = 0.2;

// |(T_k/T₁)[order 3] / (T_k/T₁)[first Sonine] − 1| above which the first-Sonine ratio is uncertain. The HCS Sonine
// series is asymptotic (docs/physics-beyond.md §4.4): the step to the next order estimates the error of the previous
// one. In MG's and v1's mixtures, where DSMC confirms the first Sonine (MG's γ within 0.6%, docs/physics.md §6), orders
// 1 and 3 differ by ≤ 1.4% at α = 0.5 and ≤ 3.8% at α ≥ 0.3; a 5% step flags a first-Sonine ratio off by several
// percent (v2 Fig. 5's intruder at the Santos–Dufty edge: 15% between the orders, the first Sonine's 478 18% below the
// converged 580, §5.4).
constexpr double warn_T_ratio_orders_apart = 0.05;

// Where the expansion's own reference lies: the converged HCS on request (up to its species limit), else the next order.
std::string converged_hint(const HcsSummary& h) {
  if (h.grid) return "the converged HCS (T_ratio_converged, c_converged) is the reference";
  if (h.mix.size() <= max_converged_hcs_species) return "try --converged (the HCS without the Sonine truncation)";
  return "no converged HCS above " + std::to_string(max_converged_hcs_species) + " species: compare T_ratio_sonine3, c_sonine3";
}

void add_species_warning(std::vector<HcsWarning>& out, const char* code, std::size_t k, std::string message) {
  out.push_back({code, k + 1, "species " + std::to_string(k + 1) + ": " + std::move(message)});
}

}  // namespace

std::vector<HcsWarning> hcs_warnings(const HcsSummary& h) {
  std::vector<HcsWarning> out;
  const auto& s = h.sonine;
  const std::string how = converged_hint(h);
  if (!std::isfinite(s.zeta_star)) out.push_back({"non_finite", 0, fmt::format("zeta_star = {} is not finite", s.zeta_star)});
  if (h.third_failure)
    out.push_back({"sonine3_no_steady_state", 0,
                   "no Sonine order 3 to check the first Sonine against: " + *h.third_failure + "; " + how});
  for (std::size_t k = 0; k < h.mix.size(); ++k) {
    const double T = s.T[k] / s.T[0], c = s.c[k];
    for (const auto& [name, value] : {std::pair{"T_ratio_maxwell", h.d.T[k] / h.d.T[0]}, std::pair{"T_ratio_sonine", T},
                                      std::pair{"c", c}, std::pair{"D_ratio", h.d.D_ratio[k]}})
      if (!std::isfinite(value)) add_species_warning(out, "non_finite", k, fmt::format("{} = {} is not finite", name, value));
    if (std::abs(c) > warn_c_above)
      add_species_warning(out, "c_large", k,
                          fmt::format("c = {:.4g} at first Sonine, |c| > {}: the Sonine correction is not small; {}", c, warn_c_above, how));
    if (!h.third) continue;
    const double c3 = h.third->c[k], T3 = h.third->T[k] / h.third->T[0];
    if (std::abs(c3 - c) > warn_c_orders_apart)
      add_species_warning(out, "c_orders_disagree", k,
          fmt::format("c = {:.4g} at first Sonine, {:.4g} at Sonine order 3 (apart by more than {}); {}", c, c3, warn_c_orders_apart, how));
    if (std::abs(T3 / T - 1) > warn_T_ratio_orders_apart)
      add_species_warning(out, "T_ratio_orders_disagree", k,
          fmt::format("T_ratio_sonine = {:.6g} at first Sonine, {:.6g} at Sonine order 3 ({:.3g}% apart, more than {:.3g}%); {}", T, T3,
                      100 * std::abs(T3 / T - 1), 100 * warn_T_ratio_orders_apart, how));
  }
  return out;
}

nlohmann::ordered_json hcs_warnings_json(const std::vector<HcsWarning>& warnings) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const HcsWarning& w : warnings) {
    nlohmann::ordered_json e{{"code", w.code}};
    if (w.species > 0) e["species"] = w.species;
    e["message"] = w.message;
    list.push_back(e);
  }
  return list;
}

}  // namespace granmix::compare
