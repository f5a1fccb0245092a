#include <cerrno>
#include <cstdlib>
#include <string>

#include "commands.hpp"

namespace granmix::compare {

namespace {
std::string& stored() {
  static std::string s;
  return s;
}
}  // namespace

const std::string& command_line() { return stored(); }

void set_command_line(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  stored() = s;
}

CLI::Validator seed_range() {
  return CLI::Validator(
      [](std::string& in) -> std::string {
        const std::string allowed = " (allowed: an integer in [0, " + std::to_string(max_seed) + "] = [0, 2^53], exact in report.json)";
        if (in.empty() || in.find_first_not_of("0123456789") != std::string::npos) return "seed " + in + " is not a non-negative integer" + allowed;
        errno = 0;
        const unsigned long long v = std::strtoull(in.c_str(), nullptr, 10);
        if (errno == ERANGE || v > max_seed) return "seed " + in + " out of range" + allowed;
        return "";
      },
      "SEED in [0, 2^53]");
}

}  // namespace granmix::compare
