#pragma once
// The subcommands of `granmix` (docs/architecture.md §3). Each registers its options on the CLI11 app and
// returns the process exit code: 0 success, 1 comparison failed, 2 bad input, 3 numerical failure.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <string>

namespace granmix::compare {

// The command line as typed, for provenance headers.
const std::string& command_line();
void set_command_line(int argc, char** argv);

// --seed: an integer in [0, 2^53] (JSON numbers hold it exactly); anything else is refused by CLI11 (exit 2).
inline constexpr unsigned long long max_seed = 1ULL << 53;
CLI::Validator seed_range();

// compare/scenes of the working folder if there is one, else of the source tree.
std::filesystem::path default_scene_folder();

// Each returns the action to run once the command line has parsed.
std::function<int()> add_theory_command(CLI::App& app);
std::function<int()> add_hcs_command(CLI::App& app);
std::function<int()> add_dsmc_command(CLI::App& app);
std::function<int()> add_compare_command(CLI::App& app);
std::function<int()> add_validate_command(CLI::App& app);
std::function<int()> add_bench_command(CLI::App& app);
std::function<int()> add_levels_command(CLI::App& app);
std::function<int()> add_observables_command(CLI::App& app);
std::function<int()> add_model_errors_command(CLI::App& app);

}  // namespace granmix::compare
