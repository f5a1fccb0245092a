// granmix — kinetic theory of freely cooling granular gas mixtures side by side with DSMC.
// Command line of docs/architecture.md §3. Exit codes: 0 success, 1 a comparison failed its tolerance,
// 2 bad input or usage, 3 numerical failure.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <functional>
#include <map>
#include <stdexcept>

#include "allocator_setup.hpp"
#include "commands.hpp"
#include "granmix_version.hpp"
#include "model/errors.hpp"
#include "scheduler.hpp"

int main(int argc, char** argv) {
  using namespace granmix;
  compare::keep_freed_memory();
  compare::set_command_line(argc, argv);
  CLI::App app{"granmix: kinetic theory of granular gas mixtures beside DSMC"};
  app.set_version_flag("--version", std::string(granmix::version) + " (git " + granmix::git_sha + ")");
  app.require_subcommand(1);
  std::map<std::string, std::function<int()>> actions;
  actions["theory"] = compare::add_theory_command(app);
  actions["hcs"] = compare::add_hcs_command(app);
  actions["dsmc"] = compare::add_dsmc_command(app);
  actions["compare"] = compare::add_compare_command(app);
  actions["validate"] = compare::add_validate_command(app);
  actions["bench"] = compare::add_bench_command(app);
  actions["levels"] = compare::add_levels_command(app);
  actions["observables"] = compare::add_observables_command(app);
  actions["model-errors"] = compare::add_model_errors_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return 2;
  }
  int code = 2;
  try {
    for (const CLI::App* sub : app.get_subcommands()) code = actions.at(sub->get_name())();
    compare::scheduler::finish();
    return code;
  } catch (const InputError& e) {
    std::fprintf(stderr, "granmix: %s\n", e.what());
    code = 2;
  } catch (const std::invalid_argument& e) {  // a model constructor refused a value the user gave
    std::fprintf(stderr, "granmix: %s\n", e.what());
    code = 2;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "granmix: numerical failure: %s\n", e.what());
    code = 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "granmix: %s\n", e.what());
    code = 3;
  }
  compare::scheduler::abort(code);  // under MPI: every rank stops with this code
  return code;
}
