#pragma once
// A theory level: how the kinetic equations are closed (docs/levels.md). A scene chooses one with `[theory] level`;
// every curve of theory.tsv is computed through it. The levels and their variants declare themselves in the catalogue
// (level_catalogue.hpp), each in its own file: paper_level.cpp, kinetic_level.cpp, converged_level.cpp,
// hcs_converged_level.cpp. Each level has a tracer form (scene `tracer = true`, docs/physics.md §4).
// A level is a type, chosen once per scene: the code that computes curves never asks which it is.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/diffusion.hpp"
#include "model/scene.hpp"
#include "theory/histories/msd.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/histories/temperature_history.hpp"
#include "theory/grid/tracer_form.hpp"
#include "theory/rates/tracer_limit.hpp"

namespace granmix::theory {

struct LevelDescriptor;

class TheoryLevel {
 public:
  virtual ~TheoryLevel() = default;
  // Its catalogue entry (name, companions, how to make another): set by LevelDescriptor::make.
  const LevelDescriptor& descriptor() const { return *descriptor_; }
  const char* name() const;
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
  // The binary tracer limit (species 2 an intruder with n₂ → 0) in the level's closure, at T₁ = 1: its settled θ.
  virtual TracerLimit tracer(const CollisionRates& rates) const = 0;
  // The tracer limit in time to t_end (tracer_form.hpp): closed forms from tracer(rates), settled from the start (they
  // take no start), unless the level relaxes it from the intruders' start theta0 (the scene's: tracer_start_theta).
  virtual std::unique_ptr<TracerForm> tracer_form(const CollisionRates& rates, double theta0, double t_end) const;
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

 private:
  friend struct LevelDescriptor;
  const LevelDescriptor* descriptor_ = nullptr;
};

}  // namespace granmix::theory
