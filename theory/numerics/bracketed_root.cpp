#include "theory/numerics/bracketed_root.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <limits>

#include "model/errors.hpp"
#include "model/gsl_setup.hpp"

namespace granmix::theory {

Root bracketed_root(const std::function<double(double)>& f, const std::string& what, double limit) {
  model::use_gsl_return_codes();
  double lo = -1.0, hi = 1.0;
  double flo = f(lo), fhi = f(hi);
  while (flo * fhi > 0.0) {
    if (hi >= limit)
      throw NumericalError(what + ": no sign change within |x| <= " + std::to_string(limit));
    lo *= 2.0, hi *= 2.0;
    flo = f(lo), fhi = f(hi);
  }
  if (flo == 0.0) return {lo, 0};
  if (fhi == 0.0) return {hi, 0};
  struct Callback {
    const std::function<double(double)>& f;
    model::GslCallbackGuard guard;
  } cb{f, {}};
  gsl_function F{[](double x, void* p) {
                   auto& c = *static_cast<Callback*>(p);
                   return c.guard.run(std::numeric_limits<double>::quiet_NaN(), [&] { return c.f(x); });
                 },
                 &cb};
  const model::GslPtr<gsl_root_fsolver, gsl_root_fsolver_free> s(gsl_root_fsolver_alloc(gsl_root_fsolver_brent));
  if (s == nullptr) throw NumericalError("gsl_root_fsolver_alloc failed");
  Root out;
  int status = gsl_root_fsolver_set(s.get(), &F, lo, hi);
  while (status == GSL_SUCCESS && out.iterations < 500) {
    ++out.iterations;
    status = gsl_root_fsolver_iterate(s.get());
    if (status != GSL_SUCCESS) break;
    out.x = gsl_root_fsolver_root(s.get());
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(s.get()), gsl_root_fsolver_x_upper(s.get()), 1e-300, 2e-16);
    if (status == GSL_SUCCESS) break;
    if (status == GSL_CONTINUE) status = GSL_SUCCESS;
  }
  cb.guard.rethrow();
  if (status != GSL_SUCCESS) throw NumericalError(what + " (gsl brent): " + gsl_strerror(status));
  return out;
}

}  // namespace granmix::theory
