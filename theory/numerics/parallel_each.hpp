#pragma once
// parallel_each(n, f): f(i) for every i in [0, n) on OpenMP threads, each call wholly on one thread (dynamic
// schedule, one index at a time), so results that f writes per index do not depend on the thread count. An
// exception may not leave an OpenMP region: each is caught, and after all calls the lowest index's is rethrown.
// parallel = false: the same calls in order on the calling thread (work too small for a fork and join: where it runs
// per right-hand side, a core taken by another process leaves the other thread spinning at every join).
#include <cstddef>
#include <exception>
#include <vector>

namespace granmix::theory {

template <class F>
void parallel_each(std::size_t n, F&& f, bool parallel = true) {
  std::vector<std::exception_ptr> failed(n);
#pragma omp parallel for schedule(dynamic, 1) if (parallel && n > 1)
  for (std::size_t i = 0; i < n; ++i) {
    try {
      f(i);
    } catch (...) {
      failed[i] = std::current_exception();
    }
  }
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace granmix::theory
