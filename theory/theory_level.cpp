#include "theory_level.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "initial_state.hpp"
#include "settled_ratios.hpp"
#include "sonine2_diffusion.hpp"
#include "sonine_cooling.hpp"
#include "sonine_hcs.hpp"
#include "sonine_moment_cooling.hpp"
#include "sonine_moment_table.hpp"
#include "sonine_pair_terms.hpp"
#include "sonine_tracer.hpp"

namespace granmix::theory {

namespace {

// The papers' closure (Bodrova & Osinsky v1): Maxwellian rates, v1 Eq. (19) D.
class PaperLevel final : public TheoryLevel {
 public:
  const char* name() const override { return "paper"; }
  MsdMethod msd_method(const model::Scene& s) const override { return parse_msd_method(s.theory.msd); }
  void configure(TemperatureOptions&, const CollisionRates&) const override {}
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    return theory::diffusion_at(rates, std::move(T));
  }
  std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates,
                                           TemperatureOptions&) const override {
    return theory::initial_temperatures(init, rates);
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override { return theory::settled_temperatures(rates).T; }
  SonineHcs hcs(const CollisionRates& rates) const override { return sonine_hcs(rates.mixture(), rates.law(), rates.contact_values()); }
  TracerLimit tracer(const CollisionRates& rates) const override { return tracer_limit(rates); }
};

// The kinetic level (physics-beyond.md §2, §4): temperatures with the first-Sonine (Garzó–Dufty)
// cooling rates and cumulants relaxing from the Maxwellian start (what DSMC does); the MSD by the VACF
// ODE (transients included) with kinetic_sonine_order Sonine modes per species (SonineDecay: the first-Sonine
// decay from the start, D_k[M] in the diffusive regime, physics-beyond §3); settled states from
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
constexpr std::size_t max_sonine_species = 1000;

// The kinetic level's cooling closure: the first Sonine (a₂ relaxing; sonine_cooling.hpp), or with cooling_order 3
// a₂ and a₃ relaxing (sonine_moment_cooling.hpp) up to max_third_sonine_species, above which its pair terms (15
// polynomials per ordered pair at every new temperature set, the Krylov solver's products included) cost 33 s on
// v2 Fig. 6's 691 species against the first Sonine's 7 s. Both take their pair terms from `terms`: closed forms at
// constant ε, the quadrature over the impact speed for a viscoelastic law. z0: the initial unknowns (empty: the
// Maxwellian start).
constexpr std::size_t max_third_sonine_species = 100;
bool third_sonine_applies(const CollisionRates& rates, int cooling_order) {
  return cooling_order == 3 && rates.size() <= max_third_sonine_species;
}
std::shared_ptr<const CoolingModel> kinetic_cooling(const CollisionRates& rates, std::vector<double> z0,
                                                    std::shared_ptr<const SoninePairTerms> terms, int cooling_order) {
  if (!third_sonine_applies(rates, cooling_order))
    return std::make_shared<SonineCooling>(rates, CumulantMode::relaxing, std::move(z0), std::move(terms));
  return std::make_shared<SonineMomentCooling>(rates, sonine_moment_max, std::move(z0), std::move(terms));
}

bool dissipative(const model::Restitution& law, std::size_t k, std::size_t i) {
  return law.is_viscoelastic() ? law.akappa(k, i) > 0.0 : law.eps(k, i) < 1.0;
}

bool sonine_applies(const CollisionRates& rates) {
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
// Two variants beyond it, not the judged default (README, "Temperatures at Sonine order 3"): "kinetic-cooling3"
// (cooling_order 3: a₂ and a₃ relaxing, sonine_moment_cooling.hpp; its temperatures follow DSMC closer) and
// "kinetic-cooling3-shaped" (also the species' a₂, a₃ in the velocity modes, SonineDecay's shaped form).
class KineticLevel final : public TheoryLevel {
 public:
  KineticLevel(std::size_t order, int cooling_order = 2, bool shaped = false)
      : order_(order), cooling_order_(cooling_order), shaped_(shaped), name_(level_name(order, cooling_order, shaped)) {}
  const char* name() const override { return name_.c_str(); }
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
    // D_k[M] (physics-beyond §3); where the expansion has no diffusive solution (NaN, a
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
                      third_sonine_applies(rates, cooling_order_) ? 3 : 2);  // constant ε (a viscoelastic gas has no HCS)
  }
  TracerLimit tracer(const CollisionRates& rates) const override { return sonine_tracer_limit(rates, {true, order_}); }

 private:
  static std::string level_name(std::size_t order, int cooling_order, bool shaped) {
    const std::string base = cooling_order == 3 ? (shaped ? "kinetic-cooling3-shaped" : "kinetic-cooling3") : "kinetic";
    return order == kinetic_sonine_order ? base : base + "-sonine" + std::to_string(order);
  }
  std::size_t order_;
  int cooling_order_;
  bool shaped_;
  std::string name_;
};

}  // namespace

std::string companion_level(const std::string& level, const std::string& correction) {
  if (correction == "paper" || correction == "kinetic") return correction;
  if (correction == "cooling3") return "kinetic-cooling3";
  if (correction == "sonine1" && (level == "kinetic" || level == "kinetic-cooling3")) return level + "-sonine1";
  throw std::invalid_argument("no companion level '" + correction + "' beside the level '" + level + "'");
}

std::unique_ptr<TheoryLevel> make_theory_level(const std::string& name) {
  if (name == "paper") return std::make_unique<PaperLevel>();
  if (name == "kinetic") return std::make_unique<KineticLevel>(kinetic_sonine_order);
  if (name == "kinetic-cooling3") return std::make_unique<KineticLevel>(kinetic_sonine_order, 3);
  if (name == "kinetic-cooling3-shaped") return std::make_unique<KineticLevel>(kinetic_sonine_order, 3, true);
  for (std::size_t n = 1; n <= max_sonine_modes; ++n) {
    if (name == "kinetic-sonine" + std::to_string(n)) return std::make_unique<KineticLevel>(n);
    if (name == "kinetic-cooling3-sonine" + std::to_string(n)) return std::make_unique<KineticLevel>(n, 3);
  }
  throw std::invalid_argument("theory level '" + name + "' (allowed: paper, kinetic, kinetic-sonine1 … kinetic-sonine5, kinetic-cooling3, kinetic-cooling3-sonine1 … 5, kinetic-cooling3-shaped)");
}

}  // namespace granmix::theory
