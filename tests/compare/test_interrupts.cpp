// Interrupts and unwritable outputs: a real SIGINT/SIGTERM sent to a running
// `granmix compare` ends it with 130/143, one line saying what was finished, and nothing partial on
// disk; an output location that cannot be written is refused with exit 2 before any computing.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <tuple>

#include "run_cli.hpp"

extern char** environ;

using namespace granmix;

namespace {

std::string test_scene(const std::string& name) { return std::string(GRANMIX_SOURCE_DIR) + "/tests/scenes/" + name; }

bool has_entry_starting(const std::filesystem::path& dir, const std::string& prefix) {
  if (!std::filesystem::is_directory(dir)) return false;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().filename().string().rfind(prefix, 0) == 0) return true;
  return false;
}

struct Interrupted {
  int code = -1;
  std::string stderr_text;
};

// Starts `granmix compare` on the long scene, waits until its DSMC has begun (the scheduler's first
// line on stderr), sends `sig` and waits for the exit.
Interrupted interrupt_compare(const std::filesystem::path& out, int sig) {
  const std::filesystem::path err = test::fresh_dir("interrupt-stderr-" + std::to_string(getpid())) / "stderr.txt";
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string exe = GRANMIX_EXE, cmd = "compare", scene = test_scene("interrupt-long-dsmc.toml"), flag = "--out", dir = out.string(),
              threads = "--threads", two = "2";
  char* argv[] = {exe.data(), cmd.data(), scene.data(), flag.data(), dir.data(), threads.data(), two.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, exe.c_str(), &fa, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  REQUIRE(spawned == 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto started = [&] {  // the scheduler's first line: the DSMC units are being computed
    std::ifstream in(err);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str().find("DSMC: ") != std::string::npos;
  };
  while (!started() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // into the DSMC
  REQUIRE(kill(pid, sig) == 0);
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  Interrupted r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err);
  std::ostringstream s;
  s << in.rdbuf();
  r.stderr_text = s.str();
  return r;
}

}  // namespace

TEST_CASE("SIGINT and SIGTERM during granmix compare: exit 130/143, one line, no partial output", "[compare]") {
  for (const auto& [sig, code, name] : {std::tuple{SIGINT, 130, "SIGINT"}, std::tuple{SIGTERM, 143, "SIGTERM"}}) {
    const auto base = test::fresh_dir(std::string("interrupt-") + name);
    const auto out = base / "out" / "nested";  // created by the run: removed again when left empty
    const Interrupted r = interrupt_compare(out, sig);
    INFO(r.stderr_text);
    CHECK(r.code == code);
    CHECK(r.stderr_text.find(std::string("granmix: interrupted by ") + name + "; finished: nothing") != std::string::npos);
    // One line about the interrupt, after the scheduler's start line.
    CHECK(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n') == 2);
    CHECK(r.stderr_text.rfind("granmix: interrupted", 0) == std::string::npos);
    CHECK(r.stderr_text.find("\ngranmix: interrupted") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(base / "out"));  // no staging folder, no empty output folders
  }
}

TEST_CASE("SIGINT keeps a previous result whole: the old scene folder stays, no staging folder", "[compare]") {
  const auto out = test::fresh_dir("interrupt-keep");
  std::filesystem::create_directories(out / "interrupt-long-dsmc");
  test::write_file(out / "interrupt-long-dsmc" / "report.json", "{}\n");
  const Interrupted r = interrupt_compare(out, SIGINT);
  INFO(r.stderr_text);
  CHECK(r.code == 130);
  CHECK_FALSE(has_entry_starting(out, "."));
  CHECK(std::filesystem::exists(out / "interrupt-long-dsmc" / "report.json"));
}

TEST_CASE("an unwritable --out is refused with exit 2 naming it, before any computing", "[compare]") {
  const auto d = test::fresh_dir("unwritable-out");
  test::write_file(d / "file", "not a folder\n");
  for (const std::string& out : {std::string("/proc/forbidden"), (d / "file").string(), (d / "file" / "sub").string()}) {
    for (const std::string& cmd : {"compare " + test_scene("interrupt-long-dsmc.toml"), "dsmc " + test_scene("interrupt-long-dsmc.toml"),
                                  std::string("validate")}) {
      const auto r = test::run_granmix(cmd + " --out " + out);  // the long scene would run for minutes
      INFO(cmd << " --out " << out << "\n" << r.output);
      CHECK(r.code == 2);
      CHECK(r.output.find("--out " + out + ":") != std::string::npos);
    }
  }
  CHECK(std::filesystem::is_regular_file(d / "file"));
}
