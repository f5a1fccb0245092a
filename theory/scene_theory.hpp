#pragma once
// The theory curves a scene asks for, and nothing else (docs/architecture.md §1: "model only what a scene
// needs"): temperatures, MSD, t_s, D_k/D_1, γ, TAMSD along the time grid, or settled D_k/D_1
// along a parameter sweep.
#include <memory>
#include <string>

#include "model/scene.hpp"
#include "model/table.hpp"
#include "theory/histories/temperature_history.hpp"

namespace granmix::theory {

// A scene read and checked against the theory levels' catalogue (model::load_scene with theory::level_rules()):
// the one way in for every command, study and test.
model::Scene load_scene(const std::string& path);
model::Scene load_scene_text(const std::string& text, const std::string& path);

struct TheoryResult {
  model::Table table;
  SolverStats stats;     // of the temperature integration (zero when none was needed)
  double seconds = 0.0;  // wall time of the whole theory evaluation
};

// tables: the Galerkin pair tables its levels share (null: a store of its own); a caller that runs the same scene
// again (compare's error estimate at 100× tighter rtol) passes the same store, so the tables are built once.
TheoryResult run_theory(const model::Scene& scene, std::shared_ptr<GalerkinPairTables> tables = nullptr);
// Whether the scene's curves come from integrations in time (rtol applies): not for a sweep of settled γ or c alone,
// nor for settled distributions — those are algebraic HCS, the same at any rtol (compare skips its rtol/100 rerun).
bool theory_uses_rtol(const model::Scene& scene);
// One level's curves alone (level: paper, kinetic, kinetic-sonineN; no companion columns), timed:
// `granmix bench theory` compares the levels' cost scene by scene.
TheoryResult run_level(const model::Scene& scene, const std::string& level);

// Factor from the scene's time unit to natural units (1, or MG's t0 for [time] unit = "mg"), and
// the conversion of a table's time columns (t, lag, t_s) by a factor.
double scene_time_unit(const model::Scene& scene);
void rescale_time_columns(model::Table& table, double factor);

// χ_ij of a scene's mixture: Enskog (MG Eq. 26) when the scene asks for it, else 1.
std::vector<std::vector<double>> scene_contact_values(const model::Scene& scene);

// The rates of a scene's mixture and law, with χ from Enskog or 1.
CollisionRates scene_rates(const model::Scene& scene, const model::Mixture& mix, const model::Restitution& law);

}  // namespace granmix::theory
