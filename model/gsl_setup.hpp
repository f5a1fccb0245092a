#pragma once
// GSL's default error handler aborts the process. granmix checks every GSL return code instead,
// so the handler is switched off once, before the first GSL call of any layer.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <array>
#include <exception>
#include <memory>
#include <mutex>

#include "errors.hpp"

namespace granmix::model {

inline void use_gsl_return_codes() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

// GSL calls granmix's functions from its C frames: an exception must not unwind through them (the
// solver allocated around the call leaks, and C frames need not have unwind tables; fuzz_hcs_args
// found the leak: a singular Sonine system thrown from inside gsl_multiroot). A callback runs its
// body through run(): the first exception is kept and GSL gets the failure value; the caller frees
// GSL's state (unique_ptr below), then calls rethrow().
class GslCallbackGuard {
 public:
  template <class R, class Body>
  R run(R failure, Body&& body) noexcept {
    if (error_) return failure;
    try {
      return body();
    } catch (...) {
      error_ = std::current_exception();
      return failure;
    }
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::exception_ptr error_;
};

// GSL objects owned by a unique_ptr with their free function: freed on every path, throws included.
template <auto Free>
struct GslFree {
  template <class T>
  void operator()(T* p) const {
    Free(p);
  }
};
template <class T, auto Free>
using GslPtr = std::unique_ptr<T, GslFree<Free>>;

// Adaptive-quadrature workspaces, one set per thread (replicas and sweeps may integrate at once).
// Quadratures nest: the MSD integrand (outer) may evaluate viscoelastic collision moments, which
// are quadratures themselves (inner); each level has its own workspace so they never share one.
enum class QuadratureLevel { outer = 0, inner = 1 };
inline constexpr std::size_t quadrature_intervals = 1000;

inline gsl_integration_workspace* quadrature_workspace(QuadratureLevel level) {
  struct Workspaces {
    std::array<gsl_integration_workspace*, 2> w{gsl_integration_workspace_alloc(quadrature_intervals),
                                                gsl_integration_workspace_alloc(quadrature_intervals)};
    ~Workspaces() {
      for (auto* p : w) gsl_integration_workspace_free(p);
    }
  };
  thread_local Workspaces ws;
  gsl_integration_workspace* p = ws.w[static_cast<std::size_t>(level)];
  if (p == nullptr) throw NumericalError("gsl_integration_workspace_alloc failed");
  return p;
}

}  // namespace granmix::model
