// granmix theory SCENE.toml [--out DIR]  ->  DIR/<scene>/theory.tsv (design.md §3–4).
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "interrupts.hpp"
#include "model/scene.hpp"
#include "provenance.hpp"
#include "model/sha256.hpp"
#include "theory/scene_theory.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

std::function<int()> add_theory_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("theory", "theory curves of a scene -> DIR/<scene>/theory.tsv");
  auto scene = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("out");
  cmd->add_option("scene", *scene, "scene file (TOML)")->required();
  cmd->add_option("--out", *out, "output folder")->capture_default_str();
  return [scene, out]() {
    // Everything is read and checked before anything is written.
    const model::Scene s = model::load_scene(*scene);
    interrupts::require_writable_folder(*out);  // exit 2 naming --out, not a filesystem error after the solve
    const theory::TheoryResult r = theory::run_theory(s);
    Provenance p;
    p.scene_name = s.name, p.scene_file = s.file, p.scene_sha256 = model::sha256_hex(s.text), p.command = command_line();
    const std::filesystem::path file = std::filesystem::path(*out) / s.name / "theory.tsv";
    write_atomically(file, format_tsv(provenance_header(p), r.table));
    std::printf("%s: %zu rows -> %s  (%.3f s; CVODE %ld steps, %ld RHS evaluations)\n", s.name.c_str(),
                r.table.rows.size(), file.c_str(), r.seconds, r.stats.steps, r.stats.rhs_evals);
    return 0;
  };
}

}  // namespace granmix::compare
