// granmix model-errors [--scenes DIR] [--write] [--drift F]: the frozen model errors of the scenes of compare/scenes/
// (frozen_model_errors.hpp, docs/judging.md "Frozen model errors"). Without --write it checks: for every scene with
// computed model errors, the live computation against its committed table; exit 1 when one drifts by more than F
// (relative to max(frozen, 1e-4)), so a change that moves a bound is seen and reviewed. --write regenerates the tables.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "frozen_model_errors.hpp"
#include "model/errors.hpp"
#include "model/sha256.hpp"
#include "theory/level_choice.hpp"
#include "theory/scene_theory.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

std::function<int()> add_model_errors_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("model-errors", "check (or --write) the frozen model errors of compare/scenes/ against the live theory");
  struct Options {
    std::string scenes;
    bool write = false;
    double drift = default_model_error_drift;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--scenes", o->scenes, "scene folder (default compare/scenes; its tables are in ../model-errors/)");
  cmd->add_flag("--write", o->write, "regenerate the tables (after reviewing why the bounds moved)");
  cmd->add_option("--drift", o->drift, "the largest relative drift accepted")->check(CLI::Range(0.0, 10.0))->capture_default_str();
  return [o]() {
    const std::filesystem::path dir = o->scenes.empty() ? default_scene_folder() : std::filesystem::path(o->scenes);
    if (!std::filesystem::is_directory(dir)) throw InputError("model-errors: no scene folder " + dir.string() + " (allowed: compare/scenes)");
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".toml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::vector<model::Scene> scenes;  // every scene read first: a bad one stops the command before anything is written
    for (const auto& f : files) scenes.push_back(theory::with_level_chosen(theory::load_scene(f.string())));
    bool ok = true;
    for (const model::Scene& s : scenes) {
      const std::filesystem::path path = frozen_table_path(s);
      if (path.empty()) throw InputError("model-errors: " + s.file + " is not a scene of compare/scenes/ (allowed: the paper scenes' folder)");
      const FrozenModelErrors live = compute_model_errors(s, theory::run_theory(s).table);
      std::size_t points = 0;
      for (const auto& [q, p] : live.points) points += p.size();
      if (live.points.empty()) continue;
      if (o->write) {
        std::filesystem::create_directories(path.parent_path());
        write_atomically(path, format_model_errors(s, live));
        std::printf("%-24s %5zu points -> %s\n", s.name.c_str(), points, path.c_str());
        continue;
      }
      std::optional<FrozenModelErrors> frozen;
      std::string problem;
      try {
        frozen = load_frozen_model_errors(s);
      } catch (const InputError& e) {
        problem = e.what();
      }
      if (!frozen) {
        ok = false;
        std::printf("%-24s STALE %s\n", s.name.c_str(), problem.c_str());
        continue;
      }
      const auto [drift, where] = largest_drift(*frozen, live);
      const bool pass = drift <= o->drift;
      ok = ok && pass;
      std::printf("%-24s %5zu points, largest drift %.3g (%s)%s\n", s.name.c_str(), points, drift, where.c_str(), pass ? "" : "  DRIFT");
    }
    if (!o->write)
      std::printf("model-errors: %s (drift accepted: %g of max(frozen, %g))\n", ok ? "every table matches the live theory" : "TABLES AND THEORY DIFFER",
                  o->drift, model_error_floor);
    return ok ? 0 : 1;
  };
}

}  // namespace granmix::compare
