#pragma once
// A theory level: how the kinetic equations are closed (issue 12; physics-beyond.md). A scene
// chooses one with `[theory] level`; every curve of theory.tsv is computed through it.
//   paper    the papers' closure: Maxwellian cooling rates (v1 A2), the scene's MSD form (v1 Eq. 17 by
//            default), D_k = T_k τ_v,k/m_k (v1 Eq. 19 = the first-Sonine D, physics-beyond §1).
//   kinetic  first-Sonine (Garzó–Dufty) cooling rates with relaxing cumulants (physics-beyond §4), the MSD
//            by the velocity-autocorrelation ODE (§2) with kinetic_sonine_order = 4 Sonine modes per species
//            (SonineDecay: first-Sonine ν_k at short times, D to Sonine order 4 at long times, §3), settled states of the
//            first-Sonine HCS (MG App. A); for a viscoelastic law the same integrals by quadrature over the
//            impact speed (sonine_quadrature.hpp). Variants: kinetic-sonineN (D to order N), kinetic-cooling3
//            (temperatures with a₂ and a₃, sonine_moment_cooling.hpp, and the order-3 HCS; judged by v1 Figs. 2, 9, 10),
//            kinetic-cooling3-sonineN, kinetic-cooling3-shaped (and the a's in D), kinetic-cooling4 (a₄ too, constant
//            restitution: the order-3 temperatures' next correction, correction_from = "cooling4"); kinetic-hcs-converged (its HCS
//            without the Sonine truncation, converged_hcs.hpp, its settled distributions the solved speed densities
//            themselves; judged by MG Figs. 2–5, 7; companions -knots, -rule, -partners and -domain for the distributions' model error).
// Each level has a tracer form (scene `tracer = true`, physics.md §4): paper tracer_limit.hpp (Maxwellian θ,
// Haff gas, first-Sonine D), kinetic sonine_tracer.hpp (first-Sonine θ with both a₂, Sonine cooling,
// D to Sonine order 4); both give the MSD and the TAMSD from one velocity correlation in closed form (the
// kinetic one keeps one mode decaying at ν_eff: no multi-mode transient, unlike the mixture's VACF ODE).
// A level is a type, chosen once per scene: the code that computes curves never asks which it is.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "collision_rates.hpp"
#include "diffusion.hpp"
#include "model/scene.hpp"
#include "msd.hpp"
#include "sonine_hcs.hpp"
#include "temperature_history.hpp"
#include "tracer_form.hpp"
#include "tracer_limit.hpp"

namespace granmix::theory {

class TheoryLevel {
 public:
  virtual ~TheoryLevel() = default;
  virtual const char* name() const = 0;
  // How the MSD is computed in time (the paper level follows the scene's `msd`).
  virtual MsdMethod msd_method(const model::Scene& s) const = 0;
  // The level's cooling and velocity-decay models for the temperature integrator.
  virtual void configure(TemperatureOptions& opt, const CollisionRates& rates) const = 0;
  // D_k, the MSD's velocity memory τ_v,k and τ₀ at the temperatures T (no settling).
  virtual SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const = 0;
  // The scene's initial temperatures as the level predicts them: the aged start is the level's own
  // cooling history (and may set the cooling model's initial unknowns in opt); others as the scene says.
  virtual std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates,
                                                   TemperatureOptions& opt) const = 0;
  // The level's settled temperatures (⟨T⟩ = 1).
  virtual std::vector<double> settled_temperatures(const CollisionRates& rates) const = 0;
  // The level's homogeneous cooling state in MG's reduced form (γ, cumulants, Φ_k; constant restitution): MG's
  // first Sonine for the paper level (the MG figures' theory) and the kinetic level, Sonine order 3 (a₃ too) for
  // kinetic-cooling3.
  virtual SonineHcs hcs(const CollisionRates& rates) const = 0;
  // The level's settled distribution in MG's units (MG Figs. 3, 7; distribution_table): its HCS and Φ_k(v*) — the HCS's
  // Sonine form unless the level solves the densities themselves (kinetic-hcs-converged).
  struct SettledDistribution {
    SonineHcs hcs;
    std::function<double(std::size_t k, double v)> phi;
    // The relative error of Φ_k's shell average over the bin [lo, hi] that the level computes (empty: none):
    // kinetic-hcs-converged's grid error at the exact elastic limit of the same mixture, where Φ is Maxwellian.
    std::function<double(std::size_t k, double lo, double hi)> bin_error;
  };
  virtual SettledDistribution settled_distribution(const CollisionRates& rates) const;
  // The binary tracer limit (species 2 an intruder with n₂ → 0) in the level's closure, at T₁ = 1: its θ is where the
  // intruder starts (DSMC's start too).
  virtual TracerLimit tracer(const CollisionRates& rates) const = 0;
  // The tracer limit in time to t_end (tracer_form.hpp): closed forms from tracer(rates) unless the level relaxes it.
  virtual std::unique_ptr<TracerForm> tracer_form(const CollisionRates& rates, double t_end) const;
  // Whether the level computes its own model error of its settled D_k/D_1, and that error (relative, per species;
  // species 1: 0): kinetic-converged-hcs carries the converged HCS's error estimates through its tracer problem
  // (converged_hcs_diffusion.hpp). A sweep's theory.tsv holds it at the DSMC points as `D_ratio_error`, which a scene
  // judges with (error_column). The other levels compute none (they judge with companion levels, correction_from).
  virtual bool computes_d_ratio_error() const { return false; }
  virtual std::vector<double> d_ratio_error(const CollisionRates& rates) const;
  // The level whose MSD history carries the effect of a sweep's start into this level's increments, where this level's
  // MSD is the closed form of a settled start but DSMC starts elsewhere (kinetic-converged-hcs: its own settled ratios
  // against DSMC's Maxwellian ones; increment_ratios, scene_theory.cpp), and the level one order below it, whose same
  // factor against the companion's is that factor's model error (the last correction). Empty: the level's history is
  // from the start.
  struct StartCompanions {
    std::string level, lower;
  };
  virtual StartCompanions start_companion() const { return {}; }
};

// "paper" or "kinetic" (scene.theory.level), or "kinetic-sonineN", N = 1 … 5 (the kinetic level with D_k to
// Sonine order N, the lower order of a scene's correction_from = "sonineN"), the variants "kinetic-cooling3",
// "kinetic-cooling3-shaped", "kinetic-cooling3-sonineN", "kinetic-cooling4" and "kinetic-hcs-converged"; throws
// std::invalid_argument otherwise.
std::unique_ptr<TheoryLevel> make_theory_level(const std::string& name);

// The level whose curves a scene at `level` compares with for correction_from = `correction` (theory.tsv columns
// `<quantity>_<correction>`): "paper", "kinetic", "cooling3" → kinetic-cooling3, "sonine1" → the level with the
// first-Sonine D (kinetic-sonine1, kinetic-cooling3-sonine1); beside kinetic-converged-cooling3 also "converged" →
// kinetic-converged (its first-Sonine temperatures) and "sonine4" → kinetic-cooling3 (its D at Sonine order 4). Throws std::invalid_argument where there is none
// (scene.cpp refuses those scenes with a message first).
std::string companion_level(const std::string& level, const std::string& correction);

}  // namespace granmix::theory
