#pragma once
// The settled (HCS) state of a mixture as `granmix hcs` reports it (docs/architecture.md §3): the options of its two
// forms, every quantity it computes, and its JSON object (`granmix hcs --json`). The command line and the Python module
// (granmix.hcs, docs/python.md) share it, so both give the same keys and the same numbers. What each field is:
// compare/command_hcs.cpp.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hcs_warnings.hpp"
#include "model/mixture.hpp"
#include "theory/grid/converged_hcs.hpp"
#include "theory/grid/tracer_temperature.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_truncation.hpp"

namespace granmix::compare {

// The converged HCS (converged): N² pair grids per pass, ~25 ms each, up to this many species.
inline constexpr std::size_t max_converged_hcs_species = 10;

// Listed species (mass, diameter, density, eps) or MG's binary (mu, delta, w, alpha or the three per-pair alphas);
// nstar > 0: Enskog χ at that reduced density. Empty: not given.
struct HcsOptions {
  std::vector<double> mass, diameter, density;
  std::optional<double> eps;
  double nstar = 0.0;
  std::optional<double> mu, delta, w, alpha, alpha11, alpha22, alpha12;
  bool converged = false;
};

struct HcsSummary {
  HcsSummary(HcsOptions o, model::Mixture m) : options(std::move(o)), mix(std::move(m)) {}
  HcsOptions options;      // as given (the JSON's "inputs")
  model::Mixture mix;
  bool has_tau0 = false;   // τ₀ needs an absolute density: not for the dilute MG form, nor a gas that does not cool
  double eps_one = -1.0;   // the one constant restitution of the one-species second Sonine (negative: none)
  theory::SettledDiffusion d;
  theory::SonineHcs sonine;
  std::optional<theory::SonineHcs> third;
  std::optional<std::string> third_failure;     // why the Sonine order 3 has no steady state (then no `third`)
  std::vector<double> sonine2;                  // D_k[2]/D_k[1] (NaN: no diffusive solution)
  std::vector<std::vector<double>> orders;      // D_k[M]/D_k[1], M = 1… up to the first without a diffusive solution
  std::vector<double> converged, change;        // D_k/D_k[1] without the Sonine truncation and its change (NaN: none)
  theory::TracerTemperature tracer, intruder;   // binaries (NaN θ: none)
  std::optional<theory::ConvergedHcs> grid;     // on request (converged)
  std::optional<theory::SonineTruncation> trunc;
  std::vector<HcsWarning> warnings;             // where the first Sonine breaks down (hcs_warnings.hpp)
};

// Throws InputError ("hcs: …", naming the command line's flag) for options out of range.
HcsSummary compute_hcs(const HcsOptions& options);
nlohmann::ordered_json hcs_json(const HcsSummary& h);

}  // namespace granmix::compare
