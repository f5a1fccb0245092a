#pragma once
// The DSMC curves a scene asks for (design.md §4): T, msd, c, gamma and collisions with their
// standard errors over replicas, in the long form of theory.tsv (species 0: ⟨T⟩, total MSD,
// γ = T_1/T_2, collisions per particle of the whole system).
#include <cstdint>
#include <functional>
#include <string>

#include "ensemble.hpp"
#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::dsmc {

struct DsmcRun {
  model::Table table;
  model::Table distribution;  // t, species, v, phi, phi_err per sample time (empty unless asked; settled: in table)
  DsmcResult result;
  DsmcSetup setup;
};

// fidelity: "quick" or "paper". progress(done, total) is called as replicas finish.
DsmcRun run_scene_dsmc(const model::Scene& scene, const std::string& fidelity, std::uint64_t seed, int threads,
                       const std::function<void(std::size_t, std::size_t)>& progress = {});

// Sweep scenes: one settled-state run per value in dsmc.at; rows (x, species) with D_ratio, gamma,
// c and their errors, in the long form of the theory sweep table.
DsmcRun run_sweep_dsmc(const model::Scene& scene, const std::string& fidelity, std::uint64_t seed, int threads,
                       const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace granmix::dsmc
