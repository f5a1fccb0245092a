#pragma once
// CPU cycles and instructions of the calling thread from the hardware counters (Linux
// perf_event_open), for the selector study's cycles per trial. Where the counters do not
// exist (virtual machines, perf_event_paranoid > 2, other systems) available() is false and the study
// leaves its cycle columns out.
#include <cstdint>

namespace granmix::bench {

class CycleCounter {
 public:
  CycleCounter();  // opens the counters, disabled
  ~CycleCounter();
  CycleCounter(const CycleCounter&) = delete;
  CycleCounter& operator=(const CycleCounter&) = delete;
  bool available() const { return cycles_fd_ >= 0 && instructions_fd_ >= 0; }
  void start();  // zero and enable (a failing call closes the counters: available() turns false)
  struct Counts {
    std::uint64_t cycles = 0, instructions = 0;
    bool valid = false;  // false when a counter call failed (the counter is then closed)
  };
  Counts stop();  // disable and read

 private:
  void close_all();
  int cycles_fd_ = -1, instructions_fd_ = -1;
};

}  // namespace granmix::bench
