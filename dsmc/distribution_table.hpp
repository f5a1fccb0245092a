#pragma once
// The settled DSMC distribution as a table over v* (MG Figs. 3, 7): Φ_k, Δ_k (MG Eq. 27 solved for
// Δ with the simulation's own c_k and λ_k) and G_k (MG Eq. 30), each with its standard error.
#include "ensemble.hpp"
#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::dsmc {

// r must come from a run with distribution_time_average and cumulant set (run_scene_dsmc does it).
model::Table settled_distribution_table(const model::Scene& scene, const DsmcSetup& setup, const DsmcResult& r);

}  // namespace granmix::dsmc
