// The converged family of levels (docs/levels.md, "converged"): the kinetic level with the tracer problem solved
// without the Sonine truncation, its variants, and their declarations.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "theory/grid/converged_hcs.hpp"
#include "theory/grid/converged_hcs_diffusion.hpp"
#include "theory/grid/galerkin_decay.hpp"
#include "theory/grid/speed_grid_cooling.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/grid/tracer_temperature.hpp"
#include "theory/levels/kinetic_level.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/levels/level_families.hpp"
#include "theory/numerics/parallel_each.hpp"

namespace granmix::theory {

namespace {

// The converged levels' basis companion (kinetic-converged-grid's, kinetic-converged-cooling3's): the tracer problem with
// this many functions (the level's 8). v1 Fig. 2's MSDs move by ≤ 4.2e-4 from 8 to 10 functions (1.0e-4 from 8 to 7;
// measured).
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
// (docs/levels.md, "The converged tracer problem").
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
    // (docs/validation.md; test "kinetic-converged-hcs: …").
    bool hcs_converged = false;
    // "kinetic-converged-grid": the temperatures and the species' shapes in time without the Sonine truncation (the
    // speed grid, speed_grid_cooling.hpp; constant ε, up to grid_species_limit species), the HCS the
    // converged one. Why: in time the Sonine series is asymptotic where a light species runs far from its partners'
    // temperature (v1 Fig. 2's light species at t = 10: orders 2 / 3 / 4 −3.8 / 0 / −3.4% from order 3); on the grid
    // v1 Fig. 2's light T and v1 Fig. 6's light MSD lie within 0.1–0.2% of paper-fidelity DSMC at every time (docs/validation.md).
    bool grid = false;
    // Its companions, the computed parts of its model error: every shape seen through a₂ alone (the partners in the
    // temperatures and in the tracer problem, the species' own in the tracer's source: the a₃ term's size), and the
    // tracer problem's basis of `basis` functions.
    bool a2_only = false;
    std::size_t basis = converged_diffusion_basis;
    bool operator==(const Variant&) const = default;
  };
  explicit ConvergedLevel(Variant v) : base_(kinetic_sonine_order, v.cooling_order), v_(v) {}
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
    // choice: each level's own settled temperatures would give MSDs within 9.4e-5 (bo1-fig03-aged), v1
    // Fig. 8's near-critical k = 40–43 within 1.7e-3 (its basis sensitivity: ~1% across 6–9 functions, docs/levels.md).
    std::shared_ptr<const VelocityDecay> decay =
        std::make_shared<GalerkinDecay>(rates, theory::settled_temperatures(rates).T, v_.basis, opt.galerkin_tables);
    opt.decay = v_.a2_only ? std::make_shared<WithoutThirdSonine>(std::move(decay)) : decay;
  }
  // At settled temperature ratios (T sets the scale): the level's steady shape and cooling rates at T.
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    // The settled memory needs a settled state: a viscoelastic gas has none (its ε drifts to 1 as it cools).
    if (rates.law().is_viscoelastic())
      throw InputError("level " + std::string(name()) + ": its settled memory (sweeps, TAMSD) needs a constant restitution coefficient (allowed: collisions.restitution = number)");
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
  // equal-sizes' ε = 0.2, ≤ 0.012% at the other DSMC points of the five sweeps.
  StartCompanions start_companion() const override {
    if (!v_.hcs_converged) return {};
    return {"kinetic-converged-cooling3", "kinetic-converged"};
  }
  std::vector<double> d_ratio_error(const CollisionRates& rates) const override {
    if (!v_.hcs_converged) return TheoryLevel::d_ratio_error(rates);
    return converged_d_ratio_error(rates, converged_state(rates, true)).total();
  }
  // The tracer limit with the intruder's converged stationary θ (the speed grid, with its heating of the gas:
  // tracer_temperature.hpp), its memory that state's (τ_v⁻¹ = ν̄ − ζ/2), where that state exists (constant ε < 1,
  // intruders under a tenth of the gas's energy budget); the kinetic level's otherwise.
  TracerLimit tracer(const CollisionRates& rates) const override { return tracer_at(rates, converged_intruder(rates)); }
  // Where that state exists the intruder relaxes from the scene's start theta0, a Maxwellian (its shape forms, θ moves
  // toward the stationary one: tracer_relaxation.hpp); the gas keeps its own converged memory (this level's, of the
  // gas alone).
  std::unique_ptr<TracerForm> tracer_form(const CollisionRates& rates, double theta0, double t_end) const override {
    const TracerTemperature c = converged_intruder(rates);  // ~0.25 s: whether the state exists (and its refusal)
    if (!std::isfinite(c.theta)) return closed_tracer_form(tracer_at(rates, c));
    const model::Species gas = rates.mixture()[0];
    const CollisionRates alone(model::Mixture({gas}), model::Restitution::constant(1, rates.law().eps(0, 0)), {{rates.chi(0, 0)}});
    const SettledDiffusion d = diffusion_at(alone, {1.0});
    RelaxationOptions opt;
    opt.gas_shape = v_.reshaped;
    return relaxing_tracer_form(rates, d.memory_of(0), 2.0 / d.tau0, theta0, t_end, opt);
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
  // Beyond 10% the level refuses, naming the limit, rather than judge DSMC against a number the
  // grid does not resolve. Where it settles the change bounds the grid's error: against a finer grid (knots 2× and 3×
  // denser, the collision rule's 12 gas points → 24 and 48) θ moves by 1.5e-5 at ε = 0.5 (v2 Fig. 5), 2.5e-5 at 0.7,
  // 0.08% at 0.8 and 0.21% at 0.9 (m₂/m₁ = 100; the rule's part, the knots' < 3e-8 there).
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
      throw InputError("level " + std::string(name()) + ": the speed grid's exact sphere integrals need a constant restitution coefficient (allowed: collisions.restitution = number)");
    if (rates.size() > grid_species_limit)
      throw InputError("level " + std::string(name()) + ": " + std::to_string(rates.size()) + " species; the speed-grid temperatures take up to " +
                       std::to_string(grid_species_limit) + " (allowed: level = \"kinetic-converged-cooling3\" for more)");
    return std::make_shared<SpeedGridCooling>(rates, v_.a2_only ? 2 : 3, SpeedGridSettings{}, std::move(z0));
  }
  void refuse_beyond_species_limit(const CollisionRates& rates) const {
    // N² Galerkin pair problems per settled state, ~1 ms each (tracer_diffusion_galerkin.hpp): 1e4 pairs is ~5 s per
    // point on 2 cores, so a 51-point sweep of 100 species takes minutes; beyond that a clear refusal, not hours.
    if (rates.size() > converged_species_limit)
      throw InputError("level " + std::string(name()) + ": " + std::to_string(rates.size()) + " species need " + std::to_string(rates.size() * rates.size()) +
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

 public:
  // The family's naming rule (level_catalogue.hpp).
  static std::string level_name(const Variant& v) {
    if (v.hcs_converged) return "kinetic-converged-hcs";
    if (v.grid)
      return std::string("kinetic-converged-grid") + (v.a2_only ? "-a2" : "") +
             (v.basis != converged_diffusion_basis ? "-basis" + std::to_string(v.basis) : "");
    return std::string(v.cooling_order == 2 ? "kinetic-converged" : "kinetic-converged-cooling" + std::to_string(v.cooling_order)) +
           (v.reshaped ? "-reshaped" : "") + (v.basis != converged_diffusion_basis ? "-basis" + std::to_string(v.basis) : "");
  }

 private:
  KineticLevel base_;
  Variant v_;
  mutable std::vector<double> memo_key_, hcs_key_;  // one level object serves one thread (scene_theory.cpp)
  mutable SettledDiffusion memo_;
  mutable ConvergedHcs hcs_memo_;
};

using Variant = ConvergedLevel::Variant;

// A part changed: the companion of a variant within the family (nullopt where that part does not change).
struct ConvergedCompanion {
  const char* correction;
  const char* changes;
  std::optional<Variant> (*change)(Variant);
  std::vector<std::string> quantities;
  bool needs_tracer = false, needs_history_with_constant_restitution = false;
};

bool plain(const Variant& v) { return !v.hcs_converged && !v.grid && !v.a2_only; }

}  // namespace

void declare_converged_levels(LevelCatalogue& c) {
  const std::vector<Variant> variants = {
      {},
      {.cooling_order = 3},
      {.cooling_order = 4},
      {.cooling_order = 3, .basis = companion_basis},
      {.reshaped = true},
      {.cooling_order = 3, .reshaped = true},
      {.hcs_converged = true},
      {.cooling_order = 3, .grid = true},
      {.cooling_order = 3, .grid = true, .a2_only = true},
      {.cooling_order = 3, .grid = true, .basis = companion_basis},
  };
  const std::vector<ConvergedCompanion> companions = {
      {"cooling3", "the temperatures and HCS at Sonine order 3",
       [](Variant v) -> std::optional<Variant> { return plain(v) && v.cooling_order == 2 ? (v.cooling_order = 3, std::optional(v)) : std::nullopt; }, {}},
      {"converged", "the temperatures at first Sonine",
       [](Variant v) -> std::optional<Variant> { return plain(v) && v.cooling_order == 3 ? (v.cooling_order = 2, std::optional(v)) : std::nullopt; }, {}},
      {"reshaped", "the gas reshaped by the intruders in the tracer form",
       [](Variant v) -> std::optional<Variant> { return !v.reshaped ? (v.reshaped = true, std::optional(v)) : std::nullopt; }, {}, true},
      {"cooling4", "the temperatures at Sonine order 4 (a4 relaxing too)",
       [](Variant v) -> std::optional<Variant> { return plain(v) && v.cooling_order == 3 ? (v.cooling_order = 4, std::optional(v)) : std::nullopt; },
       {"T", "gamma", "msd", "msd_ratio"}},
      {"grid", "the temperatures and shapes in time on the speed grid (no Sonine truncation)",
       [](Variant v) -> std::optional<Variant> { return plain(v) && v.cooling_order == 3 ? (v.grid = true, std::optional(v)) : std::nullopt; }, {}, false, true},
      {"a2", "every shape seen through a2 alone",
       [](Variant v) -> std::optional<Variant> { return v.grid && !v.a2_only ? (v.a2_only = true, std::optional(v)) : std::nullopt; }, {}},
      {"basis", "the tracer problem with 10 functions instead of 8",
       [](Variant v) -> std::optional<Variant> { return v.basis != companion_basis ? (v.basis = companion_basis, std::optional(v)) : std::nullopt; }, {}},
  };
  for (const Variant& v : variants) {
    LevelDescriptor d;
    d.name = ConvergedLevel::level_name(v);
    d.family = "converged";
    const std::string temperatures = v.grid ? "every species' speed density in time on the speed grid (no Sonine truncation)"
                                     : v.cooling_order == 2 ? "first Sonine, a2 relaxing" : v.cooling_order == 3 ? "Sonine order 3, a2 and a3 relaxing" : "Sonine order 4";
    d.summary = v.hcs_converged ? "the converged tracer problem at the converged HCS: settled D ratios of sweeps with their own computed model error"
                : v.grid        ? "the converged tracer problem along temperatures and shapes solved on the speed grid"
                                : "the kinetic level with the tracer problem solved without the Sonine truncation, temperatures at " + temperatures;
    if (v.reshaped) d.summary += "; the gas reshaped by the intruders in the tracer form";
    if (v.a2_only) d.summary += "; every shape through a2 alone";
    if (v.basis != converged_diffusion_basis) d.summary += "; the tracer problem with " + std::to_string(v.basis) + " functions";
    d.parts = {temperatures, "the converged tracer problem (Galerkin, " + std::to_string(v.basis) + " functions; docs/levels.md)",
               v.hcs_converged || v.grid ? "converged HCS (no Sonine truncation)" : v.cooling_order == 2 ? "first Sonine" : "Sonine order 3",
               "the intruder's converged theta relaxing in time (speed grid)", "the HCS's Sonine Phi_k"};
    d.applies = v.grid ? "constant restitution, a history (no sweep, no tracer form), up to 10 species"
                : v.hcs_converged ? "sweeps at constant restitution, up to 100 species"
                                  : "any restitution law in time (constant in sweeps), up to 100 species";
    d.cost = v.grid ? "seconds (v1 Fig. 2: ~1 s)" : v.hcs_converged ? "~0.1-0.5 s per sweep point" : "~0.1-1 s per history, more for many species";
    d.scene_may_choose = v == Variant{} || v == Variant{.cooling_order = 3} || v == Variant{.hcs_converged = true} ||
                         v == Variant{.cooling_order = 3, .grid = true};
    // level = "auto": a sweep's settled D ratios, then the histories with the converged tracer problem and on the speed
    // grid, each within seconds up to 10 species
    if (v == Variant{.hcs_converged = true}) d.auto_step = 4, d.auto_max_species = 10;
    if (v == Variant{.cooling_order = 3}) d.auto_step = 5, d.auto_max_species = 10;
    if (v == Variant{.cooling_order = 3, .grid = true}) d.auto_step = 6, d.auto_max_species = 10;
    if (v.hcs_converged)
      d.conditions.push_back({.needs_sweep = true,
                              .what = "level \"" + d.name + "\" is the settled state of a sweep (the converged HCS has no history in time)",
                              .allowed = "theory.sweep with level = \"" + d.name + "\", or level = \"" + ConvergedLevel::level_name({}) + "\""});
    if (v.grid)  // the speed-grid history (theory/grid/speed_grid_cooling.hpp) integrates every species' density with a constant ε
      d.conditions.push_back({.needs_history = true, .needs_constant_restitution = true, .refuses_tracer = true,
                              .what = "level \"" + d.name + "\" integrates every species' density in time, which needs a constant restitution "
                                      "coefficient and a history (no sweep, no tracer form)",
                              .allowed = "collisions.restitution = number without sweep or tracer, or level = \"" +
                                         ConvergedLevel::level_name({.cooling_order = 3}) + "\""});
    d.conditions.push_back({.constant_restitution_in_sweeps = true,
                            .what = "level \"" + d.name + "\" settles its memory for a sweep, which needs a constant restitution coefficient",
                            .allowed = "collisions.restitution = number"});
    if (v.hcs_converged)
      d.error_columns.push_back({"D_ratio_error", "the model error the level " + d.name + " computes for its D ratios", {"D_ratio"}});
    d.companions.push_back({"paper", "paper", "the papers' closure", {}});
    d.companions.push_back({"kinetic", "kinetic", "the kinetic level (first-Sonine temperatures, D to Sonine order 4)", {}});
    if (plain(v) && v.cooling_order == 3 && !v.reshaped && v.basis == converged_diffusion_basis)
      d.companions.push_back({"sonine4", KineticLevel::level_name(kinetic_sonine_order, 3, false), "D at Sonine order 4 instead of the converged tracer problem", {}});
    for (const ConvergedCompanion& k : companions)
      if (const std::optional<Variant> w = k.change(v); w && std::find(variants.begin(), variants.end(), *w) != variants.end())
        d.companions.push_back({k.correction, ConvergedLevel::level_name(*w), k.changes, k.quantities, k.needs_tracer, false, k.needs_history_with_constant_restitution});
    d.construct = [v] { return std::make_unique<ConvergedLevel>(v); };
    c.add(std::move(d));
  }
}

}  // namespace granmix::theory
