#pragma once
// A scene: one figure or table of a paper (docs/architecture.md §4). The schema is documented in
// docs/scenes.md; load_scene() refuses anything else with file:line: key: message.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "initial_state.hpp"
#include "level_rules.hpp"
#include "mixture.hpp"
#include "restitution.hpp"

namespace granmix::model {

struct Observables {
  bool temperatures = false;   // column T (species 0: ⟨T⟩)
  bool msd = false;            // column msd (species 0: total MSD, v1 Eq. 16)
  bool msd_ratio = false;      // column msd_ratio = ⟨R_k²⟩/⟨R_1²⟩ (v1 Fig. 8)
  bool rescaled_time = false;  // column t_s (v1 Fig. 1)
  bool d_ratio = false;        // column D_ratio = D_k/D_1 (in time, or settled along a sweep)
  bool gamma = false;          // column gamma = T_1/T_2 (species 0 row)
  bool tamsd = false;          // columns lag, tamsd (lags = the time grid)
  std::size_t distribution_bins = 0;  // DSMC: Φ_k(v*) histogram -> distribution.tsv (0: none)
  double distribution_vmax = 4.0;
  // The settled Φ_k(v*), Δ_k(v*), G_k(v*) (MG Figs. 3, 7): theory.tsv and dsmc.tsv are tables over
  // v* (bin centres) instead of time; the DSMC histogram is averaged over the [time] samples.
  bool distribution_settled = false;
  bool cumulant = false;       // column c = 2[(3/5)⟨v⁴⟩/⟨v²⟩² − 1] (DSMC; theory with the Sonine solver)
  double tamsd_measurement_time = 0.0;
  std::size_t tamsd_tracers = 100;  // DSMC: tracer particles per species
  bool needs_msd() const { return msd || msd_ratio; }
};

struct Sweep {
  // eps: the restitution coefficient of every pair; density: n_k of one species; n_star: the reduced
  // density n σ_12³ of MG (Enskog χ, MG Eq. 26; 0 = dilute), all densities scaled together (MG Fig. 6).
  enum class Parameter { eps, density, n_star } parameter = Parameter::eps;
  std::size_t species = 0;  // density: 0-based species whose density is swept
  std::vector<double> values;
  const char* column() const { return parameter == Parameter::eps ? "eps" : parameter == Parameter::density ? "density" : "n_star"; }
};

struct TheorySettings {
  // The theory level judged (docs/levels.md). "auto" (a user's scene that names none): chosen before the theory
  // runs, by theory/level_choice.hpp, as the cheapest level whose computed model error meets auto_target; a paper
  // scene that names none: the catalogue's default. A scene at any other level than the papers' also gets the paper
  // level's curves in theory.tsv as `<column>_paper`.
  std::string level;
  double auto_target = 0.03;  // level = "auto": the largest computed model error accepted (relative)
  std::string level_choice;   // level = "auto", once chosen: which level and why, in words
  bool level_is_auto() const { return level == LevelRules::auto_level; }
  std::string msd = "eq17";        // eq17 | vacf | longtime | closed
  std::string moments = "auto";    // viscoelastic rates: auto | series | quadrature
  double rtol = 1e-11;             // CVODE relative tolerance
  bool tracer = false;             // binary tracer limit (species 2 = intruder)
  std::optional<Sweep> sweep;      // settled quantities along a parameter
};

// [dsmc]: how to simulate the scene (docs/architecture.md §4). Particles are a total, split over species in
// proportion to the number densities; one set per fidelity.
struct DsmcFidelity {
  std::size_t particles = 0;
  std::size_t replicas = 0;
};

struct DsmcSettings {
  bool present = false;
  std::string method = "auto";  // auto | direct | lowrank | bird | timestep
  double time_step = 3e-3;      // timestep: Δt = time_step λ11/v01(t) (MG Sec. 3)
  bool rescale = true;          // scale initial velocities to exactly T_k(0)
  // Sweep scenes: the swept values simulated (settled start; [time] gives the sample times:
  // γ and c at the last, D_k/D_1 from MSD increments between the first and the last).
  std::vector<double> at;
  DsmcFidelity quick, paper;
  bool paper_given = true;  // false: no [dsmc] paper table; --fidelity paper runs the quick settings (and says so)
};

// [compare]: which quantities are compared and with what tolerance (docs/architecture.md §3–4). A point passes
// when |dsmc − theory| <= relative |theory| + z · dsmc_err, or <= absolute: `relative` is the judged
// theory's computed model error, z · dsmc_err the statistical part (the two add: a point can carry
// both); `species` and `t_min` restrict a tolerance to where it applies.
struct CompareQuantity {
  std::string name;             // a quantity column of both tables (model/observable_catalogue.hpp)
  std::string theory;           // the theory column that predicts the DSMC column `name` (default: name)
  // Model error computed point by point as the size of the judged theory's last or next correction:
  // |theory − theory_<correction_from>| / |theory|, each name a companion of the judged level (the level with one
  // part changed: theory/levels/level_catalogue.hpp, docs/judging.md §3.2) or "maxwell" (the Maxwellian column of a
  // Sonine quantity), added to `relative`. Several: the largest of them at each point (the corrections of independent
  // truncations). Empty: `relative` alone.
  std::vector<std::string> correction_from;
  // A theory column holding the judged level's own computed model error at each point (relative), added too: one of
  // the error columns the level declares in the catalogue. Empty: none.
  std::string error_column;
  // The resolution the judged level claims for this quantity (relative): a judged point whose model error (relative
  // + the computed parts) exceeds it fails as unresolved, whatever DSMC says. A bound computed from companions widens
  // with a bug that moves the companions as much as the level (oscillating densities, docs/reliability.md, "kill table"); this is the
  // check that the computed bound is itself what the level was built to resolve (3% for MSDs, T and D ratios; docs/judging.md §4). Infinite: none.
  double model_error_max = INFINITY;
  double relative = 0.05, z = 4.0;
  double absolute = 0.0;        // for quantities that cross zero (c): |dsmc − theory| <= absolute also passes
  std::vector<std::size_t> species;  // 1-based; empty: all rows (species 0 included)
  double t_min = 0.0;           // points at t < t_min are reported but not judged
  double x_max = 1e300;         // nor points whose first column (t, v*, swept value) exceeds x_max
  std::string why;              // the reason for the tolerance, carried into report.json
};

// [plot]: the figure of the paper (docs/architecture.md §3).
struct PlotSettings {
  std::string x = "t", y = "msd";  // x = "species": the values at the last time
  std::string xlabel, ylabel;      // empty: the catalogue's label with units (model::axis_label)
  std::string key = "top left";  // where the legend sits in the figure's right margin: its top or bottom
  std::optional<bool> logx, logy;  // unset: logarithmic where the data span more than two decades
  bool maxwell = false;  // also draw theory's `<y>_maxwell` column dashed (MG Fig. 7's Maxwell–Boltzmann lines)
  std::vector<std::size_t> species;  // curves drawn (0 = the total row); empty: every species
  std::vector<std::string> slopes;  // guide lines: "2", "1", "1/6", "log"
};

struct Scene {
  std::string file;    // path as given
  std::string text;    // file content (hashed for provenance)
  std::string name, source, title;
  Mixture mixture{{Species{}}};
  Restitution restitution = Restitution::constant(1, 1.0);
  bool enskog = false;
  InitialState initial;
  std::vector<double> times;  // in the scene's unit (see time_unit)
  bool time_unit_mg = false;  // [time] unit = "mg": times in t0 = λ11/v01(0) (MG Fig. 1)
  Observables observables;
  TheorySettings theory;
  DsmcSettings dsmc;
  std::vector<CompareQuantity> compare;
  bool compare_generated = false;  // no [compare] but [dsmc]: compare holds the default comparison
  PlotSettings plot;
};

// Throws InputError("file:line: key: what is wrong (allowed: …)"). `levels`: the theory levels' rules
// (theory::level_rules(), from the level catalogue).
// path "-": the scene's text from standard input (named <stdin> in messages).
Scene load_scene(const std::string& path, const LevelRules& levels);
// The same from the file's text; `path` only names it in messages (and Scene::file). Fuzzed in tests/fuzz.
Scene load_scene_text(const std::string& text, const std::string& path, const LevelRules& levels);

// A scene with [dsmc] and without [compare] is judged by default (docs/judging.md, "The default comparison"): every
// quantity it asks for that DSMC measures, z = 4, model error from every companion its level has for that quantity in
// this scene (fixed relative 0.05 where there is none), a generated `why` saying so.
std::vector<CompareQuantity> default_comparison(const Scene& scene, const LevelRules& levels);

// The paper scenes: the files of the folder compare/scenes (and compare/paper-size), whose tolerances must say why
// and whose figures keep the paper's single panel.
bool is_paper_scene(const std::string& path);

// The scene at one value x of its sweep (mixture, restitution, Enskog as the parameter says), sweep removed.
Scene sweep_point(const Scene& scene, double x);

}  // namespace granmix::model
