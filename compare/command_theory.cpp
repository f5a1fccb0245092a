// granmix theory SCENE.toml [--out DIR]  ->  DIR/<scene>/theory.tsv (docs/architecture.md §3–4).
// --level NAME: one theory level's curves alone (any level of the catalogue, `granmix levels --all`, also those a scene
// may not judge) -> DIR/<scene>/theory_<NAME>.tsv, to compute a model error from any next order by hand
// (docs/judging.md, "How far the computed bounds can be tightened").
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "interrupts.hpp"
#include "model/scene.hpp"
#include "provenance.hpp"
#include "scene_folder.hpp"
#include "model/sha256.hpp"
#include "model/errors.hpp"
#include "theory/level_choice.hpp"
#include "theory/scene_theory.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

std::function<int()> add_theory_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("theory", "theory curves of a scene -> DIR/<scene>/theory.tsv");
  auto scene = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("out");
  auto level = std::make_shared<std::string>();  // empty: the scene's own level and companions -> theory.tsv
  cmd->add_option("scene", *scene, "scene file (TOML); - reads it from standard input")->required();
  cmd->add_option("--out", *out, "output folder")->capture_default_str();
  cmd->add_option("--level", *level, "one level's curves alone -> theory_<level>.tsv; one of: " + theory::level_catalogue().names());
  return [scene, out, level]() {
    // Everything is read and checked before anything is written.
    const model::Scene loaded = theory::load_scene(*scene);
    if (!level->empty()) try {
        theory::find_level(*level);
      } catch (const std::invalid_argument& e) {
        throw InputError(std::string("--level: ") + e.what());
      }
    interrupts::require_writable_folder(*out);  // exit 2 naming --out, not a filesystem error after the solve
    const model::Scene s = level->empty() ? theory::with_level_chosen(loaded) : loaded;
    if (!s.theory.level_choice.empty()) std::printf("level: %s\n", s.theory.level_choice.c_str());
    const theory::TheoryResult r = level->empty() ? theory::run_theory(s) : theory::run_level(s, *level);
    Provenance p;
    p.scene_name = s.name, p.scene_file = s.file, p.scene_sha256 = model::sha256_hex(s.text), p.command = command_line();
    p.level_choice = s.theory.level_choice;
    const std::filesystem::path file = std::filesystem::path(*out) / s.name / (level->empty() ? "theory.tsv" : "theory_" + *level + ".tsv");
    const auto moved = set_aside_other_scene(*out, s.name, p.scene_sha256);  // never beside another scene file's tables
    write_atomically(file, format_tsv(provenance_header(p), r.table));
    if (moved) std::printf("warning: %s\n", moved->c_str());
    std::printf("%s: %zu rows -> %s  (%.3f s; CVODE %ld steps, %ld RHS evaluations, %ld linear iterations)\n",
                s.name.c_str(), r.table.rows.size(), file.c_str(), r.seconds, r.stats.steps, r.stats.rhs_evals, r.stats.linear_iterations);
    return 0;
  };
}

}  // namespace granmix::compare
