// granmix._core: the Python bindings of the layers the command line runs (docs/python.md). Every function here calls
// the same code as its command — compare::compute_hcs/hcs_json (granmix hcs --json), theory::load_scene(_text),
// theory::run_theory/run_level (granmix theory), dsmc::run_scene_dsmc (granmix dsmc), compare::evaluate_scene and
// report_json (granmix compare) and the level catalogue (granmix levels) — and hands its tables to Python as float64
// arrays, one per column. The package python/granmix wraps them in Result and Report.
//
// Errors: InputError and std::invalid_argument (the command line's exit 2) -> granmix.SceneError (a ValueError);
// NumericalError (exit 3) -> granmix.SolverError (a RuntimeError). The long calls release the GIL; the DSMC runs on a
// thread of its own while the calling thread polls Python's signal handlers, so Ctrl-C abandons the replicas at their
// next refresh point and raises KeyboardInterrupt (compare/interrupts.hpp, run_stoppable).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "compare/deviations.hpp"
#include "compare/hcs_summary.hpp"
#include "compare/interrupts.hpp"
#include "compare/scene_compare.hpp"
#include "dsmc/scene_dsmc.hpp"
#include "granmix_version.hpp"
#include "model/errors.hpp"
#include "model/scene.hpp"
#include "model/table.hpp"
#include "theory/level_choice.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"

namespace py = pybind11;
using namespace granmix;

namespace {

// nlohmann's JSON as Python objects: numbers stay the same doubles (no text in between).
py::object to_python(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (const auto& [key, value] : j.items()) d[py::str(key)] = to_python(value);
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l(j.size());
      for (std::size_t i = 0; i < j.size(); ++i) l[i] = to_python(j[i]);
      return l;
    }
    case nlohmann::json::value_t::string: return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    default: return py::none();
  }
}

// A table as {"columns": [...], "data": {column: float64 array}} (rows in the files' order).
py::dict to_python(const model::Table& t) {
  py::dict data;
  const std::size_t n = t.rows.size();
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    py::array_t<double> a(static_cast<py::ssize_t>(n));
    double* p = a.mutable_data();
    for (std::size_t r = 0; r < n; ++r) p[r] = t.rows[r][c];
    data[py::str(t.columns[c])] = std::move(a);
  }
  py::dict out;
  out["columns"] = t.columns;
  out["data"] = std::move(data);
  return out;
}

std::string fspath(const py::object& path) { return py::str(py::module_::import("os").attr("fspath")(path)); }

// The run options of granmix.dsmc and granmix.compare, checked as the command line checks its flags.
dsmc::RunOptions run_options(const std::string& fidelity, std::uint64_t seed, int threads) {
  if (fidelity != "quick" && fidelity != "paper")
    throw InputError("fidelity: \"" + fidelity + "\" is not a fidelity (allowed: quick, paper)");
  if (threads < 0 || threads > 4096)
    throw InputError("threads: " + std::to_string(threads) + " (allowed: 0 for all cores, or 1 to 4096)");
  dsmc::RunOptions opt;
  opt.fidelity = fidelity, opt.seed = seed, opt.threads = threads;
  return opt;
}

// Runs DSMC work with the GIL released, on a thread of its own; a signal whose Python handler raises (SIGINT:
// KeyboardInterrupt) abandons the replicas and re-raises that exception here.
void run_interruptibly(const std::function<void(const dsmc::StopRequest&)>& work) {
  std::optional<py::error_already_set> raised;  // destroyed with the GIL held (declared outside the release)
  try {
    py::gil_scoped_release release;
    compare::interrupts::run_stoppable(work, [&] {
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() == 0) return false;
      raised.emplace();  // takes the handler's exception
      return true;
    });
  } catch (const compare::interrupts::Interrupted&) {
    if (raised) throw *raised;
    throw;
  }
}

py::dict dsmc_info(const dsmc::DsmcResult& r, const std::string& fidelity, std::uint64_t seed) {
  py::dict info;
  info["method"] = dsmc::to_string(r.method);
  info["species"] = r.species, info["particles"] = r.particles, info["replicas"] = r.replicas;
  info["collisions"] = r.accepted, info["trials"] = r.trials, info["acceptance"] = r.acceptance();
  info["seconds"] = r.seconds, info["collisions_per_second"] = r.collisions_per_second();
  info["fidelity"] = fidelity, info["seed"] = seed;
  return info;
}

py::dict theory_info(const theory::TheoryResult& r) {
  py::dict info;
  info["seconds"] = r.seconds;
  info["cvode_steps"] = r.stats.steps, info["rhs_evaluations"] = r.stats.rhs_evals;
  info["linear_iterations"] = r.stats.linear_iterations;
  return info;
}

// granmix.hcs holds the GIL: one call at a time writes it.
double last_hcs_seconds = 0.0;

py::dict level_dict(const theory::LevelDescriptor& l) {
  py::dict d;
  d["name"] = l.name, d["family"] = l.family, d["summary"] = l.summary, d["applies"] = l.applies, d["cost"] = l.cost;
  d["scene_may_choose"] = l.scene_may_choose;
  py::dict parts;
  parts["cooling"] = l.parts.cooling, parts["diffusion"] = l.parts.diffusion, parts["hcs"] = l.parts.hcs;
  parts["tracer"] = l.parts.tracer, parts["distributions"] = l.parts.distributions;
  d["parts"] = parts;
  py::list companions;
  for (const auto& c : l.companions) {
    py::dict e;
    e["correction"] = c.correction, e["level"] = c.level, e["changes"] = c.changes, e["quantities"] = c.quantities;
    companions.append(e);
  }
  d["companions"] = companions;
  d["synonyms"] = l.synonyms;
  return d;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "granmix: kinetic theory of freely cooling granular gas mixtures beside DSMC (the bindings; see granmix)";
  m.attr("__version__") = granmix::version;
  m.attr("git_sha") = granmix::git_sha;

  static py::exception<InputError> scene_error(m, "SceneError", PyExc_ValueError);
  static py::exception<NumericalError> solver_error(m, "SolverError", PyExc_RuntimeError);
  scene_error.attr("__module__") = "granmix";
  solver_error.attr("__module__") = "granmix";
  scene_error.doc() = "Bad input: a scene, an option or an argument refused (the command line's exit code 2).";
  solver_error.doc() = "A solver failed (a CVODE or GSL call, the DSMC's energy balance; the command line's exit code 3).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(scene_error.ptr(), e.what());
    } catch (const std::invalid_argument& e) {  // a model constructor refused a value (exit 2 on the command line)
      PyErr_SetString(scene_error.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(solver_error.ptr(), e.what());
    }
  });

  m.def(
      "hcs",
      [](const std::vector<double>& mass, const std::vector<double>& diameter, const std::vector<double>& density,
         std::optional<double> eps, double nstar, std::optional<double> mu, std::optional<double> delta, std::optional<double> w,
         std::optional<double> alpha, std::optional<double> alpha11, std::optional<double> alpha22, std::optional<double> alpha12,
         bool converged) {
        compare::HcsOptions o;  // None: the command line's "not given"
        o.mass = mass, o.diameter = diameter, o.density = density, o.nstar = nstar, o.converged = converged;
        o.eps = eps, o.mu = mu, o.delta = delta, o.w = w, o.alpha = alpha, o.alpha11 = alpha11, o.alpha22 = alpha22, o.alpha12 = alpha12;
        const auto start = std::chrono::steady_clock::now();
        const nlohmann::ordered_json j = compare::hcs_json(compare::compute_hcs(o));
        last_hcs_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return to_python(j);
      },
      py::kw_only(), py::arg("mass") = std::vector<double>{}, py::arg("diameter") = std::vector<double>{},
      py::arg("density") = std::vector<double>{}, py::arg("eps") = py::none(), py::arg("nstar") = 0.0, py::arg("mu") = py::none(),
      py::arg("delta") = py::none(), py::arg("w") = py::none(), py::arg("alpha") = py::none(), py::arg("alpha11") = py::none(),
      py::arg("alpha22") = py::none(), py::arg("alpha12") = py::none(), py::arg("converged") = false,
      R"(The settled (HCS) state of a mixture: the object of `granmix hcs --json`, as a dict with the same keys and numbers.

Two forms, as on the command line: mass, diameter, density (one value per species) and eps; or Montanero and
Garzo's binary mu, delta, w with alpha (or alpha11, alpha22, alpha12). nstar > 0: Enskog contact values at the reduced
density n sigma_12^3. converged: also the HCS without the Sonine truncation (~1 s for a binary). Raises SceneError for
arguments out of range or missing (the message names the command line's flag). The dict's "warnings" list says where the
first-Sonine numbers break down ({"code", "species", "message"}; docs/user-guide.md), "inputs" echoes the arguments.)");
  // The seconds of the last granmix.hcs's C++ computation (compute_hcs and hcs_json): the rest of the call's time is the
  // binding's own (tests/python measure it).
  m.def("_last_hcs_seconds", [] { return last_hcs_seconds; });

  py::class_<model::Scene>(m, "Scene",
                           "A scene (one paper figure, like the files of compare/scenes/), read and checked as the command line reads it.")
      .def(py::init([](const py::object& path) { return theory::with_level_chosen(theory::load_scene(fspath(path))); }), py::arg("path"),
           "Reads a scene file (TOML); SceneError with file:line: key: message if anything is wrong. A scene with level "
           "\"auto\" has its level chosen here (level_choice says which and why).")
      .def_static(
          "from_toml", [](const std::string& text, const std::string& path) { return theory::with_level_chosen(theory::load_scene_text(text, path)); },
          py::arg("text"), py::arg("path") = "<string>", "A scene from TOML text; `path` names it in messages.")
      .def_property_readonly("name", [](const model::Scene& s) { return s.name; })
      .def_property_readonly("source", [](const model::Scene& s) { return s.source; })
      .def_property_readonly("title", [](const model::Scene& s) { return s.title; })
      .def_property_readonly("file", [](const model::Scene& s) { return s.file; })
      .def_property_readonly("level", [](const model::Scene& s) { return s.theory.level; }, "The judged theory level.")
      .def_property_readonly(
          "level_choice", [](const model::Scene& s) { return s.theory.level_choice; },
          "With level \"auto\": the level chosen and why (docs/levels.md, \"Choosing a level\"); otherwise empty.")
      .def_property_readonly("species", [](const model::Scene& s) { return s.mixture.size(); }, "The number of species.")
      .def_property_readonly("has_dsmc", [](const model::Scene& s) { return s.dsmc.present; })
      .def_property_readonly(
          "times", [](const model::Scene& s) { return py::array_t<double>(py::ssize_t(s.times.size()), s.times.data()); },
          "The sample times, in the scene's unit.")
      .def_property_readonly(
          "quantities",
          [](const model::Scene& s) {
            std::vector<std::string> names;
            for (const auto& q : s.compare) names.push_back(compare::label(q));
            return names;
          },
          "The compared quantities' labels (as in report.json).")
      .def("to_toml", [](const model::Scene& s) { return s.text; }, "The scene's TOML text.")
      .def("__repr__", [](const model::Scene& s) { return "<granmix.Scene " + s.name + ": " + s.source + ">"; });

  m.def(
      "_theory",
      [](const model::Scene& s, std::optional<std::string> level) {
        std::string name = s.theory.level;
        if (level) try {
            name = theory::find_level(*level).name;
          } catch (const std::invalid_argument& e) {
            throw InputError(std::string("level: ") + e.what());
          }
        theory::TheoryResult r;
        {
          py::gil_scoped_release release;
          r = level ? theory::run_level(s, *level) : theory::run_theory(s);
        }
        py::dict out = to_python(r.table);
        out["level"] = name, out["info"] = theory_info(r);
        return out;
      },
      py::arg("scene"), py::arg("level") = py::none());

  m.def(
      "_dsmc",
      [](const model::Scene& s, const std::string& fidelity, std::uint64_t seed, int threads) {
        dsmc::RunOptions opt = run_options(fidelity, seed, threads);
        dsmc::DsmcRun run;
        run_interruptibly([&](const dsmc::StopRequest& stop) {
          opt.stop = &stop;
          run = dsmc::run_scene_dsmc(s, opt);
        });
        py::dict out = to_python(run.table);
        out["info"] = dsmc_info(run.result, fidelity, seed);
        if (!run.distribution.rows.empty()) out["distribution"] = to_python(run.distribution);
        return out;
      },
      py::arg("scene"), py::arg("fidelity") = "quick", py::arg("seed") = 1, py::arg("threads") = 0);

  m.def(
      "_compare",
      [](const model::Scene& s, const std::string& fidelity, std::uint64_t seed, int threads) {
        dsmc::RunOptions opt = run_options(fidelity, seed, threads);
        compare::SceneEvaluation e;
        run_interruptibly([&](const dsmc::StopRequest& stop) {
          opt.stop = &stop;
          e = compare::evaluate_scene(s, opt);
        });
        py::dict out;
        out["report"] = to_python(compare::report_json(s, e.outcome, seed, fidelity));
        out["compared"] = e.outcome.compared;
        py::dict passes;  // QuantityResult::pass(), which report.json leaves to its counts
        for (const auto& q : e.outcome.quantities) passes[py::str(compare::label(q.spec))] = q.pass();
        out["passes"] = passes;
        py::dict th = to_python(e.theory.table);
        th["level"] = s.theory.level, th["info"] = theory_info(e.theory);
        out["theory"] = th;
        if (s.dsmc.present) {  // a theory-only scene is compared with nothing, as on the command line
          py::dict ds = to_python(e.dsmc.table);
          ds["info"] = dsmc_info(e.dsmc.result, fidelity, seed);
          out["dsmc"] = ds;
        } else {
          out["dsmc"] = py::none();
        }
        const std::size_t n = e.deviations.size();
        py::array_t<double> x(n), species(n), theory_v(n), dsmc_v(n), err(n), rel(n), z(n), paper_rel(n), model_error(n);
        py::array_t<bool> judged(n), pass(n), resolved(n);
        py::list quantity;
        for (std::size_t i = 0; i < n; ++i) {
          const compare::Deviation& d = e.deviations[i];
          x.mutable_at(i) = d.t, species.mutable_at(i) = d.species, theory_v.mutable_at(i) = d.theory;
          dsmc_v.mutable_at(i) = d.dsmc, err.mutable_at(i) = d.dsmc_err, rel.mutable_at(i) = d.rel, z.mutable_at(i) = d.z;
          paper_rel.mutable_at(i) = d.paper_rel, model_error.mutable_at(i) = d.model_error;
          judged.mutable_at(i) = d.judged, pass.mutable_at(i) = d.pass, resolved.mutable_at(i) = d.resolved;
          quantity.append(d.quantity);
        }
        py::dict dev;
        dev["x"] = x, dev["species"] = species, dev["quantity"] = quantity, dev["theory"] = theory_v, dev["dsmc"] = dsmc_v;
        dev["dsmc_err"] = err, dev["rel"] = rel, dev["z"] = z, dev["judged"] = judged, dev["pass"] = pass;
        dev["paper_rel"] = paper_rel, dev["model_error"] = model_error, dev["resolved"] = resolved;
        out["deviations"] = dev;
        out["x"] = e.theory.table.columns.front();
        return out;
      },
      py::arg("scene"), py::arg("fidelity") = "quick", py::arg("seed") = 1, py::arg("threads") = 0);

  m.def(
      "levels",
      [] {
        py::list out;
        for (const auto& l : theory::level_catalogue().levels()) out.append(level_dict(*l));
        return out;
      },
      R"(Every theory level of the catalogue (`granmix levels --all`), as dicts: name, family, summary, applies, cost,
scene_may_choose (False: a companion or study level, for granmix.theory(scene, level=...)), parts, companions, synonyms.)");
}
