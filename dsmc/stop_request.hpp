#pragma once
// A stop asked of the replicas in flight (SIGINT/SIGTERM with checkpointing on, compare/interrupts.cpp):
// each writes a snapshot at its next refresh point and then waits for the process to end; replicas
// not yet started do not start. The watcher that asked waits until no replica is in flight and
// then ends the process. Polled only at refresh points (an atomic load every N collisions).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>

namespace granmix::dsmc {

class StopRequest {
 public:
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
  std::atomic<bool> requested_{false};
  std::mutex mutex_;
  std::condition_variable idle_;
  std::size_t in_flight_ = 0, stopped_ = 0;
};

}  // namespace granmix::dsmc
