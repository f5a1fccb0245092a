#include "theory/sonine/sonine_second_order.hpp"

#include "model/errors.hpp"

namespace granmix::theory {

HcsCollisionMoments hcs_collision_moments(double a) {
  const double a2 = a * a, a3 = a2 * a, a4 = a2 * a2, a5 = a4 * a, e = 1.0 - a2, p = 1.0 + a;
  // Each coefficient vanishes at α = −1 (no momentum transfer); the a-independent ones also at α = 1
  // (elastic: a Maxwellian is stationary). The elastic a₂ coefficient of μ₄ is 4, the linearised
  // Boltzmann eigenvalue of S₂ for hard spheres.
  HcsCollisionMoments m;
  m.mu2 = {e, 3.0 / 16.0 * e, e / 64.0};
  m.mu4 = {e * (4.5 + a2), p * (271.0 - 207.0 * a + 30.0 * a2 - 30.0 * a3) / 32.0,
           -p * (181.0 - 117.0 * a + 10.0 * a2 - 10.0 * a3) / 128.0};
  m.mu6 = {3.0 / 16.0 * e * (115.0 + 44.0 * a2 + 8.0 * a4),
           3.0 / 256.0 * p * (8297.0 - 6889.0 * a + 2852.0 * a2 - 2340.0 * a3 + 280.0 * a4 - 280.0 * a5),
           -3.0 / 1024.0 * p * (16841.0 - 12617.0 * a + 5476.0 * a2 - 3940.0 * a3 + 280.0 * a4 - 280.0 * a5)};
  return m;
}

namespace {

// μ₄ − 5μ₂(1 + a₂) = 0 and μ₆ − (105/4)μ₂(1 + 3a₂ − a₃) = 0, linear in a₂, a₃: K (a₂, a₃) = r.
struct LinearSystem {
  double K11, K12, K21, K22, r1, r2;
};

LinearSystem linear_system(double alpha) {
  if (!(alpha >= 0.0 && alpha <= 1.0)) throw InputError("second Sonine HCS: restitution must lie in [0, 1]");
  const HcsCollisionMoments m = hcs_collision_moments(alpha);
  const auto& A = m.mu2;
  const auto& B = m.mu4;
  const auto& C = m.mu6;
  const double k = 105.0 / 4.0;
  return {B[1] - 5.0 * (A[0] + A[1]), B[2] - 5.0 * A[2], C[1] - k * (3.0 * A[0] + A[1]), C[2] - k * (A[2] - A[0]),
          5.0 * A[0] - B[0], k * A[0] - C[0]};
}

}  // namespace

SecondSonine second_sonine_hcs(double alpha) {
  const LinearSystem s = linear_system(alpha);
  const double det = s.K11 * s.K22 - s.K12 * s.K21;  // from −39.2 (α = 0) down to −90 (α = 1): never singular
  // + 0.0: the elastic solution is +0, not −0 (it is printed).
  return {(s.r1 * s.K22 - s.K12 * s.r2) / det + 0.0, (s.K11 * s.r2 - s.K21 * s.r1) / det + 0.0};
}

double third_sonine_given_a2(double alpha, double a2) {
  const LinearSystem s = linear_system(alpha);
  return (s.r2 - s.K21 * a2) / s.K22;  // K22 between −23.5 (α = 0) and −34: never zero
}

}  // namespace granmix::theory
