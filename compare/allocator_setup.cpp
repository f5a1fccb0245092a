#include "allocator_setup.hpp"

#include <malloc.h>

#include <utility>

namespace granmix::compare {

void keep_freed_memory() {
#if defined(__GLIBC__)
  const std::pair<int, int> settings[] = {{M_MMAP_THRESHOLD, 32 << 20}, {M_TRIM_THRESHOLD, 512 << 20}, {M_TOP_PAD, 64 << 20}};
  for (const auto& [param, value] : settings)
    if (mallopt(param, value) != 1) return;  // refused (another allocator, e.g. a sanitizer's): the defaults stay, speed only
#endif
}

}  // namespace granmix::compare
