// libFuzzer harness: the `granmix hcs` command line (compare/command_hcs.cpp, hcs_summary.cpp) parsed by the same CLI11
// app as main.cpp and run. The input is the argument list, one argument per line. Accepted outcomes
// are those main.cpp maps to exit 2 (usage, InputError, invalid_argument) or 3 (NumericalError,
// domain_error); anything else (crash, logic error, sanitizer report, > 2 s) is a finding.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "compare/commands.hpp"
#include "model/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool quiet = std::freopen("/dev/null", "w", stdout) != nullptr;  // the results table
  (void)quiet;
  std::vector<std::string> args{"granmix", "hcs"};
  std::string a;
  for (std::size_t i = 0; i < size; ++i) {
    const char c = char(data[i]);
    if (c == '\n' || c == '\0') {
      args.push_back(a), a.clear();
    } else {
      a += c;
    }
  }
  if (!a.empty()) args.push_back(a);
  if (args.size() > 64) return 0;  // a command line, not a data file
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  CLI::App app{"granmix"};
  app.require_subcommand(1);
  const auto action = granmix::compare::add_hcs_command(app);
  try {
    app.parse(int(argv.size()), argv.data());
    action();
  } catch (const CLI::Error&) {
  } catch (const granmix::InputError&) {
  } catch (const std::invalid_argument&) {
  } catch (const granmix::NumericalError&) {
  } catch (const std::domain_error&) {
  }
  return 0;
}
