#pragma once
// The kinetic family of levels (docs/levels.md, "kinetic"): the papers' equations closed at first Sonine and beyond,
// declared in kinetic_level.cpp. The converged levels build on it (their temperatures, HCS and tracer limit).
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "theory/histories/initial_state.hpp"
#include "theory/levels/theory_level.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/sonine/sonine2_diffusion.hpp"
#include "theory/sonine/sonine_cooling.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_moment_cooling.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"
#include "theory/sonine/sonine_tracer.hpp"

namespace granmix::theory {

// The kinetic level (docs/physics-beyond.md §2, §4): temperatures with the first-Sonine (Garzó–Dufty)
// cooling rates and cumulants relaxing from the Maxwellian start (what DSMC does); the MSD by the VACF
// ODE (transients included) with kinetic_sonine_order Sonine modes per species (SonineDecay: the first-Sonine
// decay from the start, D_k[M] in the diffusive regime, docs/physics-beyond.md §3); settled states from
// the first-Sonine HCS. The pair integrals follow the restitution law (sonine_pair_terms.hpp): closed forms
// at constant ε, a quadrature over the normal impact speed for a viscoelastic law, whose cumulants then
// follow a drifting quasi-state (ε → 1 as the gas cools) and which has no HCS: its settled ratios stay the
// momentary Maxwellian ones (settled_ratios.hpp). An elastic gas keeps the Maxwellian closures (its settled
// state is the Maxwellian equilibrium, where the cumulant equations are singular), and so does a mixture
// of more than 1000 species (below).
// Above this many species the Sonine closure is not used: its cumulant system is dense N×N at every
// right-hand side, so its cost grows as N² per right-hand side (v2 Fig. 6, 691 species to t = 10: 210
// right-hand sides, 7.9 s CPU; 1000 species about twice that). There it moves T₁ by up to 0.97% at
// t = 10 (the lightest species), the model error its scenes judge with.
inline constexpr std::size_t max_sonine_species = 1000;

// The kinetic level's cooling closure: the first Sonine (a₂ relaxing; sonine_cooling.hpp), or with cooling_order 3
// a₂ and a₃ relaxing (sonine_moment_cooling.hpp) up to max_third_sonine_species, above which its pair terms (15
// polynomials per ordered pair at every new temperature set, the Krylov solver's products included) cost 33 s on
// v2 Fig. 6's 691 species against the first Sonine's 7 s. Both take their pair terms from `terms`: closed forms at
// constant ε, the quadrature over the impact speed for a viscoelastic law. z0: the initial unknowns (empty: the
// Maxwellian start).
inline constexpr std::size_t max_third_sonine_species = 100;
inline bool third_sonine_applies(const CollisionRates& rates, int cooling_order) {
  return cooling_order >= 3 && rates.size() <= max_third_sonine_species;
}
inline std::shared_ptr<const CoolingModel> kinetic_cooling(const CollisionRates& rates, std::vector<double> z0,
                                                    std::shared_ptr<const SoninePairTerms> terms, int cooling_order) {
  if (!third_sonine_applies(rates, cooling_order))
    return std::make_shared<SonineCooling>(rates, CumulantMode::relaxing, std::move(z0), std::move(terms));
  return std::make_shared<SonineMomentCooling>(rates, cooling_order, std::move(z0), std::move(terms));
}

inline bool dissipative(const model::Restitution& law, std::size_t k, std::size_t i) {
  return law.is_viscoelastic() ? law.akappa(k, i) > 0.0 : law.eps(k, i) < 1.0;
}

inline bool sonine_applies(const CollisionRates& rates) {
  if (rates.size() > max_sonine_species) return false;
  for (std::size_t k = 0; k < rates.size(); ++k)
    for (std::size_t i = k; i < rates.size(); ++i)
      if (dissipative(rates.law(), k, i)) return true;
  return false;
}

// order: the Sonine order M of D_k (the VACF modes per species). "kinetic" is M = kinetic_sonine_order;
// "kinetic-sonineN" the same level with D_k[N] — N = 1: one VACF mode at ν_k = τ_v,k⁻¹ + ζ_k/2, D_k[1]
// settled. A lower order's difference to the kinetic level is the size of its last Sonine corrections
// (a scene's correction_from = "sonineN").
// Two variants beyond it, not the judged default (docs/levels.md, "Temperatures at Sonine order 3"): "kinetic-cooling3"
// (cooling_order 3: a₂ and a₃ relaxing, sonine_moment_cooling.hpp; its temperatures follow DSMC closer) and
// "kinetic-cooling3-shaped" (also the species' a₂, a₃ in the velocity modes, SonineDecay's shaped form).
class KineticLevel final : public TheoryLevel {
 public:
  KineticLevel(std::size_t order, int cooling_order = 2, bool shaped = false)
      : order_(order), cooling_order_(cooling_order), shaped_(shaped) {}
  MsdMethod msd_method(const model::Scene&) const override { return MsdMethod::vacf; }
  void configure(TemperatureOptions& opt, const CollisionRates& rates) const override {
    if (!sonine_applies(rates)) return;
    // One set of pair terms for both closures: a viscoelastic law's ε at the impact speeds is evaluated once
    // per pair and right-hand side.
    const std::shared_ptr<const SoninePairTerms> terms = make_sonine_pair_terms(rates.law());
    opt.cooling = kinetic_cooling(rates, {}, terms, cooling_order_);
    if (order_ > 1) opt.decay = std::make_shared<SonineDecay>(rates, order_, terms, shaped_);
  }
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    SettledDiffusion d = theory::diffusion_at(rates, T);
    if (!sonine_applies(rates) || order_ < 2) return d;
    // D_k[M] (docs/physics-beyond.md §3); where the expansion has no diffusive solution (NaN, a
    // large rare grain near the Santos–Dufty edge) the first-Sonine D stays.
    for (std::size_t k = 0; k < T.size(); ++k) {
      const double f = sonine_factor(rates, k, T.data(), order_);
      if (std::isfinite(f)) d.D[k] *= f, d.tau_v[k] *= f;  // τ_v = D m/T: the memory of the MSD's closed form
    }
    for (std::size_t k = 0; k < T.size(); ++k) d.D_ratio[k] = d.D[k] / d.D[0];
    // τ₀ = 2/ξ with the first-Sonine rate at the steady cumulants of these temperatures.
    std::vector<double> xi(T.size());
    SonineCooling(rates, CumulantMode::quasi_static).rates(T.data(), nullptr, xi.data(), nullptr);
    d.tau0 = xi[0] > 0.0 ? 2.0 / xi[0] : std::numeric_limits<double>::infinity();
    return d;
  }
  // The DSMC ages its gas with the true collisions: its aged start has the settled cumulants, which the
  // relaxing Sonine model then starts from. The other starts are Maxwellian in DSMC too.
  std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates,
                                           TemperatureOptions& opt) const override {
    if (init.kind != model::InitialState::Kind::aged || !sonine_applies(rates)) return theory::initial_temperatures(init, rates);
    const AgedState a = aged_state(init.T_hot, rates, opt);
    opt.cooling = kinetic_cooling(rates, a.z, make_sonine_pair_terms(rates.law()), cooling_order_);
    return a.T;
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override {
    if (!sonine_applies(rates) || rates.law().is_viscoelastic()) return theory::settled_temperatures(rates).T;
    return hcs(rates).T;  // Σ x_k T_k = ⟨T⟩ = 1
  }
  SonineHcs hcs(const CollisionRates& rates) const override {
    return sonine_hcs(rates.mixture(), rates.law(), rates.contact_values(), false, SonineSolver::automatic,
                      third_sonine_applies(rates, cooling_order_) ? cooling_order_ : 2);  // constant ε (a viscoelastic gas has no HCS)
  }
  TracerLimit tracer(const CollisionRates& rates) const override { return sonine_tracer_limit(rates, {true, order_}); }

 // The family's naming rule (level_catalogue.hpp): kinetic, kinetic-cooling3[-shaped], kinetic-cooling4, then
  // "-sonineN" where D is not at kinetic_sonine_order.
  static std::string level_name(std::size_t order, int cooling_order, bool shaped) {
    const std::string base = cooling_order == 4 ? "kinetic-cooling4" : cooling_order == 3 ? (shaped ? "kinetic-cooling3-shaped" : "kinetic-cooling3") : "kinetic";
    return order == kinetic_sonine_order ? base : base + "-sonine" + std::to_string(order);
  }

 private:
  std::size_t order_;
  int cooling_order_;
  bool shaped_;
};

}  // namespace granmix::theory
