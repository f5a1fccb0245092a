// granmix observables [--markdown]: the observables a scene may ask for, from the observable catalogue
// (model/observable_catalogue.hpp): the [observables] key, the quantity columns it writes, the axis of its tables, and
// where its theory column, DSMC estimator and error are computed. --markdown: the table of docs/scenes.md.
#include <cstdio>

#include "commands.hpp"
#include "model/observable_catalogue.hpp"

namespace granmix::compare {

std::function<int()> add_observables_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("observables", "the observables: their columns, axes and where each is computed");
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--markdown", *markdown, "a Markdown table (docs/scenes.md)");
  return [markdown]() {
    std::fputs(model::observable_listing(*markdown).c_str(), stdout);
    return 0;
  };
}

}  // namespace granmix::compare
