#include "cycle_counter.hpp"

#include <initializer_list>

#if defined(__linux__)
#include <linux/perf_event.h>
#include <sys/ioctl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstring>
#endif

namespace granmix::bench {

#if defined(__linux__)
namespace {
// One user-space hardware counter of this thread (pid 0, any CPU), disabled until start().
int open_counter(std::uint64_t config) {
  perf_event_attr a;
  std::memset(&a, 0, sizeof a);
  a.size = sizeof a;
  a.type = PERF_TYPE_HARDWARE;
  a.config = config;
  a.disabled = 1;
  a.exclude_kernel = 1;
  a.exclude_hv = 1;
  return static_cast<int>(syscall(SYS_perf_event_open, &a, 0, -1, -1, 0));
}

bool read_counter(int fd, std::uint64_t& v) { return read(fd, &v, sizeof v) == static_cast<ssize_t>(sizeof v); }
}  // namespace

CycleCounter::CycleCounter() : cycles_fd_(open_counter(PERF_COUNT_HW_CPU_CYCLES)), instructions_fd_(open_counter(PERF_COUNT_HW_INSTRUCTIONS)) {}

CycleCounter::~CycleCounter() { close_all(); }

void CycleCounter::start() {
  if (!available()) return;
  for (int fd : {cycles_fd_, instructions_fd_})
    if (ioctl(fd, PERF_EVENT_IOC_RESET, 0) != 0 || ioctl(fd, PERF_EVENT_IOC_ENABLE, 0) != 0) return close_all();
}

CycleCounter::Counts CycleCounter::stop() {
  if (!available()) return {};
  for (int fd : {cycles_fd_, instructions_fd_})
    if (ioctl(fd, PERF_EVENT_IOC_DISABLE, 0) != 0) return close_all(), Counts{};
  Counts c;
  if (!read_counter(cycles_fd_, c.cycles) || !read_counter(instructions_fd_, c.instructions)) return close_all(), Counts{};
  c.valid = true;
  return c;
}

void CycleCounter::close_all() {
  if (cycles_fd_ >= 0) close(cycles_fd_);
  if (instructions_fd_ >= 0) close(instructions_fd_);
  cycles_fd_ = instructions_fd_ = -1;
}
#else
CycleCounter::CycleCounter() {}
CycleCounter::~CycleCounter() {}
void CycleCounter::start() {}
CycleCounter::Counts CycleCounter::stop() { return {}; }
void CycleCounter::close_all() {}
#endif

}  // namespace granmix::bench
