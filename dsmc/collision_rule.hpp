#pragma once
// One inelastic collision (v1 Eq. 3, MG Eqs. 23–24): g = v_a − v_b, e the unit vector along the
// line of centres with g·e > 0; v_a −= (m_b/(m_a+m_b))(1+ε)(g·e)e, v_b += (m_a/(m_a+m_b))(1+ε)(g·e)e.
// Momentum is conserved exactly (up to rounding); kinetic energy drops by (1−ε²) m_eff (g·e)²/2.
#include "particles.hpp"

namespace granmix::dsmc {

// At time t. With displacements (v1 Eq. 15), each flight intercept R0_e = R − v (t − t_e) changes by
// −Δv (t − t_e), so that R(t) = R0_e + v (t − t_e) is continuous through the collision (particles.hpp).
inline void collide(Particles& p, std::size_t a, std::size_t b, double ma, double mb, double eps, const Vec3& e, double g_dot_e,
                    double t) {
  const double impulse = (1.0 + eps) * g_dot_e / (ma + mb);  // J / (m_a m_b) with J = m_eff (1+ε) g·e
  const double da = mb * impulse, db = ma * impulse;
  Vec3 &va = p.v[a], &vb = p.v[b];
  va.x -= da * e.x, va.y -= da * e.y, va.z -= da * e.z;
  vb.x += db * e.x, vb.y += db * e.y, vb.z += db * e.z;
  if (!p.track_displacement) return;
  const double since_epoch = t - p.epoch;
  const double ra = da * since_epoch, rb = db * since_epoch;  // Δv_a = −da e, Δv_b = +db e
  add_scaled(p.flight[a], ra, e);
  add_scaled(p.flight[b], -rb, e);
}

}  // namespace granmix::dsmc
