#pragma once
// Runs the granmix executable as a user would and captures its exit code and output.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fresh_dir.hpp"

namespace granmix::test {

struct CliResult {
  int code = -1;
  std::string output;  // stdout and stderr together (run_granmix_split: stdout alone)
  std::string error;   // run_granmix_split: stderr
};

// A shell command line run through popen: its exit code and what it prints on stdout.
inline CliResult run_shell(const std::string& cmd) {
  CliResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), p)) r.output += buf.data();
  const int status = pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline CliResult run_granmix(const std::string& args) { return run_shell(std::string(GRANMIX_EXE) + " " + args + " 2>&1"); }

// The same with stdout and stderr apart (stderr through a file in a fresh folder of this process).
inline CliResult run_granmix_split(const std::string& args) {
  const auto err = fresh_dir("stderr-" + std::to_string(getpid())) / "stderr.txt";
  CliResult r = run_shell(std::string(GRANMIX_EXE) + " " + args + " 2>" + err.string());
  std::ifstream in(err);
  r.error.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
}

#ifdef GRANMIX_MPIEXEC
// granmix under mpirun as the CI runs it: more ranks than cores, as root in a container.
inline CliResult run_mpi(int ranks, const std::string& args) {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  return run_shell(std::string(GRANMIX_MPIEXEC) + " --oversubscribe -n " + std::to_string(ranks) + " " + GRANMIX_EXE + " " + args + " 2>&1");
}
#endif

inline void write_file(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

inline std::string scene_path(const std::string& name) {
  return std::string(GRANMIX_SOURCE_DIR) + "/compare/scenes/" + name;
}

}  // namespace granmix::test
