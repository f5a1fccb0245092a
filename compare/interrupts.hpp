#pragma once
// SIGINT/SIGTERM during `granmix dsmc|compare|validate`: the run stops with exit 130/143,
// one line on stderr saying what was finished, and no partial output: the staging folder of the scene
// in progress and any output folder this run created empty are removed. Signals are taken by a
// watcher thread (sigwait), not an async handler, so the clean-up may use the file system freely;
// a WriteGuard holds it off while outputs are being written or renamed into place.
// A host that takes the signals itself and lives on (the Python module) runs its work through run_stoppable instead.
#include <chrono>
#include <filesystem>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>

#include "dsmc/stop_request.hpp"

namespace granmix::compare::interrupts {

// Blocks SIGINT and SIGTERM in the calling thread (and so in every thread it starts later, OpenMP's
// included) and starts the watcher. Call first in a command, before any thread exists.
void install();

// Exit 2 (InputError naming the path) unless `out` is, or can be created as, a writable folder. The
// check creates and removes a probe file and the folders it needed; none is left behind.
void require_writable_folder(const std::filesystem::path& out);

// The folder being filled for the current scene: removed if the run is interrupted. Empty: none.
void set_staging(const std::filesystem::path& dir);
// What the run has finished, for the message (e.g. "3 of 33 scenes written to out/").
void set_finished(const std::string& what);

// With checkpointing on: an interrupt first asks every replica in flight for a last snapshot in
// `dir` and waits until they have written it (dsmc/stop_request.hpp), then ends the run as above.
void set_stop_request(dsmc::StopRequest* stop, const std::filesystem::path& dir);

// For a host with signal handling of its own, which goes on after an interrupt (the Python module, where SIGINT raises
// KeyboardInterrupt; install() is never called there): `work` runs on a thread of its own and hands the stop request to
// its DSMC runs (dsmc::RunOptions::stop); the calling thread asks `interrupted` every `poll`, and once it answers true,
// the replicas are abandoned at their next refresh point (dsmc/stop_request.hpp), the work is waited for and Interrupted
// is thrown. Otherwise the work's own exception, if any, is rethrown on the calling thread.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};
void run_stoppable(const std::function<void(const dsmc::StopRequest&)>& work, const std::function<bool()>& interrupted,
                   std::chrono::milliseconds poll = std::chrono::milliseconds(20));

// While alive, an interrupt waits (writes of several files and the final rename are not split).
class WriteGuard {
 public:
  WriteGuard();
 private:
  std::unique_lock<std::recursive_mutex> lock_;
};

}  // namespace granmix::compare::interrupts
