#pragma once
// GSL's default error handler aborts the process. granmix checks every GSL return code instead,
// so the handler is switched off once, before the first GSL call of any layer.
#include <gsl/gsl_errno.h>

#include <mutex>

namespace granmix::model {

inline void use_gsl_return_codes() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

}  // namespace granmix::model
