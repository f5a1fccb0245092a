#include "theory/histories/tamsd.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "model/gsl_setup.hpp"

namespace granmix::theory {

double msd_increment(double D0, double tau_v0, double tau0, double t, double lag) {
  return msd_increment(VelocityMemory::exponential(D0, tau_v0), tau0, t, lag);
}

double tamsd(double D0, double tau_v0, double tau0, double measurement_time, double lag) {
  return tamsd(VelocityMemory::exponential(D0, tau_v0), tau0, measurement_time, lag);
}

double tamsd(const VelocityMemory& memory, double tau0, double measurement_time, double lag) {
  if (!(lag > 0.0 && lag < measurement_time))
    throw std::invalid_argument("TAMSD: the lag must lie in (0, measurement time)");
  model::use_gsl_return_codes();
  struct Params {
    const VelocityMemory& memory;
    double tau0, lag;
  } p{memory, tau0, lag};
  gsl_function f{[](double t, void* q) {
                   const auto* a = static_cast<const Params*>(q);
                   return msd_increment(a->memory, a->tau0, t, a->lag);
                 },
                 &p};
  double result = 0.0, abserr = 0.0;
  const double span = measurement_time - lag;
  // 1e-10 relative: far below any statistical error a simulation can reach.
  int status = gsl_integration_qag(&f, 0.0, span, 0.0, 1e-10, model::quadrature_intervals, GSL_INTEG_GAUSS21,
                                   model::quadrature_workspace(model::QuadratureLevel::outer), &result, &abserr);
  // The increments' own rounding (differences of exponentials) stops the refinement near 1e-9 for a heavy intruder
  // whose velocity persists (mass ratio 1e4: 1.3e-9); accepted while the error estimate stays below 1e-7 relative.
  if (status == GSL_EROUND && abserr <= 1e-7 * std::abs(result)) status = GSL_SUCCESS;
  if (status != GSL_SUCCESS) throw NumericalError(std::string("TAMSD quadrature: ") + gsl_strerror(status));
  return result / span;
}

}  // namespace granmix::theory
