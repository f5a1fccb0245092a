#include "collision_moments.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "model/gsl_setup.hpp"

namespace granmix::theory {

double viscoelastic_scale(double akappa, double V) { return std::sqrt(akappa) * std::pow(2.0 * V, 0.05); }

CollisionMoments series_moments(double a) {
  constexpr std::size_t H = model::viscoelastic_h.size();
  auto h = [](std::size_t n) { return (n >= 1 && n <= H) ? model::viscoelastic_h[n - 1] : 0.0; };
  CollisionMoments m;
  double an = 1.0;
  for (std::size_t n = 1; n <= 2 * H; ++n) {
    an *= a;
    const double twoB = an * std::tgamma(2.0 + n / 20.0);  // ⟨y^n⟩ = 2 B_n
    double An = 4.0 * h(n);                                  // A_n = 4h_n + Σ_{j+l=n} h_j h_l
    for (std::size_t j = 1; j < n; ++j) An += h(j) * h(n - j);
    m.W1 += h(n) * twoB;
    m.W2 += An * twoB;
  }
  return m;
}

namespace {

struct QuadParams {
  double a;
  model::ViscoelasticForm form;
  int power;
};

// With u = √(2V) w^10 the weight u³e^(-u²/2V) du becomes ∝ 10 w^39 exp(-w^20) dw and
// y = a w: a smooth integrand on a finite range (exp(-w^20) < 1e-40 beyond w = 1.3).
double integrand(double w, void* p) {
  const auto* q = static_cast<const QuadParams*>(p);
  const double one_plus_eps = 1.0 + model::restitution(q->form, q->a * w);
  const double w20 = std::pow(w, 20);
  return 20.0 * std::pow(w, 39) * std::exp(-w20) * (q->power == 1 ? one_plus_eps : one_plus_eps * one_plus_eps);
}

double moment(double a, model::ViscoelasticForm form, int power) {
  model::use_gsl_return_codes();
  // One workspace per thread: replicas and sweeps may evaluate rates concurrently.
  struct Workspace {
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(64);
    ~Workspace() { gsl_integration_workspace_free(w); }
  };
  thread_local Workspace ws;
  if (ws.w == nullptr) throw NumericalError("gsl_integration_workspace_alloc failed");
  QuadParams q{a, form, power};
  gsl_function f{integrand, &q};
  double result = 0.0, abserr = 0.0;
  // 1e-12 relative: the rates built on these moments are compared with the series at 1e-8.
  const int status = gsl_integration_qag(&f, 0.0, 1.3, 0.0, 1e-12, 64, GSL_INTEG_GAUSS31, ws.w, &result, &abserr);
  if (status != GSL_SUCCESS)
    throw NumericalError(std::string("collision moment quadrature (gsl_integration_qag): ") + gsl_strerror(status));
  return result;  // ∫ 20 w^39 e^(-w^20) dw = 1: already normalised
}

}  // namespace

CollisionMoments quadrature_moments(double a, model::ViscoelasticForm form) {
  return {moment(a, form, 1), moment(a, form, 2)};
}

}  // namespace granmix::theory
