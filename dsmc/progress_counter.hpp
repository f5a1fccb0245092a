#pragma once
// The collisions of the replicas in flight, published at their refresh points (every N accepted collisions, N the
// particle count), so that a long replica shows progress before it ends: the scheduler's progress line
// (compare/scheduler.cpp) adds them to the finished replicas' and estimates the time left from the units' costs
// (dsmc/unit_cost.hpp, in collisions). Reading it changes nothing in any replica.
#include <atomic>
#include <cstdint>

namespace granmix::dsmc {

class InFlightCollisions {
 public:
  // A replica's accepted collisions so far (called at its refresh points and with 0 when it ends).
  void publish(std::uint64_t& published, std::uint64_t accepted) {
    total_.fetch_add(static_cast<std::int64_t>(accepted) - static_cast<std::int64_t>(published), std::memory_order_relaxed);
    published = accepted;
  }
  std::int64_t total() const { return total_.load(std::memory_order_relaxed); }

 private:
  std::atomic<std::int64_t> total_{0};
};

// The process's one counter (replicas of every set-up and thread add to it).
inline InFlightCollisions& in_flight_collisions() {
  static InFlightCollisions counter;
  return counter;
}

// Publishes a replica's collisions while it runs and takes them back when it ends (finished or thrown).
class PublishedCollisions {
 public:
  void at(std::uint64_t accepted) { in_flight_collisions().publish(published_, accepted); }
  ~PublishedCollisions() { in_flight_collisions().publish(published_, 0); }

 private:
  std::uint64_t published_ = 0;
};

}  // namespace granmix::dsmc
