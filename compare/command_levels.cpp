// granmix levels [--all] [--markdown]: the theory levels a scene may choose, from the level catalogue
// (theory/levels/level_catalogue.hpp): name, family, what it is, where it applies, its typical cost and the companions
// a scene may judge with (correction_from). --all: the companion and study levels too (`granmix theory --level`);
// --markdown: the table of docs/levels.md.
#include <cstdio>

#include "commands.hpp"
#include "theory/levels/level_catalogue.hpp"

namespace granmix::compare {

std::function<int()> add_levels_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("levels", "the theory levels: what each is, where it applies, its cost and companions");
  auto all = std::make_shared<bool>(false);
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--all", *all, "also the companion and study levels (granmix theory --level)");
  cmd->add_flag("--markdown", *markdown, "a Markdown table (docs/levels.md)");
  return [all, markdown]() {
    std::fputs(theory::level_listing(*all, *markdown).c_str(), stdout);
    return 0;
  };
}

}  // namespace granmix::compare
