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

}  // namespace granmix::compare
