#pragma once
// The scalars of a DSMC loop that a snapshot of a replica in flight carries (dsmc/replica_snapshot.hpp).
// Snapshots are taken only where everything else of the loop is a pure function of the particles
// (the event loop's refresh points, the time-step scheme's step boundaries), so these scalars, the
// particles, the counters and the random stream restore the loop exactly.
#include <cstdint>
#include <vector>

namespace granmix::dsmc {

struct LoopState {
  double t = 0.0;                // the loop's clock
  double ts = 0.0, t_e1 = 0.0;   // event loop: rescaled time accumulated up to t_e1 (EventLoop::rescaled_time)
  double e1_start = 0.0;         // event loop: kinetic energy of species 1 at the clock's start
  std::uint64_t steps = 0;       // time-step scheme: steps taken
  std::vector<double> carry;     // time-step scheme: fractional candidate counts per ordered pair
};

}  // namespace granmix::dsmc
