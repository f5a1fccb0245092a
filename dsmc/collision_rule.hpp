#pragma once
// One inelastic collision (v1 Eq. 3, MG Eqs. 23–24): g = v_a − v_b, e the unit vector along the
// line of centres with g·e > 0; v_a −= (m_b/(m_a+m_b))(1+ε)(g·e)e, v_b += (m_a/(m_a+m_b))(1+ε)(g·e)e.
// Momentum is conserved exactly (up to rounding); kinetic energy drops by (1−ε²) m_eff (g·e)²/2.
#include "particles.hpp"

namespace granmix::dsmc {

inline void collide(Particles& p, std::size_t a, std::size_t b, double ma, double mb, double eps, const Vec3& e,
                    double g_dot_e) {
  const double impulse = (1.0 + eps) * g_dot_e / (ma + mb);  // J / (m_a m_b) with J = m_eff (1+ε) g·e
  const double da = mb * impulse, db = ma * impulse;
  Vec3 &va = p.v[a], &vb = p.v[b];
  va.x -= da * e.x, va.y -= da * e.y, va.z -= da * e.z;
  vb.x += db * e.x, vb.y += db * e.y, vb.z += db * e.z;
}

// v1 Eq. (15): before a particle's velocity changes, its free flight since the last collision is
// added to its displacement.
inline void advance_displacement(Particles& p, std::size_t a, double t) {
  Particles::Flight& f = p.flight[a];
  const double dt = t - f.t_last;
  f.r.x += p.v[a].x * dt, f.r.y += p.v[a].y * dt, f.r.z += p.v[a].z * dt;
  f.t_last = t;
}

}  // namespace granmix::dsmc
