#include "theory/sonine/sonine_truncation.hpp"

#include <cmath>

#include "model/enskog.hpp"
#include "model/mixture.hpp"
#include "model/restitution.hpp"
#include "theory/sonine/sonine_hcs.hpp"
#include "theory/sonine/sonine_polynomials.hpp"

namespace granmix::theory {

double SonineTruncation::a2_relative() const { return std::abs(linear.a2 - a2_first) / std::abs(a2_first); }

double SonineTruncation::phi_a3_relative(double c, SonineScheme s) const {
  const double x = c * c;
  return std::abs(second(s).a3 * sonine_S3(x)) / std::abs(1.0 + a2_first * sonine_S2(x));
}

double SonineTruncation::phi_relative(double c, SonineScheme s) const {
  const double x = c * c;
  const SecondSonine& f = second(s);
  return std::abs((f.a2 - a2_first) * sonine_S2(x) + f.a3 * sonine_S3(x)) / std::abs(1.0 + a2_first * sonine_S2(x));
}

double SonineTruncation::delta_shift(double c, SonineScheme s) const { return second(s).a3 / second(s).a2 * sonine_S3(c * c); }

double SonineTruncation::delta_a3_relative(double c, SonineScheme s) const {
  const double x = c * c;
  return std::abs(second(s).a3 * sonine_S3(x)) / std::abs(second(s).a2 * sonine_S2(x));
}

SonineTruncation sonine_truncation(double alpha) {
  const SecondSonine second = second_sonine_hcs(alpha);  // checks the range of alpha
  // The first-Sonine a₂ of one species is the c/2 of the HCS solver theory/ uses everywhere (its
  // one-species limit is van Noije–Ernst's; tests/theory/test_sonine.cpp); density and size drop out.
  const SonineHcs first = sonine_hcs(model::Mixture({{1.0, 1.0, 1.0}}), model::Restitution::constant(1, alpha),
                                     model::dilute_contact_values(1));
  const double a2_first = 0.5 * first.c[0];
  return {alpha, a2_first, second, {a2_first, third_sonine_given_a2(alpha, a2_first)}};
}

}  // namespace granmix::theory
