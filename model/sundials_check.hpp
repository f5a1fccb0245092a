#pragma once
// Every SUNDIALS call is checked at once; a failure names the call and the solver's message.
#include <cvode/cvode.h>

#include <string>

#include "errors.hpp"

namespace granmix::model {

inline void check_cvode(int flag, const char* call, const std::string& context = {}) {
  if (flag >= 0) return;
  std::string msg = std::string(call) + " failed: " + CVodeGetReturnFlagName(flag);
  if (!context.empty()) msg += " (" + context + ")";
  throw NumericalError(msg);
}

template <class T>
T* check_alloc(T* p, const char* call) {
  if (p == nullptr) throw NumericalError(std::string(call) + " returned no memory");
  return p;
}

}  // namespace granmix::model
