#pragma once
// Runs the granmix executable as a user would and captures its exit code and output.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "fresh_dir.hpp"

namespace granmix::test {

struct CliResult {
  int code = -1;
  std::string output;  // stdout and stderr together
};

inline CliResult run_granmix(const std::string& args) {
  const std::string cmd = std::string(GRANMIX_EXE) + " " + args + " 2>&1";
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline void write_file(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

inline std::string scene_path(const std::string& name) {
  return std::string(GRANMIX_SOURCE_DIR) + "/compare/scenes/" + name;
}

}  // namespace granmix::test
