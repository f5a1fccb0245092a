#pragma once
// The tiny runs whose checkpoint files the checkpoint harness reads (fuzz_checkpoint.cpp) and whose
// real snapshots seed its corpus (make_checkpoint_corpus.cpp): an event-driven run with every part
// a snapshot can hold (displacements, cumulants, histograms, TAMSD), and a time-step run.
#include <string>
#include <vector>

#include "dsmc/ensemble.hpp"

namespace granmix::fuzz {

inline std::vector<dsmc::DsmcSetup> checkpoint_runs() {
  dsmc::DsmcSetup e;
  e.mixture = model::Mixture({{1, 1, 0.05}, {4, 1.5, 0.05}});
  e.law = model::Restitution::constant(2, 0.8);
  e.counts = {6, 4}, e.T0 = {1.0, 1.0}, e.times = {0.5, 2.0, 8.0};
  e.msd = true, e.cumulant = true, e.distribution_bins = 3, e.method = dsmc::Method::direct;
  e.tamsd_measurement_time = 8.0, e.tamsd_lags = {0.5, 2.0}, e.tamsd_tracers = 2;
  e.seed = 5, e.replicas = 2, e.scene_sha256 = std::string(64, 'f'), e.unit_key = "fuzz.event";
  dsmc::DsmcSetup t = e;
  t.method = dsmc::Method::timestep, t.tamsd_measurement_time = 0.0, t.tamsd_lags.clear(), t.time_step_factor = 0.1;
  t.unit_key = "fuzz.timestep";
  return {e, t};
}

inline const char* checkpoint_fuzz_version = "fuzz";

}  // namespace granmix::fuzz
