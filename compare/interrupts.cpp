#include "interrupts.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

#include "model/errors.hpp"

namespace granmix::compare::interrupts {

namespace {

struct State {
  std::recursive_mutex mutex;
  std::filesystem::path staging;
  std::string finished = "nothing";
  std::vector<std::filesystem::path> created;  // output folders this run created, deepest first
  std::atomic<dsmc::StopRequest*> stop{nullptr};  // checkpointing on: replicas to stop first
  std::filesystem::path checkpoint_dir;
};

// Never destroyed: the watcher may need it while the process exits.
State& state() {
  static State* s = new State;
  return *s;
}

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

[[noreturn]] void watch(sigset_t set) {
  int sig = 0;
  while (sigwait(&set, &sig) != 0) {
  }
  State& s = state();
  std::string snapshots;
  if (dsmc::StopRequest* stop = s.stop.load()) {  // before the lock: a replica's last snapshot may take a while
    const std::size_t n = stop->request_and_wait();
    snapshots = "; last snapshots of " + std::to_string(n) + " replicas in flight written to " + s.checkpoint_dir.string() +
                " (resume with --restart " + s.checkpoint_dir.string() + ")";
  }
  s.mutex.lock();  // held until _Exit: no output is written or renamed any more
  std::error_code ec;
  if (!s.staging.empty()) std::filesystem::remove_all(s.staging, ec);
  for (const auto& d : s.created) std::filesystem::remove(d, ec);  // only if still empty
  std::fprintf(stderr, "granmix: interrupted by %s; finished: %s; no partial output left%s\n", sig == SIGINT ? "SIGINT" : "SIGTERM",
               s.finished.c_str(), snapshots.c_str());
  std::fflush(stderr);
  std::_Exit(128 + sig);
}

}  // namespace

void install() {
  static std::once_flag once;
  std::call_once(once, [] {
    const sigset_t set = interrupt_signals();
    if (const int e = pthread_sigmask(SIG_BLOCK, &set, nullptr); e != 0)
      throw std::system_error(e, std::generic_category(), "pthread_sigmask");
    std::thread(watch, set).detach();
  });
}

void require_writable_folder(const std::filesystem::path& out) {
  const std::filesystem::path abs = std::filesystem::absolute(out);
  std::vector<std::filesystem::path> missing;  // deepest first
  std::error_code ec;
  std::filesystem::path p = abs;
  while (!std::filesystem::exists(p, ec) && p.has_relative_path()) missing.push_back(p), p = p.parent_path();
  auto fail = [&](const std::string& why) {
    for (const auto& d : missing) std::filesystem::remove(d, ec);
    throw InputError("--out " + out.string() + ": " + why + " (allowed: a writable folder, or one that can be created)");
  };
  if (!std::filesystem::is_directory(p, ec)) fail(p.string() + " is not a folder");
  if (!missing.empty() && !std::filesystem::create_directories(abs, ec) && ec) fail("cannot create the folder: " + ec.message());
  const std::filesystem::path probe = abs / (".granmix-probe-" + std::to_string(getpid()));
  // Under mpirun every rank checks --out at once, and a rank that created the folder removes it again after its probe
  // (below): another rank's probe can then meet ENOENT (seen in ctest under load). Create and retry.
  std::FILE* f = nullptr;
  int err = 0;
  for (int attempt = 0; attempt < 8 && f == nullptr; ++attempt) {
    if (attempt > 0) std::filesystem::create_directories(abs, ec);
    f = std::fopen(probe.c_str(), "wb");
    err = errno;
    if (f == nullptr && err != ENOENT) break;
  }
  if (f == nullptr) fail("cannot write in the folder: " + std::string(std::strerror(err)));
  const bool ok = std::fputc('x', f) != EOF && std::fflush(f) == 0;
  const bool closed = std::fclose(f) == 0;
  std::filesystem::remove(probe, ec);
  if (!ok || !closed) fail("cannot write in the folder (full?)");
  for (const auto& d : missing) std::filesystem::remove(d, ec);  // created again when there is output
  State& s = state();
  std::lock_guard lock(s.mutex);
  s.created = missing;
}

void set_staging(const std::filesystem::path& dir) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  s.staging = dir;
}

void set_finished(const std::string& what) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  s.finished = what;
}

void set_stop_request(dsmc::StopRequest* stop, const std::filesystem::path& dir) {
  State& s = state();
  std::lock_guard lock(s.mutex);
  s.checkpoint_dir = dir;
  s.stop = stop;
}

void run_stoppable(const std::function<void(const dsmc::StopRequest&)>& work, const std::function<bool()>& interrupted,
                   std::chrono::milliseconds poll) {
  dsmc::StopRequest stop;
  std::mutex m;
  std::condition_variable finished;
  bool done = false;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      work(stop);
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard lock(m);
    done = true;
    finished.notify_all();
  });
  bool stopped = false;
  try {
    for (;;) {
      {
        std::unique_lock lock(m);
        if (finished.wait_for(lock, poll, [&] { return done; })) break;
      }
      if (!stopped && interrupted()) stopped = true, stop.abandon();
    }
  } catch (...) {  // `interrupted` itself failed: stop the work all the same
    stop.abandon();
    worker.join();
    throw;
  }
  worker.join();
  if (stopped) throw Interrupted();
  if (failure) std::rethrow_exception(failure);
}

WriteGuard::WriteGuard() : lock_(state().mutex) {}

}  // namespace granmix::compare::interrupts
