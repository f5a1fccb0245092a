#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>

#include "enskog.hpp"
#include "errors.hpp"
#include "mixture_generators.hpp"
#include "model_error.hpp"
#include "observable_catalogue.hpp"
#include "toml_fields.hpp"

namespace granmix::model {

namespace {

constexpr double huge = 1e300;

Mixture read_mixture(TomlFields& f) {
  const int forms = int(f.has("species")) + int(f.has("power_law")) + int(f.has("montanero_garzo")) + int(f.has("exponential"));
  if (forms != 1)
    f.fail("species", "give exactly one of 'species' (a list), 'power_law', 'exponential' or 'montanero_garzo' (tables)",
           "species, power_law, exponential, montanero_garzo");
  if (f.has("exponential")) {
    TomlFields x = f.sub("exponential");
    Exponential e;  // v2 Fig. 6 / Table 1 (model/mixture_generators.hpp)
    e.n1_particles = x.number("n1_particles", 1.0, 1e12);
    e.decay = x.number("decay", 0.0, 100.0);
    e.species = x.count("species", 1, 1000000, std::nullopt);
    e.total_density = x.positive("total_density");
    e.diameter_exponent = x.number("diameter_exponent", 0.0, 1.0, 1.0 / 3.0);
    e.mass1 = x.positive("mass1", 1.0);
    e.diameter1 = x.positive("diameter1", 1.0);
    x.finish();
    return exponential_mixture(e);
  }
  const bool law = f.has("power_law");
  if (f.has("montanero_garzo")) {
    TomlFields m = f.sub("montanero_garzo");
    // MG Sec. 3 parameters; units m_2 = σ_22 = 1 (model/mixture_generators.hpp).
    const double mu = m.number("mu", 1e-6, 1e6), delta = m.number("delta", 1e-6, 1e6), w = m.number("w", 1e-3, 1e3);
    const double nstar = m.number("n_star", 0.0, 1.9, 0.0);
    m.finish();
    return montanero_garzo_binary(mu, delta, w, nstar);
  }
  if (law) {
    TomlFields p = f.sub("power_law");
    PowerLaw pl;
    pl.n1 = p.positive("n1");
    pl.theta = p.number("theta", 0.0, 20.0);
    pl.n1_particles = p.number("n1_particles", 1.0, 1e15);
    pl.diameter_exponent = p.number("diameter_exponent", 0.0, 1.0, 1.0 / 3.0);
    pl.mass1 = p.positive("mass1", 1.0);
    pl.diameter1 = p.positive("diameter1", 1.0);
    pl.max_species = p.count("max_species", 1, 1000000, 100000);
    p.finish();
    return power_law_mixture(pl);
  }
  const toml::node* n = f.node("species");
  const toml::array* a = n->as_array();
  if (a == nullptr || a->empty()) f.fail("species", "expected a non-empty array of tables", "[{mass = …, diameter = …, density = …}, …]");
  // The fractions form: a total number density and relative amounts (normalised), the species giving mass and
  // diameter only. Without `fraction` the species share the total equally.
  std::optional<double> total;
  std::vector<double> fractions;
  if (f.has("density")) total = f.positive("density");
  if (f.has("fraction")) {
    if (!total) f.fail("fraction", "needs the total number density beside it", "[mixture] density = n, fraction = [x1, x2, …]");
    fractions = f.numbers("fraction", 0.0, huge);
    if (fractions.size() != a->size())
      f.fail("fraction", std::to_string(fractions.size()) + " values for " + std::to_string(a->size()) + " species", "one fraction > 0 per species");
    for (double x : fractions)
      if (!(x > 0.0)) f.fail("fraction", "value " + format_number(x) + " must be positive", "one fraction > 0 per species");
  }
  if (total && fractions.empty()) fractions.assign(a->size(), 1.0);
  double sum = 0.0;
  for (double x : fractions) sum += x;
  std::vector<Species> out;
  for (const toml::node& e : *a) {
    if (!e.is_table()) f.fail_at(e, "species", "element is not a table", "{mass = …, diameter = …, density = …}");
    TomlFields s(*e.as_table(), f.file(), "mixture.species[" + std::to_string(out.size() + 1) + "]");
    if (total && s.has("density"))
      s.fail("density", "given here and as the total [mixture] density", "either density per species, or [mixture] density with fraction");
    const double mass = s.positive("mass"), diameter = s.positive("diameter");
    const double density = total ? *total * (fractions[out.size()] / sum) : s.positive("density");
    out.push_back({mass, diameter, density});
    s.finish();
  }
  return Mixture(std::move(out));
}

Restitution read_collisions(TomlFields& f, const Mixture& mix, bool& enskog) {
  enskog = f.flag("enskog", false);
  const toml::node* n = f.node("restitution");
  const std::string allowed = "a number in [0, 1], a symmetric N×N matrix, or {viscoelastic = Aκ^(2/5), form = …}";
  if (n == nullptr) f.fail("restitution", "missing", allowed);
  if (n->is_number()) {
    const double e = f.number("restitution", 0.0, 1.0);
    return Restitution::constant(mix.size(), e);
  }
  if (n->is_table()) {
    TomlFields v = f.sub("restitution");
    // Aκ^(2/5) of the 1–1 pair; 10 is far beyond any material (v1 uses 0.09).
    const double ak = v.number("viscoelastic", 0.0, 10.0);
    const auto form = parse_viscoelastic_form(v.choice("form", {"exact", "series", "pade"}, "exact"));
    v.finish();
    return Restitution::viscoelastic(mix, ak, form);
  }
  const toml::array* rows = n->as_array();
  if (rows == nullptr || rows->size() != mix.size()) f.fail("restitution", "expected a scalar or one row per species", allowed);
  std::vector<std::vector<double>> eps;
  for (const toml::node& row : *rows) {
    const toml::array* r = row.as_array();
    if (r == nullptr || r->size() != mix.size()) f.fail_at(row, "restitution", "each row needs one value per species", allowed);
    eps.emplace_back();
    for (const toml::node& e : *r) {
      if (!e.is_number()) f.fail_at(e, "restitution", "matrix element is not a number", allowed);
      const double v = e.value<double>().value();
      if (!(v >= 0.0 && v <= 1.0)) f.fail_at(e, "restitution", "matrix element " + format_number(v) + " out of range", allowed);
      eps.back().push_back(v);
    }
  }
  for (std::size_t k = 0; k < eps.size(); ++k)
    for (std::size_t i = 0; i < k; ++i)
      if (eps[k][i] != eps[i][k]) f.fail("restitution", "matrix is not symmetric", allowed);
  return Restitution::constant_matrix(std::move(eps));
}

InitialState read_initial(TomlFields& f, std::size_t species) {
  InitialState s;
  const toml::node* n = f.node("temperatures");
  const std::string allowed = "\"equal\", \"hcs\", \"aged\" (with hot = T) or a list of one positive T per species";
  if (n == nullptr || n->is_string()) {
    const std::string kind = f.choice("temperatures", {"equal", "hcs", "aged"}, "equal");
    s.kind = kind == "equal" ? InitialState::Kind::equal : kind == "hcs" ? InitialState::Kind::hcs : InitialState::Kind::aged;
    if (s.kind == InitialState::Kind::aged) s.T_hot = f.number("hot", 1.0 + 1e-9, 1e12);
  } else {
    s.kind = InitialState::Kind::explicit_list;
    s.values = f.numbers("temperatures", std::numeric_limits<double>::min(), huge);
    if (s.values.size() != species)
      f.fail("temperatures", "list has " + std::to_string(s.values.size()) + " values for " + std::to_string(species) + " species", allowed);
  }
  if (s.kind != InitialState::Kind::aged && f.has("hot")) f.fail("hot", "only used with temperatures = \"aged\"", "");
  return s;
}

std::vector<double> grid(TomlFields& f, const std::string& spacing_key, double lo, double hi) {
  const double start = f.number("from", lo, hi);
  const double end = f.number("to", lo, hi);
  const std::size_t points = f.count("points", 1, 100000, std::nullopt);
  const std::string spacing = f.choice(spacing_key, {"log", "linear"}, "linear");
  if (points > 1 && !(end > start)) f.fail("to", "must be larger than 'from'", "to > from");
  if (spacing == "log" && !(start > 0.0)) f.fail("from", "log spacing needs from > 0", "from > 0");
  std::vector<double> v(points);
  for (std::size_t j = 0; j < points; ++j) {
    const double u = points == 1 ? 0.0 : static_cast<double>(j) / static_cast<double>(points - 1);
    v[j] = spacing == "log" ? start * std::pow(end / start, u) : start + (end - start) * u;
  }
  return v;
}

std::vector<double> read_times(TomlFields& f) {
  std::vector<double> t;
  if (f.has("times")) {
    t = f.numbers("times", std::numeric_limits<double>::min(), 1e15);
    for (std::size_t j = 1; j < t.size(); ++j)
      if (!(t[j] > t[j - 1])) f.fail("times", "must increase strictly", "increasing positive times");
    return t;
  }
  const double end = f.number("end", 1e-12, 1e15);
  const std::size_t points = f.count("points", 1, 100000, 60);
  const std::string spacing = f.choice("spacing", {"log", "linear"}, "log");
  const double start = f.number("start", 1e-12, end, spacing == "log" ? end * 1e-6 : end / points);
  for (std::size_t j = 0; j < points; ++j) {
    const double u = points == 1 ? 1.0 : static_cast<double>(j) / static_cast<double>(points - 1);
    t.push_back(spacing == "log" ? start * std::pow(end / start, u) : start + (end - start) * u);
  }
  return t;
}

Observables read_observables(TomlFields& f) {
  Observables o;
  o.temperatures = f.flag("temperatures", false);
  o.msd = f.flag("msd", false);
  o.msd_ratio = f.flag("msd_ratio", false);
  o.rescaled_time = f.flag("rescaled_time", false);
  o.d_ratio = f.flag("d_ratio", false);
  o.gamma = f.flag("gamma", false);
  o.cumulant = f.flag("cumulant", false);
  if (f.has("distribution")) {
    TomlFields d = f.sub("distribution");
    o.distribution_bins = d.count("bins", 1, 10000, 40);
    o.distribution_vmax = d.number("v_max", 1e-3, 100.0, 4.0);
    o.distribution_settled = d.flag("settled", false);
    d.finish();
  }
  if (f.has("tamsd")) {
    TomlFields t = f.sub("tamsd");
    o.tamsd = true;
    o.tamsd_measurement_time = t.positive("measurement_time");
    o.tamsd_tracers = t.count("tracers", 1, 100000, 100);
    t.finish();
  }
  const auto& all = observable_catalogue();
  if (std::none_of(all.begin(), all.end(), [&](const ObservableDescriptor& d) { return d.asked(o); })) {
    std::string keys;
    for (const std::string& k : observable_keys()) keys += (keys.empty() ? "" : ", ") + k;
    f.fail("temperatures", "the scene asks for no observable", keys);
  }
  return o;
}

// A scene that names no level: the papers' own scenes keep the catalogue's default; a user's scene gets "auto", the
// cheapest level whose computed model error meets [theory] auto_target (docs/levels.md, "Choosing a level").
std::string default_level(const LevelRules& levels, const std::string& path) {
  return is_paper_scene(path) ? levels.default_level : std::string(LevelRules::auto_level);
}

TheorySettings read_theory(TomlFields& f, const Mixture& mix, const LevelRules& levels, const std::string& path) {
  TheorySettings s;
  std::vector<std::string> allowed = levels.scene_levels();
  allowed.emplace_back(LevelRules::auto_level);
  s.level = f.choice("level", allowed, default_level(levels, path));
  if (f.has("auto_target") && !s.level_is_auto())
    f.fail("auto_target", "is the model error level = \"auto\" aims at, but theory.level is \"" + s.level + "\"", "level = \"auto\", or no auto_target");
  // 1e-4: below it no level computes its model error reliably (the converged levels' own grids: docs/levels.md);
  // 0.5: above it the comparison says nothing.
  s.auto_target = f.number("auto_target", 1e-4, 0.5, 0.03);
  s.msd = f.choice("msd", {"eq17", "vacf", "longtime", "closed"}, "eq17");
  s.moments = f.choice("moments", {"auto", "series", "quadrature"}, "auto");
  // 1e-14: below it CVODE works at rounding level; 1e-3: above it no comparison means anything.
  s.rtol = f.number("rtol", 1e-14, 1e-3, 1e-11);
  s.tracer = f.flag("tracer", false);
  if (f.has("sweep")) {
    TomlFields w = f.sub("sweep");
    Sweep sw;
    const std::string p = w.choice("parameter", {"eps", "density", "n_star"});
    sw.parameter = p == "eps" ? Sweep::Parameter::eps : p == "density" ? Sweep::Parameter::density : Sweep::Parameter::n_star;
    if (sw.parameter == Sweep::Parameter::density) {
      sw.species = w.count("species", 1, mix.size(), std::nullopt) - 1;
      sw.values = grid(w, "spacing", std::numeric_limits<double>::min(), huge);
    } else if (sw.parameter == Sweep::Parameter::n_star) {
      sw.values = grid(w, "spacing", 0.0, 1.0);  // n σ12³ <= 1: Carnahan–Starling χ is used well below close packing
    } else {
      sw.values = grid(w, "spacing", 0.0, 1.0);
    }
    w.finish();
    s.sweep = sw;
  }
  return s;
}

// Every judged quantity can be matched before anything runs: its observable is asked for, and in a history its judged
// range [t_min, x_max] holds a sample time (else the DSMC would run for a verdict of zero points).
void check_quantities_measured(const Scene& s, TomlFields& top) {
  for (const CompareQuantity& q : s.compare) {
    for (const ObservableDescriptor& d : observable_catalogue())
      if (std::find(d.quantities.begin(), d.quantities.end(), q.name) != d.quantities.end() && !d.asked(s.observables))
        top.fail("compare", "quantity \"" + q.name + "\" is judged, but [observables] does not ask for it",
                 "observables." + d.key + " = true, or no quantity \"" + q.name + "\"");
    const bool in_time = !s.theory.sweep && !s.observables.distribution_settled && !s.times.empty();
    if (in_time && std::none_of(s.times.begin(), s.times.end(), [&](double t) { return judges(q, t); }))
      top.fail("compare", "quantity \"" + q.name + "\" judges " +
                              (q.x_max < 1e300 ? "t in [" + format_number(q.t_min) + ", " + format_number(q.x_max) + "]" : "t >= " + format_number(q.t_min)) +
                              ", which holds none of the sample times " + format_number(s.times.front()) + " … " + format_number(s.times.back()),
               "t_min <= " + format_number(s.times.back()) + " and x_max >= " + format_number(s.times.front()));
  }
}

void check_combinations(const Scene& s, TomlFields& top, const LevelRules& levels) {
  const auto& o = s.observables;
  const bool settled_start = s.initial.kind == InitialState::Kind::hcs || s.theory.tracer;
  if (s.theory.sweep && (o.temperatures || o.needs_msd() || o.rescaled_time || o.tamsd || o.distribution_bins))
    top.fail("theory", "a sweep gives settled quantities only", "observables d_ratio, gamma, cumulant with theory.sweep");
  if (s.theory.sweep && !(o.d_ratio || o.gamma || o.cumulant))
    top.fail("observables", "a sweep needs d_ratio, gamma or cumulant", "d_ratio, gamma, cumulant");
  if (s.theory.sweep && (o.gamma || o.cumulant) && s.restitution.is_viscoelastic())
    top.fail("theory", "the Sonine solution needs a constant restitution coefficient", "collisions.restitution = number");
  if (o.gamma && s.mixture.size() < 2) top.fail("observables", "gamma = T_1/T_2 needs two species", "two or more species");
  if (s.theory.tracer && s.mixture.size() != 2) top.fail("theory", "tracer = true needs exactly two species", "gas, intruder");
  // The level's own refusals, as its catalogue entry declares them (theory/levels/level_catalogue.hpp); "auto" tries
  // only the levels that accept the scene.
  if (!s.theory.level_is_auto())
    for (const LevelCondition& c : levels.find(s.theory.level)->conditions)
      if (c.violated_by(s)) top.fail("theory", c.what, c.allowed);
  if (s.theory.msd == "closed" && !settled_start)
    top.fail("theory", "msd = \"closed\" holds for a settled start only", "initial.temperatures = \"hcs\" or theory.tracer = true");
  if (s.theory.msd == "closed" && s.restitution.is_viscoelastic())
    top.fail("theory", "msd = \"closed\" needs a constant restitution coefficient", "eq17, vacf, longtime");
  if (o.tamsd && (!settled_start || s.restitution.is_viscoelastic()))
    top.fail("observables", "tamsd uses the settled-state model", "initial.temperatures = \"hcs\" or theory.tracer, constant ε");
  if (o.tamsd && !s.times.empty() && s.times.back() >= o.tamsd_measurement_time)
    top.fail("observables", "tamsd lags (the time grid) must stay below measurement_time", "time.end < measurement_time");
  if (s.theory.sweep && s.dsmc.present && (s.dsmc.at.empty() || s.times.size() < 2))
    top.fail("dsmc", "DSMC of a sweep runs at chosen points", "dsmc.at = [values of the sweep], [time] with two or more times");
  if (!s.theory.sweep && !s.dsmc.at.empty()) top.fail("dsmc", "dsmc.at is for sweep scenes", "theory.sweep with dsmc.at");
  if (s.theory.sweep && s.theory.sweep->parameter == Sweep::Parameter::eps)
    for (double x : s.dsmc.at)
      if (x > 1.0) top.fail("dsmc", "dsmc.at holds restitution coefficients here", "values in [0, 1]");
  if (s.theory.sweep && s.theory.sweep->parameter == Sweep::Parameter::n_star) {
    if (s.mixture.size() != 2) top.fail("theory", "an n_star sweep needs a binary mixture (n* = n σ12³)", "two species");
    for (double x : s.dsmc.at)
      if (x <= 0.0 || x > 1.0) top.fail("dsmc", "dsmc.at holds reduced densities n* here (n* = 0 is always run)", "values in (0, 1]");
  }
  if (o.distribution_settled) {
    if (s.initial.kind != InitialState::Kind::hcs || s.mixture.size() != 2 || s.restitution.is_viscoelastic() || s.theory.sweep)
      top.fail("observables", "distribution.settled compares the first-Sonine HCS of a binary mixture",
               "two species, initial.temperatures = \"hcs\", constant restitution, no sweep");
    if (o.temperatures || o.needs_msd() || o.rescaled_time || o.d_ratio || o.gamma || o.tamsd || o.cumulant)
      top.fail("observables", "a settled distribution scene is a table over v*: no other observable", "distribution only");
  }
  if (s.theory.sweep && s.theory.sweep->parameter == Sweep::Parameter::eps && s.restitution.is_viscoelastic())
    top.fail("theory", "an ε sweep needs a constant restitution coefficient", "collisions.restitution = number");
}

DsmcFidelity read_fidelity(TomlFields& f, const std::string& key) {
  TomlFields t = f.sub(key);
  // 1e8 particles need ~10 GB with displacements: the machine's memory is the limit.
  DsmcFidelity d{t.count("particles", 2, 100000000, std::nullopt), t.count("replicas", 1, 100000, std::nullopt)};
  t.finish();
  return d;
}

DsmcSettings read_dsmc(TomlFields& f) {
  DsmcSettings d;
  d.present = true;
  d.method = f.choice("method", {"auto", "direct", "lowrank", "bird", "bird-global", "timestep"}, "auto");
  // In units of the 1–1 mean free time λ11/v01(t); 10 is already a huge step (tests/dsmc).
  d.time_step = f.number("time_step", 1e-6, 10.0, 3e-3);
  d.rescale = f.flag("rescale", true);
  if (f.has("at")) d.at = f.numbers("at", 0.0, 1e300);
  d.quick = read_fidelity(f, "quick");
  d.paper_given = f.has("paper");
  d.paper = d.paper_given ? read_fidelity(f, "paper") : d.quick;
  return d;
}

std::vector<CompareQuantity> read_compare(TomlFields& f, std::size_t species, const LevelRules& levels, bool paper_scene) {
  std::vector<CompareQuantity> out;
  const toml::node* n = f.node("quantities");
  const std::string allowed = "[{name = \"msd\", relative = 0.05, z = 4, species = [1, 2], t_min = 0, why = \"…\"}, …]";
  if (n == nullptr || !n->is_array() || n->as_array()->empty()) f.fail("quantities", "expected a non-empty array of tables", allowed);
  for (const toml::node& e : *n->as_array()) {
    if (!e.is_table()) f.fail_at(e, "quantities", "element is not a table", allowed);
    TomlFields q(*e.as_table(), f.file(), "compare.quantities[" + std::to_string(out.size() + 1) + "]");
    CompareQuantity c;
    c.name = q.choice("name", observable_quantities());
    // Theory's prediction of exactly what the simulation measures, when the paper's quantity differs
    // (D_ratio: Eq. 19 against MSD increments -> D_ratio_increment).
    c.theory = q.has("theory") ? q.choice("theory", {"D_ratio_increment"}) : c.name;
    // "maxwell": the Maxwellian column of a Sonine quantity beside it (no level); the rest name companion levels.
    std::vector<std::string> corrections{"maxwell"};
    for (const CorrectionRule& r : levels.corrections) corrections.push_back(r.name);
    c.correction_from = q.choices("correction_from", corrections);
    if (q.has("error_column")) c.error_column = q.choice("error_column", levels.error_columns());
    c.relative = q.number("relative", 0.0, 10.0, 0.05);
    if (q.has("model_error_max")) {
      if (c.correction_from.empty() && c.error_column.empty())
        q.fail("model_error_max", "caps a computed model error, but this quantity has none (no correction_from, no error_column)",
               "correction_from or error_column beside it, or no model_error_max");
      c.model_error_max = q.number("model_error_max", 1e-6, 10.0);
    }
    c.z = q.number("z", 0.0, 100.0, 4.0);
    c.absolute = q.number("absolute", 0.0, 1e300, 0.0);
    if (q.has("species"))
      for (double v : q.numbers("species", 0, double(species))) c.species.push_back(static_cast<std::size_t>(v));
    c.t_min = q.number("t_min", 0.0, 1e300, 0.0);
    c.x_max = q.number("x_max", 0.0, 1e300, 1e300);
    // Every tolerance of a shipped paper scene says why it is what it is; elsewhere a missing why is generated.
    c.why = paper_scene || q.has("why") ? q.text("why")
                                        : "no why given in the scene: model error relative = " + format_number(c.relative) +
                                              (c.correction_from.empty() ? "" : " + the companions' differences") + ", z = " + format_number(c.z);
    q.finish();
    out.push_back(c);
  }
  return out;
}

// The computed model errors a scene asks for, against what its level offers (model/level_rules.hpp): an error column
// the level computes for that quantity, companions the level has, on a scene that gives them what they need.
void check_companions(const Scene& s, TomlFields& t, const LevelRules& levels) {
  const std::string& level = s.theory.level;
  if (s.theory.level_is_auto()) {  // companions and error columns are a named level's
    for (const CompareQuantity& q : s.compare) {
      const char* key = !q.error_column.empty() ? "error_column" : "correction_from";
      if (!q.error_column.empty() || std::any_of(q.correction_from.begin(), q.correction_from.end(), [](const std::string& c) { return c != "maxwell"; }))
        t.fail(key, "names what one level computes, but theory.level is \"auto\" (chosen when the theory runs)",
               "a named theory.level (" + [&] {
                 std::string l;
                 for (const std::string& n : levels.scene_levels()) l += (l.empty() ? "" : ", ") + n;
                 return l;
               }() + "), or no " + key + " (the default comparison)");
    }
    return;
  }
  const LevelRule& rule = *levels.find(level);
  auto quoted = [](const std::vector<std::string>& names, const char* joint) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : i + 1 == names.size() ? joint : ", ") + ("\"" + names[i] + "\"");
    return out;
  };
  auto named = [](const std::vector<std::string>& names, const std::string& x) { return names.empty() || std::find(names.begin(), names.end(), x) != names.end(); };
  for (const CompareQuantity& q : s.compare) {
    if (q.error_column.empty()) continue;
    const auto own = std::find_if(rule.error_columns.begin(), rule.error_columns.end(), [&](const ErrorColumnRule& e) { return e.column == q.error_column; });
    if (own != rule.error_columns.end() && named(own->quantities, q.name)) continue;
    std::string what, allowed;
    for (const LevelRule& l : levels.levels)
      for (const ErrorColumnRule& e : l.error_columns) {
        if (e.column == q.error_column && what.empty()) what = e.what;
        if (l.scene_may_choose) allowed += "error_column = \"" + e.column + "\" (" + quoted(e.quantities, " or ") + ") with theory.level = \"" + l.name + "\"; ";
      }
    t.fail("error_column", "\"" + q.error_column + "\" is " + what + ", but the quantity is \"" + q.name + "\" at theory.level \"" + level + "\"",
           allowed + "or no error_column");
  }
  for (const CompareQuantity& q : s.compare)
    for (const std::string& lower : q.correction_from) {
      if (lower == "maxwell") continue;
      const std::string is = "\"" + lower + "\" is " + levels.correction(lower)->what;
      const std::vector<std::string> offering = levels.offering(lower);
      const std::string elsewhere = "theory.level = " + (offering.empty() ? std::string("(none)") : quoted(offering, " or "));
      const CompanionRule* c = rule.companion(lower);
      if (c == nullptr) t.fail("correction_from", is + ", but theory.level is \"" + level + "\"", elsewhere);
      if (c->needs_tracer && !s.theory.tracer)
        t.fail("correction_from", is + ", but theory.level is \"" + level + "\" without theory.tracer", "theory.tracer = true, or " + elsewhere);
      if (c->needs_settled_distribution && !s.observables.distribution_settled)
        t.fail("correction_from", is + ", but theory.level is \"" + level + "\" without observables.distribution",
               "observables.distribution = { settled = true, ... }");
      if (c->needs_history_with_constant_restitution && (s.restitution.is_viscoelastic() || s.theory.sweep))
        t.fail("correction_from", is + ", which needs a constant restitution coefficient and no sweep", "collisions.restitution = number, without sweep");
      if (!named(c->quantities, q.name))
        t.fail("correction_from", is + ", but the quantity is \"" + q.name + "\" at theory.level \"" + level + "\"", "name = " + quoted(c->quantities, " or "));
    }
}


// Whether a companion of the scene's level computes a model error for `quantity` in this scene (check_companions'
// rules, read as a filter instead of a refusal).
bool companion_applies(const CompanionRule& c, const Scene& s, const std::string& quantity) {
  if (c.needs_tracer && !s.theory.tracer) return false;
  if (c.needs_settled_distribution && !s.observables.distribution_settled) return false;
  if (c.needs_history_with_constant_restitution && (s.restitution.is_viscoelastic() || s.theory.sweep)) return false;
  return c.quantities.empty() || std::find(c.quantities.begin(), c.quantities.end(), quantity) != c.quantities.end();
}

}  // namespace

// The paper scenes: the files of the folder compare/scenes (and compare/paper-size), whose tolerances must say why.
bool is_paper_scene(const std::string& path) {
  const std::filesystem::path p = std::filesystem::path(path).lexically_normal();
  const std::filesystem::path dir = p.parent_path();
  return dir.parent_path().filename() == "compare" && (dir.filename() == "scenes" || dir.filename() == "paper-size");
}

std::vector<CompareQuantity> default_comparison(const Scene& s, const LevelRules& levels) {
  const Observables& o = s.observables;
  std::vector<std::string> names;  // what DSMC measures of what the scene asks for, in the catalogue's order
  if (o.temperatures) names.push_back("T");
  if (o.msd) names.push_back("msd");
  if (o.msd_ratio) names.push_back("msd_ratio");
  if (o.gamma) names.push_back("gamma");
  if (o.gamma && s.theory.sweep && s.theory.sweep->parameter == Sweep::Parameter::n_star) names.push_back("gamma_ratio");
  if (o.cumulant) names.push_back("c");
  if (o.d_ratio && s.theory.sweep) names.push_back("D_ratio");
  if (o.tamsd) names.push_back("tamsd");
  if (o.rescaled_time) names.push_back("t_s");
  if (o.distribution_settled) names.insert(names.end(), {"phi", "delta", "G"});
  const LevelRule& rule = *levels.find(s.theory.level);
  std::vector<CompareQuantity> out;
  for (const std::string& name : names) {
    CompareQuantity c;
    c.name = name;
    c.theory = name == "D_ratio" ? "D_ratio_increment" : name;  // DSMC measures D_k/D_1 by MSD increments
    for (const CompanionRule& comp : rule.companions)
      if (companion_applies(comp, s, name)) c.correction_from.push_back(comp.correction);
    c.z = 4.0;
    c.relative = c.correction_from.empty() ? 0.05 : 0.0;
    std::string list;
    for (const std::string& x : c.correction_from) list += (list.empty() ? "" : ", ") + x;
    c.why = c.correction_from.empty()
                ? "default comparison (the scene has no [compare]): level " + s.theory.level + " computes no companion for " + name +
                      ", so the model error is the fixed relative = 0.05; statistical part z = 4 (docs/judging.md, \"The default comparison\")"
                : "default comparison (the scene has no [compare]): model error at each point = the largest difference of level " + s.theory.level +
                      " to its companions " + list + "; statistical part z = 4 (docs/judging.md, \"The default comparison\")";
    out.push_back(std::move(c));
  }
  return out;
}

namespace {

PlotSettings read_plot(TomlFields& f) {
  PlotSettings p;
  p.x = f.choice("x", {"t", "t_s", "eps", "density", "n_star", "lag", "v", "species"}, "t");
  p.y = f.choice("y", plotted_quantities(), "msd");
  if (f.has("logx")) p.logx = f.flag("logx", false);
  if (f.has("logy")) p.logy = f.flag("logy", false);
  p.maxwell = f.flag("maxwell", false);
  p.xlabel = f.text("xlabel", "");
  p.ylabel = f.text("ylabel", "");
  p.key = f.choice("key", {"top left", "top right", "bottom left", "bottom right"}, "top left");
  if (f.has("species"))
    for (double v : f.numbers("species", 0, 1e7)) p.species.push_back(static_cast<std::size_t>(v));
  if (f.has("slopes")) {
    const toml::node* n = f.node("slopes");
    if (!n->is_array()) f.fail("slopes", "expected an array", "[\"2\", \"1\", \"1/6\", \"log\"]");
    for (const toml::node& e : *n->as_array()) {
      const auto v = e.value<std::string>();
      if (!v || (*v != "2" && *v != "1" && *v != "1/6" && *v != "log"))
        f.fail_at(e, "slopes", "unknown guide slope", "\"2\", \"1\", \"1/6\", \"log\"");
      p.slopes.push_back(*v);
    }
  }
  return p;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the scene file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

Scene load_scene(const std::string& path, const LevelRules& levels) {
  if (path == "-") {  // the scene on standard input (a pipe or a here-document), named <stdin> in messages
    std::ostringstream text;
    text << std::cin.rdbuf();
    if (text.str().empty()) throw InputError("<stdin>: the scene given as - is empty (allowed: a scene's TOML on standard input)");
    return load_scene_text(text.str(), "<stdin>", levels);
  }
  return load_scene_text(read_file(path), path, levels);
}

Scene load_scene_text(const std::string& text, const std::string& path, const LevelRules& levels) {
  Scene s;
  s.file = path;
  s.text = text;
  toml::table root;
  try {
    root = toml::parse(s.text, path);
  } catch (const toml::parse_error& e) {
    throw InputError(path + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()));
  }
  TomlFields top(root, path, "");
  {
    TomlFields t = top.sub("scene");
    s.name = t.text("name");
    if (!std::regex_match(s.name, std::regex("[A-Za-z0-9._-]+")))
      t.fail("name", "not usable as a folder name", "letters, digits, '.', '_', '-'");
    s.source = t.text("source", "");
    s.title = t.text("title", "");
    t.finish();
  }
  {
    TomlFields t = top.sub("mixture");
    try {
      s.mixture = read_mixture(t);
    } catch (const std::invalid_argument& e) {
      t.fail("species", e.what(), "");
    }
    t.finish();
  }
  {
    TomlFields t = top.sub("collisions");
    s.restitution = read_collisions(t, s.mixture, s.enskog);
    t.finish();
  }
  if (top.has("initial")) {
    TomlFields t = top.sub("initial");
    s.initial = read_initial(t, s.mixture.size());
    t.finish();
  }
  {
    TomlFields t = top.sub("observables");
    s.observables = read_observables(t);
    t.finish();
  }
  if (top.has("theory")) {
    TomlFields t = top.sub("theory");
    s.theory = read_theory(t, s.mixture, levels, path);
    t.finish();
  }
  else
    s.theory.level = default_level(levels, path);
  if (top.has("dsmc")) {
    TomlFields t = top.sub("dsmc");
    s.dsmc = read_dsmc(t);
    t.finish();
  }
  if (top.has("compare")) {
    TomlFields t = top.sub("compare");
    s.compare = read_compare(t, s.mixture.size(), levels, is_paper_scene(path));
    t.finish();
    // [compare] without [dsmc] is refused by `granmix compare` (compare_needs_dsmc), not here: `theory` reads the scene too.
    check_companions(s, t, levels);
  }
  if (top.has("plot")) {
    TomlFields t = top.sub("plot");
    s.plot = read_plot(t);
    t.finish();
  }
  if (top.has("time") || !s.theory.sweep) {
    TomlFields t = top.sub("time");
    s.times = read_times(t);
    s.time_unit_mg = t.choice("unit", {"natural", "mg"}, "natural") == "mg";
    t.finish();
  }
  check_combinations(s, top, levels);
  check_quantities_measured(s, top);
  top.finish();
  if (s.compare.empty() && s.dsmc.present) {  // judged by default (docs/judging.md, "The default comparison")
    if (!s.theory.level_is_auto()) s.compare = default_comparison(s, levels);  // "auto": once the level is chosen
    s.compare_generated = true;
  }
  if (s.theory.sweep && !s.dsmc.at.empty()) {  // theory also at the simulated points (compared there)
    auto& v = s.theory.sweep->values;
    for (double x : s.dsmc.at) {  // a grid value within rounding of x becomes x exactly
      const auto near = std::find_if(v.begin(), v.end(), [&](double g) { return std::abs(g - x) <= 1e-9 * std::max(1.0, std::abs(x)); });
      if (near != v.end()) *near = x;
      else v.push_back(x);
    }
    std::sort(v.begin(), v.end());
  }
  return s;
}

Scene sweep_point(const Scene& s, double x) {
  Scene p = s;
  p.theory.sweep.reset();
  switch (s.theory.sweep->parameter) {
    case Sweep::Parameter::eps: p.restitution = Restitution::constant(s.mixture.size(), x); break;
    case Sweep::Parameter::density: p.mixture = s.mixture.with_density(s.theory.sweep->species, x); break;
    case Sweep::Parameter::n_star: {  // all densities scaled so that n σ12³ = x (x = 0: the dilute gas as given)
      p.enskog = x > 0.0;
      if (x > 0.0) p.mixture = with_reduced_density(s.mixture, x);
      break;
    }
  }
  return p;
}

}  // namespace granmix::model
