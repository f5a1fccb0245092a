#pragma once
// The settled (HCS) state of a mixture as `granmix hcs` reports it (docs/architecture.md §3): the options of its two
// forms, every quantity it computes, and its JSON object (`granmix hcs --json`). The command line and the Python module
// (granmix.hcs, docs/python.md) share it, so both give the same keys and the same numbers. What each field is:
// compare/command_hcs.cpp.
#include <nlohmann/json.hpp>

#include <optional>
#include <utility>
#include <vector>

#include "model/mixture.hpp"
#include "theory/grid/converged_hcs.hpp"
#include "theory/grid/tracer_temperature.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_truncation.hpp"

namespace granmix::compare {

// Listed species (mass, diameter, density, eps) or MG's binary (mu, delta, w, alpha or the three per-pair alphas);
// nstar > 0: Enskog χ at that reduced density. The negative and zero defaults mean "not given".
struct HcsOptions {
  std::vector<double> mass, diameter, density;
  double eps = -1.0, nstar = 0.0;
  double mu = 0, delta = 0, w = 0, alpha = -1, alpha11 = -1, alpha22 = -1, alpha12 = -1;
  bool converged = false;
};

struct HcsSummary {
  explicit HcsSummary(model::Mixture m) : mix(std::move(m)) {}
  model::Mixture mix;
  bool has_tau0 = false;   // τ₀ needs an absolute density: not for the dilute MG form, nor a gas that does not cool
  double eps_one = -1.0;   // the one constant restitution of the one-species second Sonine (negative: none)
  theory::SettledDiffusion d;
  theory::SonineHcs sonine;
  std::optional<theory::SonineHcs> third;
  std::vector<double> sonine2;                  // D_k[2]/D_k[1] (NaN: no diffusive solution)
  std::vector<std::vector<double>> orders;      // D_k[M]/D_k[1], M = 1… up to the first without a diffusive solution
  std::vector<double> converged, change;        // D_k/D_k[1] without the Sonine truncation and its change (NaN: none)
  theory::TracerTemperature tracer, intruder;   // binaries (NaN θ: none)
  std::optional<theory::ConvergedHcs> grid;     // on request (converged)
  std::optional<theory::SonineTruncation> trunc;
};

// Throws InputError ("hcs: …", naming the command line's flag) for options out of range.
HcsSummary compute_hcs(const HcsOptions& options);
nlohmann::ordered_json hcs_json(const HcsSummary& h);

}  // namespace granmix::compare
