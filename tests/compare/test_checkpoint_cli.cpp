// Checkpoint and restart through the command line: a `granmix dsmc` and a
// `granmix validate` killed (SIGKILL) after their first snapshot and restarted with --restart write
// the same TSV bytes as an uninterrupted run (the provenance lines of command line and date aside); damaged
// and foreign checkpoint files are refused with exit 2, naming the file, and nothing is written.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "dsmc/replica_snapshot.hpp"
#include "run_cli.hpp"

extern char** environ;

using namespace granmix;

namespace {

const std::string scenes = std::string(GRANMIX_SOURCE_DIR) + "/tests/scenes/checkpoint";
const std::string cooling = scenes + "/ckpt-cooling.toml";

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The file without the provenance lines of the command line (it differs by --out and the checkpoint
// flags) and the date; every other line, provenance included, must match byte for byte.
std::string without_command(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line))
    if (line.rfind("# command:", 0) != 0 && line.rfind("# date:", 0) != 0) out += line + "\n";
  return out;
}

std::vector<std::filesystem::path> files_with(const std::filesystem::path& dir, const std::string& ext) {
  std::vector<std::filesystem::path> v;
  if (std::filesystem::is_directory(dir))
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ext) v.push_back(e.path());
  return v;
}

#ifdef GRANMIX_MPIEXEC
// The processes of session `sid` (field 6 of /proc/<pid>/stat), zombies aside.
std::vector<pid_t> session_members(pid_t sid) {
  std::vector<pid_t> v;
  for (const auto& e : std::filesystem::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(e.path() / "stat");
    std::string line;
    if (!std::getline(in, line)) continue;  // the process ended meanwhile
    const std::size_t close = line.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    long ppid = 0, pgrp = 0, session = 0;
    if (rest >> state >> ppid >> pgrp >> session && session == sid && state != 'Z') v.push_back(static_cast<pid_t>(std::stol(name)));
  }
  return v;
}

// A killed node: SIGKILL to every process of the session, until none is left. Open MPI puts each rank
// in a process group of its own, so a signal to mpirun's group leaves the ranks running, still writing
// in the checkpoint folder while the restart reads it (which then fails with exit 2 on a vanished snapshot).
bool kill_session(pid_t sid) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    const std::vector<pid_t> alive = session_members(sid);
    if (alive.empty()) return true;
    for (pid_t p : alive) kill(p, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return false;
}
#endif

// Compares every table of the two checkpoint test scenes in `ref` with `out` (command and date lines
// aside); returns how many were compared.
std::size_t same_tables(const std::filesystem::path& ref, const std::filesystem::path& out) {
  std::size_t compared = 0;
  for (const char* scene : {"ckpt-cooling", "ckpt-sweep"})
    for (const auto& f : files_with(ref / scene, ".tsv")) {
      INFO(f);
      CHECK(without_command(read(f)) == without_command(read(out / scene / f.filename())));
      ++compared;
    }
  return compared;
}

pid_t spawn_granmix(std::vector<std::string> args, const std::filesystem::path& err) {
  args.insert(args.begin(), GRANMIX_EXE);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, GRANMIX_EXE, &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  REQUIRE(spawned == 0);
  return pid;
}

// Runs granmix with `args`, SIGKILLs it as soon as the checkpoint folder holds a snapshot, and returns
// whether it was killed (false: it finished first).
bool kill_after_first_snapshot(std::vector<std::string> args, const std::filesystem::path& ckpt) {
  const pid_t pid = spawn_granmix(std::move(args), "/dev/null");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (!files_with(ckpt, ".snap").empty()) {
      kill(pid, SIGKILL);
      break;
    }
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  REQUIRE(waitpid(pid, &status, 0) == pid);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

}  // namespace

TEST_CASE("granmix dsmc killed after its first snapshot and restarted writes the same dsmc.tsv", "[compare]") {
  const auto base = test::fresh_dir("ckpt-dsmc");
  const auto ref = base / "ref", out = base / "out", ckpt = base / "ckpt";
  REQUIRE(test::run_granmix("dsmc " + cooling + " --threads 2 --out " + ref.string()).code == 0);
  REQUIRE(kill_after_first_snapshot({"dsmc", cooling, "--threads", "2", "--out", out.string(), "--checkpoint", ckpt.string(),
                                     "--checkpoint-every", "0"},
                                    ckpt));
  CHECK_FALSE(std::filesystem::exists(out / "ckpt-cooling" / "dsmc.tsv"));
  const auto r = test::run_granmix("dsmc " + cooling + " --threads 1 --out " + out.string() + " --restart " + ckpt.string());
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::string a = read(ref / "ckpt-cooling" / "dsmc.tsv"), b = read(out / "ckpt-cooling" / "dsmc.tsv");
  CHECK(a != b);  // the command lines differ ...
  CHECK(without_command(a) == without_command(b));  // ... and nothing else
  CHECK(files_with(ckpt, ".snap").empty());
  CHECK(files_with(ckpt, ".done").size() == 4);
}

TEST_CASE("granmix validate killed after its first snapshot and restarted writes the same tables", "[compare]") {
  const auto base = test::fresh_dir("ckpt-validate");
  const auto ref = base / "ref", out = base / "out", ckpt = base / "ckpt";
  REQUIRE(test::run_granmix("validate --scenes " + scenes + " --threads 2 --out " + ref.string()).code == 0);
  REQUIRE(kill_after_first_snapshot({"validate", "--scenes", scenes, "--threads", "2", "--out", out.string(), "--checkpoint",
                                     ckpt.string(), "--checkpoint-every", "0"},
                                    ckpt));
  const auto r = test::run_granmix("validate --scenes " + scenes + " --threads 2 --out " + out.string() + " --restart " + ckpt.string());
  INFO(r.output);
  REQUIRE(r.code == 0);
  CHECK(same_tables(ref, out) >= 4);  // theory and dsmc tables of both scenes
  // Run again on the finished folder: every replica is read from its .done file, none recomputed.
  const auto again = test::run_granmix("validate --scenes " + scenes + " --threads 2 --out " + out.string() + " --restart " + ckpt.string());
  CHECK(again.code == 0);
  CHECK(without_command(read(out / "ckpt-cooling" / "dsmc.tsv")) == without_command(read(ref / "ckpt-cooling" / "dsmc.tsv")));
}

TEST_CASE("damaged or foreign checkpoints: exit 2 naming the file, nothing written", "[compare]") {
  const auto base = test::fresh_dir("ckpt-refused");
  const auto out = base / "out", ckpt = base / "ckpt";
  REQUIRE(kill_after_first_snapshot({"dsmc", cooling, "--threads", "2", "--out", out.string(), "--checkpoint", ckpt.string(),
                                     "--checkpoint-every", "0"},
                                    ckpt));
  const auto snap = files_with(ckpt, ".snap").front();
  const std::string good = read(snap);
  std::filesystem::create_directories(out / "ckpt-cooling");
  test::write_file(out / "ckpt-cooling" / "dsmc.tsv", "earlier output\n");
  auto refused = [&](const std::string& bytes, const std::string& why, const std::filesystem::path& file) {
    INFO(why);
    { std::ofstream(file, std::ios::binary) << bytes; }
    const auto r = test::run_granmix("dsmc " + cooling + " --out " + out.string() + " --restart " + ckpt.string());
    INFO(r.output);
    CHECK(r.code == 2);
    CHECK(r.output.find(file.string()) != std::string::npos);
    CHECK(r.output.find(why) != std::string::npos);
    CHECK(read(out / "ckpt-cooling" / "dsmc.tsv") == "earlier output\n");
    CHECK(read(file) == bytes);  // the refused file is kept for inspection
    std::filesystem::remove(file);
  };
  std::string flipped = good;
  flipped[good.size() / 3] ^= 0x01;
  refused(flipped, "checksum mismatch", snap);
  refused(good.substr(0, good.size() / 2), "checksum mismatch", snap);
  dsmc::SnapshotIdentity id = dsmc::read_identity(good, "f", dsmc::SnapshotKind::in_flight);
  const dsmc::ReplicaSnapshot x = dsmc::decode_snapshot(good, "f", id);
  dsmc::SnapshotIdentity old = id;
  old.granmix_version = "0.0.1 (0000000)";
  refused(dsmc::encode_snapshot(old, x), "written by granmix 0.0.1", snap);
  dsmc::SnapshotIdentity other = id;
  other.scene_sha256 = std::string(64, '0');
  refused(dsmc::encode_snapshot(other, x), "a snapshot of another scene", snap);
  refused(good, "a snapshot of another scene or run", ckpt / "ckpt-sweep.quick.seed1.0123456789ab.r0.snap");
  // A missing --restart folder is refused too.
  const auto r = test::run_granmix("dsmc " + cooling + " --out " + out.string() + " --restart " + (base / "nothing").string());
  CHECK(r.code == 2);
  CHECK(r.output.find("no such folder") != std::string::npos);
}

TEST_CASE("SIGTERM with checkpointing: every replica in flight writes a last snapshot, then exit 143", "[compare]") {
  const auto base = test::fresh_dir("ckpt-sigterm");
  const auto out = base / "out", ckpt = base / "ckpt", err = base / "stderr.txt";
  // A scene of minutes; snapshots only every 600 s, so any snapshot is the signal's.
  const pid_t pid = spawn_granmix({"dsmc", std::string(GRANMIX_SOURCE_DIR) + "/tests/scenes/interrupt-long-dsmc.toml", "--threads", "2",
                                   "--out", out.string(), "--checkpoint", ckpt.string()},
                                  err);
  // Into the DSMC: wait for a second of CPU time (the set-up takes milliseconds), not of wall time,
  // which a loaded machine may spend before the replicas start.
  auto cpu_ticks = [&] {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string field;
    long ticks = 0;
    for (int i = 1; i <= 15 && in >> field; ++i)
      if (i >= 14) ticks += std::stol(field);  // utime, stime (a name without spaces: granmix)
    return ticks;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (cpu_ticks() < sysconf(_SC_CLK_TCK) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  REQUIRE(kill(pid, SIGTERM) == 0);
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  const std::string message = read(err);
  INFO(message);
  CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 143));
  const auto snaps = files_with(ckpt, ".snap");
  CHECK(snaps.size() == 2);  // two threads, two replicas in flight
  CHECK(message.find("last snapshots of " + std::to_string(snaps.size()) + " replicas in flight written to " + ckpt.string()) !=
        std::string::npos);
  CHECK_FALSE(std::filesystem::exists(out / "interrupt-long-dsmc"));
  for (const auto& f : snaps) {
    const std::string bytes = read(f);
    CHECK(dsmc::read_identity(bytes, f.string(), dsmc::SnapshotKind::in_flight).unit_key.rfind("interrupt-long-dsmc.quick.seed1.", 0) == 0);
  }
}

#ifdef GRANMIX_MPIEXEC
TEST_CASE("under MPI: validate on 2 ranks killed after its first snapshot, restarted on 3 ranks, writes the same tables", "[compare]") {
  const auto base = test::fresh_dir("ckpt-mpi");
  const auto ref = base / "ref", out = base / "out", ckpt = base / "ckpt";
  REQUIRE(test::run_granmix("validate --scenes " + scenes + " --threads 2 --out " + ref.string()).code == 0);
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);  // containers run as root; Open MPI asks for both
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  // mpirun in a session of its own, so that SIGKILL reaches every rank (a killed node): see kill_session.
  std::vector<std::string> args = {GRANMIX_MPIEXEC, "--oversubscribe", "-n", "2", GRANMIX_EXE, "validate", "--scenes", scenes,
                                   "--threads", "1", "--out", out.string(), "--checkpoint", ckpt.string(), "--checkpoint-every", "0"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSID);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  REQUIRE(posix_spawn(&pid, GRANMIX_MPIEXEC, &fa, &attr, argv.data(), environ) == 0);
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  bool killed = false;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline && waitpid(pid, &status, WNOHANG) == 0) {
    if (!files_with(ckpt, ".snap").empty()) {
      killed = kill_session(pid);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (killed) waitpid(pid, &status, 0);
  REQUIRE(killed);
  const std::string restart = std::string(GRANMIX_MPIEXEC) + " --oversubscribe -n 3 " + GRANMIX_EXE + " validate --scenes " + scenes +
                              " --threads 1 --out " + out.string() + " --restart " + ckpt.string() + " > /dev/null 2>&1";
  REQUIRE(std::system(restart.c_str()) == 0);
  CHECK(same_tables(ref, out) >= 4);
}
#endif
