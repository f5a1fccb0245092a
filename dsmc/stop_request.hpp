#pragma once
// A stop asked of the replicas in flight, in one of two ways, polled only at refresh points (an atomic load every N
// collisions):
// * request_and_wait (SIGINT/SIGTERM with checkpointing on, compare/interrupts.cpp): each replica writes a snapshot at its
//   next refresh point and then waits for the process to end; replicas not yet started do not start. The watcher that
//   asked waits until no replica is in flight and then ends the process.
// * abandon (a host that handles signals itself and lives on, compare/interrupts.hpp's run_stoppable, the Python
//   module): each replica throws Stopped at its next refresh point, replicas not yet started throw at once; nothing is
//   written and the run ends with that exception.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace granmix::dsmc {

// A replica abandoned by StopRequest::abandon.
struct Stopped : std::runtime_error {
  Stopped() : std::runtime_error("DSMC stopped on request") {}
};

class StopRequest {
 public:
  // The abandoning stop (above): from any thread, at any time.
  void abandon() { abandoned_.store(true, std::memory_order_relaxed); }
  bool abandoned() const { return abandoned_.load(std::memory_order_relaxed); }
  // A replica at a refresh point or about to start.
  void throw_if_abandoned() const {
    if (abandoned()) throw Stopped();
  }
  bool requested() const { return requested_.load(std::memory_order_relaxed); }
  // The watcher: ask, then wait until every replica in flight has written its snapshot. Returns
  // how many did.
  std::size_t request_and_wait() {
    std::unique_lock lock(mutex_);
    requested_ = true;
    idle_.wait(lock, [&] { return in_flight_ == 0; });
    return stopped_;
  }
  // A replica starts (false: a stop was asked, do not start) and ends (finished, or stopped after
  // its snapshot: `stopped`).
  bool enter() {
    std::lock_guard lock(mutex_);
    if (requested_) return false;
    ++in_flight_;
    return true;
  }
  void leave(bool stopped) {
    std::lock_guard lock(mutex_);
    --in_flight_, stopped_ += stopped;
    idle_.notify_all();
  }
  // A stopped replica's thread waits here for the watcher to end the process.
  [[noreturn]] static void wait_for_exit() {
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
  }

 private:
  std::atomic<bool> requested_{false}, abandoned_{false};
  std::mutex mutex_;
  std::condition_variable idle_;
  std::size_t in_flight_ = 0, stopped_ = 0;
};

}  // namespace granmix::dsmc
