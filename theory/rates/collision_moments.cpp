#include "theory/rates/collision_moments.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <limits>
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
  // ε = 1 + δ, δ = Σ h_n y^n: (1+ε)² = 4 + 4δ + δ², 1 − ε² = −2δ − δ²; ⟨y^n⟩ = 2 B_n.
  for (std::size_t n = 1; n <= 2 * H; ++n) {
    an *= a;
    const double twoB = an * std::tgamma(2.0 + n / 20.0);
    double c = 0.0;  // Σ_{j+l=n} h_j h_l
    for (std::size_t j = 1; j < n; ++j) c += h(j) * h(n - j);
    m.W2 += (4.0 * h(n) + c) * twoB;  // A_n = 4h_n + Σ h_j h_l (v1 App. A)
    m.D -= (2.0 * h(n) + c) * twoB;
  }
  return m;
}

namespace {

enum class Moment { W2, D };

struct QuadParams {
  double a;
  model::ViscoelasticForm form;
  Moment what;
  model::GslCallbackGuard guard;  // model::restitution throws beyond the exact table
};

// With u = √(2V) w^10 the weight u³e^(-u²/2V) du becomes ∝ 10 w^39 exp(-w^20) dw and
// y = a w: a smooth integrand on a finite range (exp(-w^20) < 1e-40 beyond w = 1.3).
double integrand(double w, void* p) {
  auto* q = static_cast<QuadParams*>(p);
  return q->guard.run(std::numeric_limits<double>::quiet_NaN(), [&] {
    const double y = q->a * w, w20 = std::pow(w, 20);
    double f = 0.0;
    if (q->what == Moment::W2) {
      const double eps = model::restitution(q->form, y);
      f = (1.0 + eps) * (1.0 + eps);
    } else {  // (1 − ε)(1 + ε) from restitution_deficit: 1 − ε(y) loses digits where ε → 1 (y ~ 1e-3)
      const double deficit = model::restitution_deficit(q->form, y);
      f = deficit * (2.0 - deficit);
    }
    return 20.0 * std::pow(w, 39) * std::exp(-w20) * f;
  });
}

double moment(double a, model::ViscoelasticForm form, Moment what) {
  model::use_gsl_return_codes();
  QuadParams q{a, form, what, {}};
  gsl_function f{integrand, &q};
  double result = 0.0, abserr = 0.0;
  // 1e-12 relative: the rates built on these moments are compared with the series at 1e-8.
  // The exact form's ε is a table (1e-9): its 1 − ε carries rounding of 1e-16 absolute, below
  // which no accuracy can be asked for (the weight integrates to 1).
  const double epsabs = form == model::ViscoelasticForm::exact ? 1e-15 : 0.0;
  const int status = gsl_integration_qag(&f, 0.0, 1.3, epsabs, 1e-12, 64, GSL_INTEG_GAUSS31,
                                          model::quadrature_workspace(model::QuadratureLevel::inner), &result, &abserr);
  q.guard.rethrow();
  if (status != GSL_SUCCESS)
    throw NumericalError(std::string("collision moment quadrature (gsl_integration_qag): ") + gsl_strerror(status));
  return result;  // ∫ 20 w^39 e^(-w^20) dw = 1: already normalised
}

}  // namespace

CollisionMoments quadrature_moments(double a, model::ViscoelasticForm form) {
  return {moment(a, form, Moment::W2), moment(a, form, Moment::D)};
}

}  // namespace granmix::theory
