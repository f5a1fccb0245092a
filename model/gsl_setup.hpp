#pragma once
// GSL's default error handler aborts the process. granmix checks every GSL return code instead,
// so the handler is switched off once, before the first GSL call of any layer.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <array>
#include <mutex>

#include "errors.hpp"

namespace granmix::model {

inline void use_gsl_return_codes() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

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
