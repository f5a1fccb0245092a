#include "theory_level.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "converged_hcs.hpp"
#include "converged_hcs_diffusion.hpp"
#include "initial_state.hpp"
#include "settled_ratios.hpp"
#include "shell_average.hpp"
#include "sonine2_diffusion.hpp"
#include "sonine_cooling.hpp"
#include "sonine_hcs.hpp"
#include "sonine_moment_cooling.hpp"
#include "sonine_moment_table.hpp"
#include "sonine_pair_terms.hpp"
#include "sonine_tracer.hpp"
#include "speed_grid_cooling.hpp"
#include "galerkin_decay.hpp"
#include "parallel_each.hpp"
#include "tracer_diffusion_galerkin.hpp"
#include "tracer_temperature.hpp"
#include "model/errors.hpp"

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
  return cooling_order >= 3 && rates.size() <= max_third_sonine_species;
}
std::shared_ptr<const CoolingModel> kinetic_cooling(const CollisionRates& rates, std::vector<double> z0,
                                                    std::shared_ptr<const SoninePairTerms> terms, int cooling_order) {
  if (!third_sonine_applies(rates, cooling_order))
    return std::make_shared<SonineCooling>(rates, CumulantMode::relaxing, std::move(z0), std::move(terms));
  return std::make_shared<SonineMomentCooling>(rates, cooling_order, std::move(z0), std::move(terms));
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
                      third_sonine_applies(rates, cooling_order_) ? cooling_order_ : 2);  // constant ε (a viscoelastic gas has no HCS)
  }
  TracerLimit tracer(const CollisionRates& rates) const override { return sonine_tracer_limit(rates, {true, order_}); }

 private:
  static std::string level_name(std::size_t order, int cooling_order, bool shaped) {
    const std::string base = cooling_order == 4 ? "kinetic-cooling4" : cooling_order == 3 ? (shaped ? "kinetic-cooling3-shaped" : "kinetic-cooling3") : "kinetic";
    return order == kinetic_sonine_order ? base : base + "-sonine" + std::to_string(order);
  }
  std::size_t order_;
  int cooling_order_;
  bool shaped_;
  std::string name_;
};

// "kinetic-hcs-converged": the kinetic level whose homogeneous cooling state (γ, c_k, the settled T_k) is solved
// without the Sonine truncation of the species' own distributions (converged_hcs.hpp); everything in time is the kinetic
// level's. Why: the HCS Sonine series is asymptotic — over MG Figs. 4–5's 18 DSMC points (mean of three paper seeds)
// orders 2/3/4 swing by 0.3–0.7% at α ≤ 0.5 and the first Sonine is within 0.3% at 15 of them; the converged state is
// within 0.27% at all 18, and MG Fig. 2's c_k 10–12% below the first Sonine at α = 0.3, as DSMC (README, "The converged
// HCS"). Constant restitution only (a viscoelastic gas has no HCS).
// Its settled distributions Φ_k are the solved speed densities themselves, no Sonine form at all (MG Figs. 3, 7), solved
// with a finer collision rule and every partner through its full solved density (converged_distribution: why); their
// model error is computed per bin by four companions from that solve — "-knots" (knots 3/2 as far apart), "-rule" (the
// coarser rule), "-partners" (the partners' rests taken finer), "-domain" (the grid 9/7 as wide) — and the level's own
// elastic-limit error (elastic_bin_error).
class HcsConvergedLevel final : public TheoryLevel {
 public:
  explicit HcsConvergedLevel(DistributionVariant variant = DistributionVariant::solved) : variant_(variant) {}
  const char* name() const override {
    switch (variant_) {
      case DistributionVariant::sparser_knots: return "kinetic-hcs-converged-knots";
      case DistributionVariant::coarser_rule: return "kinetic-hcs-converged-rule";
      case DistributionVariant::partners_finer: return "kinetic-hcs-converged-partners";
      case DistributionVariant::wider_domain: return "kinetic-hcs-converged-domain";
      case DistributionVariant::solved: break;
    }
    return "kinetic-hcs-converged";
  }
  MsdMethod msd_method(const model::Scene& s) const override { return base_.msd_method(s); }
  void configure(TemperatureOptions& opt, const CollisionRates& rates) const override { base_.configure(opt, rates); }
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override { return base_.diffusion_at(rates, std::move(T)); }
  std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates, TemperatureOptions& opt) const override {
    return base_.initial_temperatures(init, rates, opt);
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override {
    return rates.law().is_viscoelastic() ? base_.settled_temperatures(rates) : hcs(rates).T;
  }
  // The companions' HCS is their distributions' state; the level's own the converged HCS (its 12-point rule and Sonine
  // partners, their truncation its computed model error; the distributions take panels and full partners).
  SonineHcs hcs(const CollisionRates& rates) const override {
    return variant_ == DistributionVariant::solved ? converged_hcs(rates).hcs : converged_distribution(rates, variant_).hcs;
  }
  SettledDistribution settled_distribution(const CollisionRates& rates) const override {
    SettledHcs s = converged_distribution(rates, variant_);
    SettledDistribution d{s.hcs, {}, {}};
    if (variant_ == DistributionVariant::solved) d.bin_error = elastic_bin_error(rates, s.hcs.lambda);
    d.phi = [density = std::move(s.density)](std::size_t k, double v) { return density[k].phi(v); };
    return d;
  }
  TracerLimit tracer(const CollisionRates& rates) const override { return base_.tracer(rates); }
  std::unique_ptr<TracerForm> tracer_form(const CollisionRates& rates, double t_end) const override { return base_.tracer_form(rates, t_end); }

 private:
  // The grid's error where the answer is known: the same mixture elastic, whose settled Φ_k is the Maxwellian, solved
  // by the same grid; its relative error over the same bin in thermal widths (λ_k: the inelastic state's). Why: the
  // variants' changes (knots, rule) under-estimate the grid's pointwise error up to ~3× in places — the elastic MG
  // Fig. 3 mixture's bins of 0.05 err by 0.05–0.5% between one and two thermal widths where the variants move them by
  // 0.02–0.3% (measured 2026-12-05) — so both parts enter the model error.
  static std::function<double(std::size_t, double, double)> elastic_bin_error(const CollisionRates& rates, std::vector<double> lambda) {
    const CollisionRates elastic(rates.mixture(), model::Restitution::constant(rates.size(), 1.0), rates.contact_values());
    return [e = converged_distribution(elastic, DistributionVariant::solved), lambda = std::move(lambda)](std::size_t k, double lo, double hi) {
      const double scale = std::sqrt(lambda[k] / e.hcs.lambda[k]);  // v* here ↦ the same thermal widths there
      const double grid = shell_average([&](double v) { return e.density[k].phi(v); }, scale * lo, scale * hi);
      const double exact = shell_average([&](double v) { return maxwellian_phi(e.hcs.lambda[k], v); }, scale * lo, scale * hi);
      return std::abs(grid / exact - 1.0);
    };
  }
  KineticLevel base_{kinetic_sonine_order};
  DistributionVariant variant_;
};

// The converged levels' basis companion (kinetic-converged-grid's, kinetic-converged-cooling3's): the tracer problem with
// this many functions (the level's 8). v1 Fig. 2's MSDs move by ≤ 4.2e-4 from 8 to 10 functions (1.0e-4 from 8 to 7;
// measured 2026-12-05).
constexpr std::size_t companion_basis = 10;

// A velocity decay given the species' a₂ alone (its a₃ withheld: in the tracer's source and in its partners), for
// kinetic-converged-grid-a2, the companion that measures the a₃ term's size.
class WithoutThirdSonine final : public VelocityDecay {
 public:
  explicit WithoutThirdSonine(std::shared_ptr<const VelocityDecay> decay) : decay_(std::move(decay)) {}
  void rates(const double* T, const double* xi, double* nu) const override { decay_->rates(T, xi, nu); }
  std::size_t modes() const override { return decay_->modes(); }
  bool uses_sonine_coefficients() const override { return decay_->uses_sonine_coefficients(); }
  void correlation_rates(const CollisionRates& r, const double* T, const double* xi, const double* Q, double* dQ, double* nu, const double* a2,
                         const double*) const override {
    decay_->correlation_rates(r, T, xi, Q, dQ, nu, a2, nullptr);
  }
  bool offers_correlation_jacobian() const override { return decay_->offers_correlation_jacobian(); }
  void correlation_jacobian_times(const double* v, double* Jv) const override { decay_->correlation_jacobian_times(v, Jv); }

 private:
  std::shared_ptr<const VelocityDecay> decay_;
};

// "kinetic-converged" (cooling_order 2) and "kinetic-converged-cooling3" (3; 4 and a basis of 10 for its companions,
// companion_level): the kinetic level with the tracer problem
// solved without the Sonine truncation (tracer_diffusion_galerkin.hpp): the species' own a's in its velocity
// distribution, the partners' in the collision operator, the level's cooling rate ζ_k in the scaling term.
// Sweeps: D_k and the velocity memory at the kinetic level's settled state (its HCS: T_k and a₂, with cooling_order 3
// also a₃), the MSD increments the closed form of that memory (velocity_memory.hpp). Histories: the VACF ODE with
// the same Galerkin problem following T(t), a₂(t), a₃(t) (GalerkinDecay, galerkin_decay.hpp), from the kinetic
// level's start, for constant and viscoelastic restitution (sweeps: constant only, model/scene.cpp); temperatures,
// HCS and the tracer limit are the kinetic level's.
// Why: at the kinetic level's own settled state the Sonine sequence D[M] of the tracer problem does not converge at
// strong dissipation (bo1-fig05, ε = 0.2, light species: 0.820, 0.923, 0.825, 0.945 for M = 2…5) and leaves the
// species' shape out; solved converged with it, the settled D ratios of v1 Figs. 4, 5, 7 move to within 3% of DSMC
// (README, "The converged tracer problem").
class ConvergedLevel final : public TheoryLevel {
 public:
  static constexpr std::size_t converged_species_limit = 100;
  struct Variant {
    int cooling_order = 2;
    // The tracer form with the gas's reshaping by the intruders (RelaxationOptions::gas_shape), the companion that
    // measures that left-out effect; otherwise the same level.
    bool reshaped = false;
    // "kinetic-converged-hcs", the tracer problem at the converged HCS (converged_hcs.hpp: its T_k, a₂,k, a₃,k and ζ)
    // instead of the Sonine one; sweeps only (model/scene.cpp). Why: under v1 Fig. 5's D ratios the Sonine HCS is the
    // gap — at the converged HCS they move by −1.3 … −2.8%, to within 0.5% of DSMC at paper fidelity
    // (docs/paper-fidelity.md; test "kinetic-converged-hcs: …").
    bool hcs_converged = false;
    // "kinetic-converged-grid": the temperatures and the species' shapes in time without the Sonine truncation (the
    // speed grid, speed_grid_cooling.hpp; constant ε, up to grid_species_limit species), the HCS the
    // converged one. Why: in time the Sonine series is asymptotic where a light species runs far from its partners'
    // temperature (v1 Fig. 2's light species at t = 10: orders 2 / 3 / 4 −3.8 / 0 / −3.4% from order 3); on the grid
    // v1 Fig. 2's light T and v1 Fig. 6's light MSD lie within 0.1–0.2% of paper-fidelity DSMC at every time (README).
    bool grid = false;
    // Its companions, the computed parts of its model error: every shape seen through a₂ alone (the partners in the
    // temperatures and in the tracer problem, the species' own in the tracer's source: the a₃ term's size), and the
    // tracer problem's basis of `basis` functions.
    bool a2_only = false;
    std::size_t basis = converged_diffusion_basis;
  };
  explicit ConvergedLevel(Variant v) : base_(kinetic_sonine_order, v.cooling_order), v_(v), name_(level_name(v)) {}
  const char* name() const override { return name_.c_str(); }
  // kinetic-converged-hcs: its sweep points' increments too in closed form, from the settled memory at the converged HCS
  // (a settled start is self-similar; the VACF history follows the Sonine temperatures and shapes in time), times the
  // effect of DSMC's unsettled start (start_companion below).
  MsdMethod msd_method(const model::Scene& s) const override { return s.theory.sweep || v_.hcs_converged ? MsdMethod::closed : MsdMethod::vacf; }
  void configure(TemperatureOptions& opt, const CollisionRates& rates) const override {
    base_.configure(opt, rates);
    if (v_.grid) opt.cooling = grid_cooling(rates);
    if (!opt.vacf) return;
    refuse_beyond_species_limit(rates);
    // The basis (x₀) from the Maxwellian settled temperatures, the same for both converged levels, so that the judged
    // level and its `converged` companion share their pair tables (opt.galerkin_tables). The basis is a numerical
    // choice: each level's own settled temperatures (before 2026-12-03) give MSDs within 9.4e-5 (bo1-fig03-aged), v1
    // Fig. 8's near-critical k = 40–43 within 1.7e-3 (its basis sensitivity: ~1% across 6–9 functions, README).
    std::shared_ptr<const VelocityDecay> decay =
        std::make_shared<GalerkinDecay>(rates, theory::settled_temperatures(rates).T, v_.basis, opt.galerkin_tables);
    opt.decay = v_.a2_only ? std::make_shared<WithoutThirdSonine>(std::move(decay)) : decay;
  }
  // At settled temperature ratios (T sets the scale): the level's steady shape and cooling rates at T.
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    // The settled memory needs a settled state: a viscoelastic gas has none (its ε drifts to 1 as it cools).
    if (rates.law().is_viscoelastic())
      throw InputError("level " + name_ + ": its settled memory (sweeps, TAMSD) needs a constant restitution coefficient (allowed: collisions.restitution = number)");
    refuse_beyond_species_limit(rates);
    // A sweep asks twice per point (the settled ratio, then the increments from the same settled start): the last
    // answer is kept, keyed by everything it depends on.
    std::vector<double> key = T;
    const std::vector<double> mixture_key = rates.key();
    key.insert(key.end(), mixture_key.begin(), mixture_key.end());
    if (key == memo_key_) return memo_;
    const std::size_t N = rates.size();
    std::vector<double> a2(N, 0.0), a3(N, 0.0), xi(N);
    if (v_.hcs_converged) {
      // The converged HCS at T's scale: every ζ_k the one ζ, ∝ √T (hard spheres, constant ε).
      const ConvergedHcs& c = converged_state(rates);
      const double zeta = c.zeta * std::sqrt(T[0] / c.hcs.T[0]);
      for (std::size_t k = 0; k < N; ++k) a2[k] = 0.5 * c.hcs.c[k], a3[k] = c.hcs.a3[k], xi[k] = zeta;
    } else if (sonine_applies(rates) && third_sonine_applies(rates, v_.cooling_order)) {
      const SonineMomentCooling m(rates, 3, {}, make_sonine_pair_terms(rates.law()));
      const std::vector<double> z = m.steady_state(T.data());
      std::vector<double> dz(z.size());
      m.rates(T.data(), z.data(), xi.data(), dz.data());
      for (std::size_t k = 0; k < N; ++k) a2[k] = 0.5 * z[k], a3[k] = z[N + k];  // z: c_k = 2a₂,k, then a₃,k
    } else if (sonine_applies(rates)) {
      const SonineCooling c(rates, CumulantMode::quasi_static);
      c.rates(T.data(), nullptr, xi.data(), nullptr);
      c.cumulants(T.data(), nullptr, a2.data());
      for (double& a : a2) a *= 0.5;
    } else {
      rates.xi_all(T.data(), xi.data());  // elastic (Maxwellian equilibrium) or too many species: Maxwellian
    }
    // The species' problems are independent (~0.1 s each at the 51 points of a sweep): solved on OpenMP threads,
    // each wholly on one, so the numbers do not depend on the thread count.
    std::vector<double> Dk(N);
    std::vector<std::optional<VelocityMemory>> memory(N);
    parallel_each(N, [&](std::size_t k) {
      GalerkinOptions opt;
      opt.zeta = xi[k], opt.a2 = a2.data(), opt.a3 = a3.data();
      const ConvergedDiffusion c = converged_tracer_diffusion(rates, k, T.data(), opt);
      Dk[k] = c.D;
      if (std::isfinite(c.D)) memory[k] = galerkin_memory(c.problem);
    });
    SettledDiffusion d;
    d.T = T;
    for (std::size_t k = 0; k < N; ++k) {
      // No diffusive solution (a rare grain at the Santos–Dufty edge, where the first-Sonine HCS itself runs away):
      // the first-Sonine D and its one exponential, as the kinetic level does.
      const double D = memory[k] ? Dk[k] : T[k] / (rates.mixture()[k].mass * rates.inv_tau_v_species(k, T.data()));
      d.D.push_back(D), d.tau_v.push_back(D * rates.mixture()[k].mass / T[k]);
      d.memory.push_back(memory[k] ? *memory[k] : VelocityMemory::exponential(D, d.tau_v.back()));
    }
    for (std::size_t k = 0; k < N; ++k) d.D_ratio.push_back(d.D[k] / d.D[0]);
    d.tau0 = xi[0] > 0.0 ? 2.0 / xi[0] : std::numeric_limits<double>::infinity();
    memo_key_ = std::move(key), memo_ = d;
    return d;
  }
  // A history starts where the kinetic level does (DSMC's start; the memory builds up from U = 0).
  // kinetic-converged-hcs: a settled start has the converged HCS's ratios, at the kinetic level's T₁ (the same time scale).
  std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates,
                                           TemperatureOptions& opt) const override {
    if (v_.grid && init.kind == model::InitialState::Kind::aged) {
      // DSMC ages its gas with the true collisions from Maxwellians at T_hot: so does the grid (opt.cooling, configure's),
      // and the history starts from the aged densities.
      TemperatureOptions ageing;
      ageing.rtol = opt.rtol, ageing.cooling = opt.cooling;
      const AgedState a = aged_state(init.T_hot, rates, ageing);
      opt.cooling = grid_cooling(rates, a.z);
      return a.T;
    }
    std::vector<double> T = base_.initial_temperatures(init, rates, opt);
    if (!v_.hcs_converged) return T;
    // Its MSD is the settled memory's closed form: true from a settled start only (`granmix theory --level` can ask).
    if (init.kind != model::InitialState::Kind::hcs)
      throw InputError("level kinetic-converged-hcs: its MSD is the settled state's, so the start must be settled (allowed: initial.temperatures = \"hcs\", or a sweep)");
    const SonineHcs& h = converged_state(rates).hcs;
    const double scale = T[0] / h.T[0];
    for (std::size_t k = 0; k < T.size(); ++k) T[k] = h.T[k] * scale;
    return T;
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override {
    return v_.hcs_converged || v_.grid ? converged_state(rates).hcs.T : base_.settled_temperatures(rates);
  }
  SonineHcs hcs(const CollisionRates& rates) const override { return v_.hcs_converged || v_.grid ? converged_state(rates).hcs : base_.hcs(rates); }
  // kinetic-converged-hcs: the four computed parts of its D ratios' model error (converged_hcs_diffusion.hpp). Why its
  // own: at v1 Fig. 4's n₂ = 0.01 the HCS partners' truncation is 0.99% (full partners) and the tracer problem's
  // 1.5%, at n₂ = 0.1 and 0.3 all four parts sum to 3e-4 — one `relative` per scene would either widen the latter or
  // miss the former.
  bool computes_d_ratio_error() const override { return v_.hcs_converged; }
  // Its increments are the closed form from its own settled ratios; DSMC starts at the Maxwellian HCS (v1 Fig. 4
  // same-material, n₂ = 0.001: T₂/T₁ 82.3 against 89.3, and the heavy grain remembers it: over [50, 5000] the closed
  // form was 1.0% above DSMC's 18 + 18 seeds and bo2-fig02's 20). kinetic-converged-cooling3's VACF history from both
  // starts carries the difference (its settled ratio 89.02). Its model error: the same factor by kinetic-converged (first
  // Sonine temperatures in time) against it — 0.16% there, 0.20% at v1 Fig. 4's n₂ = 0.01, 0.18% at v1 Fig. 5
  // equal-sizes' ε = 0.2, ≤ 0.012% at the other DSMC points of the five sweeps (measured 2026-12-05).
  StartCompanions start_companion() const override {
    if (!v_.hcs_converged) return {};
    return {"kinetic-converged-cooling3", "kinetic-converged"};
  }
  std::vector<double> d_ratio_error(const CollisionRates& rates) const override {
    if (!v_.hcs_converged) return TheoryLevel::d_ratio_error(rates);
    return converged_d_ratio_error(rates, converged_state(rates, true)).total();
  }
  // The tracer limit with the intruder's converged stationary θ (the speed grid, with its heating of the gas:
  // tracer_temperature.hpp) as its start, its memory that state's (τ_v⁻¹ = ν̄ − ζ/2), where that state exists (constant
  // ε < 1, intruders under a tenth of the gas's energy budget); the kinetic level's otherwise.
  TracerLimit tracer(const CollisionRates& rates) const override { return tracer_at(rates, converged_intruder(rates)); }
  // From that start the intruder relaxes (its shape forms, then θ settles: tracer_relaxation.hpp); the gas keeps its own
  // converged memory (this level's, of the gas alone).
  std::unique_ptr<TracerForm> tracer_form(const CollisionRates& rates, double t_end) const override {
    const TracerTemperature c = converged_intruder(rates);  // once: the speed-grid solve is ~0.25 s
    const TracerLimit t = tracer_at(rates, c);
    if (!std::isfinite(c.theta)) return closed_tracer_form(t);
    const model::Species gas = rates.mixture()[0];
    const CollisionRates alone(model::Mixture({gas}), model::Restitution::constant(1, rates.law().eps(0, 0)), {{rates.chi(0, 0)}});
    const SettledDiffusion d = diffusion_at(alone, {1.0});
    RelaxationOptions opt;
    opt.gas_shape = v_.reshaped;
    return relaxing_tracer_form(rates, d.memory_of(0), 2.0 / d.tau0, t.theta, t_end, opt);
  }

 private:
  TracerLimit tracer_at(const CollisionRates& rates, const TracerTemperature& c) const {
    TracerLimit t = base_.tracer(rates);
    if (!std::isfinite(c.theta)) return t;
    t.theta = c.theta;
    t.tau_v_intruder = 1.0 / (c.nu - 0.5 * (2.0 / t.tau0 + c.xi12));
    t.D_intruder = c.theta * t.tau_v_intruder / rates.mixture()[1].mass;
    return t;
  }
  // The speed grid resolves a heavy intruder's many small kicks (each ~m₁/m₂ of its thermal speed) only so far. Its θ
  // moves with a coarser grid (`change`: knots 1.5× wider or the coarse collision rule; the grid used is finer) by 0.04%
  // at m₂/m₁ = 100, ε = 0.7, 0.2% at ε = 0.5 (v2 Fig. 5), 1.0/1.9% at ε = 0.9/0.8 (θ near equipartition), 5.5% at m₂/m₁ =
  // 300 (ε = 0.5); from ~500 it does not settle at all, and at 3000 it once settled by chance with a change of 60%
  // (measured 2026-12-04). Beyond 10% the level refuses, naming the limit, rather than judge DSMC against a number the
  // grid does not resolve. Where it settles the change bounds the grid's error: against a finer grid (knots 2× and 3×
  // denser, the collision rule's 12 gas points → 24 and 48) θ moves by 1.5e-5 at ε = 0.5 (v2 Fig. 5), 2.5e-5 at 0.7,
  // 0.08% at 0.8 and 0.21% at 0.9 (m₂/m₁ = 100; the rule's part, the knots' < 3e-8 there; measured 2026-12-04).
  static constexpr double max_grid_change = 0.1;
  static TracerTemperature converged_intruder(const CollisionRates& rates) {
    const model::Restitution& law = rates.law();
    if (rates.size() != 2 || law.is_viscoelastic() || !(law.eps(0, 0) < 1.0)) return {};
    const TracerTemperature c = converged_intruder_temperature(rates, converged_tracer_temperature(rates));
    if (std::isfinite(c.theta) && !(c.change <= max_grid_change))
      throw NumericalError("converged intruder temperature: the speed grid resolves theta = " + std::to_string(c.theta) + " only to " +
                           std::to_string(100.0 * c.change) + "% (mass ratio " + std::to_string(rates.mixture()[1].mass / rates.mixture()[0].mass) +
                           "; the limit is 10%, about m2/m1 = 400 at eps = 0.5): level = \"kinetic\" for this intruder");
    return c;
  }
  // N² pairs' speed-grid operators along the history (three per node of ln(T_j/T_k), ~5 ms each): v1 Fig. 6's three
  // species 259 nodes. Beyond this many species the level refuses.
  static constexpr std::size_t grid_species_limit = 10;
  std::shared_ptr<const CoolingModel> grid_cooling(const CollisionRates& rates, std::vector<double> z0 = {}) const {
    if (rates.law().is_viscoelastic())
      throw InputError("level " + name_ + ": the speed grid's exact sphere integrals need a constant restitution coefficient (allowed: collisions.restitution = number)");
    if (rates.size() > grid_species_limit)
      throw InputError("level " + name_ + ": " + std::to_string(rates.size()) + " species; the speed-grid temperatures take up to " +
                       std::to_string(grid_species_limit) + " (allowed: level = \"kinetic-converged-cooling3\" for more)");
    return std::make_shared<SpeedGridCooling>(rates, v_.a2_only ? 2 : 3, SpeedGridSettings{}, std::move(z0));
  }
  void refuse_beyond_species_limit(const CollisionRates& rates) const {
    // N² Galerkin pair problems per settled state, ~1 ms each (tracer_diffusion_galerkin.hpp): 1e4 pairs is ~5 s per
    // point on 2 cores, so a 51-point sweep of 100 species takes minutes; beyond that a clear refusal, not hours.
    if (rates.size() > converged_species_limit)
      throw InputError("level " + name_ + ": " + std::to_string(rates.size()) + " species need " + std::to_string(rates.size() * rates.size()) +
                       " Galerkin pair problems per settled state (~1 ms each); the limit is " + std::to_string(converged_species_limit) +
                       " species (allowed: level = \"kinetic\" for more)");
  }
  // A sweep point asks for the settled state three times (its temperatures, its D, its increments' start): solved once.
  // check: with its error estimates (four more solves; the state itself is the same), kept for the later asks.
  const ConvergedHcs& converged_state(const CollisionRates& rates, bool check = false) const {
    std::vector<double> key = rates.key();
    const bool checked = !hcs_memo_.grid_variants.empty();
    if (key != hcs_key_ || (check && !checked)) hcs_memo_ = converged_hcs(rates, check), hcs_key_ = std::move(key);
    return hcs_memo_;
  }
  static std::string level_name(const Variant& v) {
    if (v.hcs_converged) return "kinetic-converged-hcs";
    if (v.grid)
      return std::string("kinetic-converged-grid") + (v.a2_only ? "-a2" : "") +
             (v.basis != converged_diffusion_basis ? "-basis" + std::to_string(v.basis) : "");
    return std::string(v.cooling_order == 2 ? "kinetic-converged" : "kinetic-converged-cooling" + std::to_string(v.cooling_order)) +
           (v.reshaped ? "-reshaped" : "") + (v.basis != converged_diffusion_basis ? "-basis" + std::to_string(v.basis) : "");
  }
  KineticLevel base_;
  Variant v_;
  std::string name_;
  mutable std::vector<double> memo_key_, hcs_key_;  // one level object serves one thread (scene_theory.cpp)
  mutable SettledDiffusion memo_;
  mutable ConvergedHcs hcs_memo_;
};

}  // namespace

std::unique_ptr<TracerForm> TheoryLevel::tracer_form(const CollisionRates& rates, double) const { return closed_tracer_form(tracer(rates)); }

TheoryLevel::SettledDistribution TheoryLevel::settled_distribution(const CollisionRates& rates) const {
  SettledDistribution d{hcs(rates), {}, {}};
  d.phi = [h = d.hcs](std::size_t k, double v) { return h.phi(k, v); };
  return d;
}

std::vector<double> TheoryLevel::d_ratio_error(const CollisionRates&) const {
  throw std::logic_error(std::string("level ") + name() + " computes no model error of its D ratios");
}

std::string companion_level(const std::string& level, const std::string& correction) {
  if (correction == "paper" || correction == "kinetic") return correction;
  // The two truncations of kinetic-converged-cooling3 one at a time: its temperatures at the first Sonine ("converged":
  // kinetic-converged) and its D at Sonine order 4 ("sonine4": kinetic-cooling3).
  if (level == "kinetic-converged-cooling3" && correction == "converged") return "kinetic-converged";
  if (level == "kinetic-converged-cooling3" && correction == "sonine4") return "kinetic-cooling3";
  // Its temperatures and shapes in time without the Sonine truncation ("grid": kinetic-converged-grid).
  if (level == "kinetic-converged-cooling3" && correction == "grid") return "kinetic-converged-grid";
  // Its own next orders: the temperatures' (a₄ relaxing too, "cooling4": kinetic-converged-cooling4, whose temperatures
  // are kinetic-cooling4's, its D the same converged tracer problem) and the tracer problem's basis ("basis"). Why not
  // the Sonine D ("sonine4") for its MSD: where the Sonine sequence of D diverges (v1 Fig. 8's heaviest species) that
  // difference measures the Sonine series, not this level (README, "The converged levels' own next orders").
  if (level == "kinetic-converged-cooling3" && correction == "cooling4") return "kinetic-converged-cooling4";
  if (level == "kinetic-converged-cooling3" && correction == "basis") return level + "-basis" + std::to_string(companion_basis);
  // kinetic-converged-grid's computed parts: every shape through a₂ alone ("a2"), the tracer problem's basis ("basis").
  if (level == "kinetic-converged-grid" && correction == "a2") return "kinetic-converged-grid-a2";
  if (level == "kinetic-converged-grid" && correction == "basis") return "kinetic-converged-grid-basis" + std::to_string(companion_basis);
  // kinetic-hcs-converged's settled distributions: sparser knots ("knots"), the coarser rule ("rule"), full partners
  // ("partners"), the wider domain ("domain").
  if (level == "kinetic-hcs-converged" && (correction == "knots" || correction == "rule" || correction == "partners" || correction == "domain"))
    return level + "-" + correction;
  if (correction == "cooling3") return level.starts_with("kinetic-converged") ? "kinetic-converged-cooling3" : "kinetic-cooling3";
  // The temperatures' next Sonine order.
  if (correction == "cooling4" && level == "kinetic-cooling3") return "kinetic-cooling4";
  if (correction == "reshaped" && level.starts_with("kinetic-converged") && !level.ends_with("-reshaped")) return level + "-reshaped";
  if (correction == "sonine1" && (level == "kinetic" || level == "kinetic-cooling3")) return level + "-sonine1";
  throw std::invalid_argument("no companion level '" + correction + "' beside the level '" + level + "'");
}

std::unique_ptr<TheoryLevel> make_theory_level(const std::string& name) {
  if (name == "paper") return std::make_unique<PaperLevel>();
  if (name == "kinetic") return std::make_unique<KineticLevel>(kinetic_sonine_order);
  if (name == "kinetic-cooling3") return std::make_unique<KineticLevel>(kinetic_sonine_order, 3);
  if (name == "kinetic-cooling3-shaped") return std::make_unique<KineticLevel>(kinetic_sonine_order, 3, true);
  if (name == "kinetic-cooling4") return std::make_unique<KineticLevel>(kinetic_sonine_order, 4);
  if (name == "kinetic-hcs-converged") return std::make_unique<HcsConvergedLevel>();
  if (name == "kinetic-hcs-converged-knots") return std::make_unique<HcsConvergedLevel>(DistributionVariant::sparser_knots);
  if (name == "kinetic-hcs-converged-rule") return std::make_unique<HcsConvergedLevel>(DistributionVariant::coarser_rule);
  if (name == "kinetic-hcs-converged-partners") return std::make_unique<HcsConvergedLevel>(DistributionVariant::partners_finer);
  if (name == "kinetic-hcs-converged-domain") return std::make_unique<HcsConvergedLevel>(DistributionVariant::wider_domain);
  using Variant = ConvergedLevel::Variant;
  if (name == "kinetic-converged") return std::make_unique<ConvergedLevel>(Variant{});
  if (name == "kinetic-converged-cooling3") return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 3});
  if (name == "kinetic-converged-cooling4") return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 4});
  if (name == "kinetic-converged-cooling3-basis" + std::to_string(companion_basis))
    return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 3, .basis = companion_basis});
  if (name == "kinetic-converged-reshaped") return std::make_unique<ConvergedLevel>(Variant{.reshaped = true});
  if (name == "kinetic-converged-cooling3-reshaped") return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 3, .reshaped = true});
  if (name == "kinetic-converged-hcs") return std::make_unique<ConvergedLevel>(Variant{.hcs_converged = true});
  if (name == "kinetic-converged-grid") return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 3, .grid = true});
  if (name == "kinetic-converged-grid-a2") return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 3, .grid = true, .a2_only = true});
  if (name == "kinetic-converged-grid-basis" + std::to_string(companion_basis))
    return std::make_unique<ConvergedLevel>(Variant{.cooling_order = 3, .grid = true, .basis = companion_basis});
  for (std::size_t n = 1; n <= max_sonine_modes; ++n) {
    if (name == "kinetic-sonine" + std::to_string(n)) return std::make_unique<KineticLevel>(n);
    if (name == "kinetic-cooling3-sonine" + std::to_string(n)) return std::make_unique<KineticLevel>(n, 3);
  }
  throw std::invalid_argument("theory level '" + name + "' (allowed: paper, kinetic, kinetic-sonine1 … kinetic-sonine5, kinetic-cooling3, kinetic-cooling3-sonine1 … 5, kinetic-cooling3-shaped, kinetic-cooling4, kinetic-hcs-converged, kinetic-hcs-converged-knots, kinetic-hcs-converged-rule, kinetic-hcs-converged-partners, kinetic-hcs-converged-domain, kinetic-converged, kinetic-converged-cooling3, kinetic-converged-cooling4, kinetic-converged-cooling3-basis10, kinetic-converged-reshaped, kinetic-converged-cooling3-reshaped, kinetic-converged-hcs, kinetic-converged-grid, kinetic-converged-grid-a2, kinetic-converged-grid-basis10)");
}

}  // namespace granmix::theory
