#pragma once
// A species' full settled density as the tracer problem sees it (tracer_diffusion_galerkin.hpp): a partner i enters
// the pair integrals only through E[f_i/f_M,i | v_iz] (its perpendicular components do not reach the tracer's v′), which
// the Sonine shape makes 1 + a₂S₂ᵃˣ(y) + a₃S₃ᵃˣ(y), y = c_z² = v_z²/(2θ_i); and the species itself through its source,
// r_n = ⟨c² B_n(c²)⟩ over f_k. With the solved speed density P (converged_hcs.hpp, P = 4πu²f) both are computed
// without the Sonine truncation:
//   E[f/f_M | v_z] = g(v_z)/g_M(v_z),  g(v_z) = 2π∫_{|v_z|}^∞ f(u) u du = ½∫_{|v_z|}^∞ P(u)/u du,  g_M = e^(−y)/√(2πθ),
// the axial marginal of f over the Maxwellian's at the density's own temperature θ (so a₁ = 0 as in the Sonine form).
// The D ratios' partners' truncation (converged_hcs_diffusion.hpp) is the change of D_k/D_1 with these in place of
// the Sonine shapes.
#include <Eigen/Dense>

#include <array>
#include <vector>

#include "theory/grid/converged_hcs.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

class AxialShape {
 public:
  // d: the density in MG's reduced speed (any scale: its own second moment fixes v = v₀v* at the temperature θ = T/m,
  // code units).
  AxialShape(const SpeedDensity& d, double theta);
  // E[f/f_M | c_z] at y = c_z², c_z = v_z/√(2θ); 0 beyond the density's grid.
  double at(double y) const;
  // ⟨c² B_n(c²)⟩ over f, c² = u²/(2θ), n < basis.size: tracer_galerkin's r.
  Eigen::VectorXd source(const RadialBasis& basis) const;

 private:
  double h_ = 0.0, theta_ = 0.0;  // knot spacing in code-unit speed; temperature
  Eigen::VectorXd P_;             // spline coefficients in code-unit speed, ∫P du = 1
  std::vector<double> tail_;      // tail_[j] = ∫_{jh}^∞ P(u)/u du, j ≥ 1
  std::array<double, 4> first_{};  // P on [0, h] as Σ c_m u^m (the 1/u at u → 0 integrated exactly)
};

}  // namespace granmix::theory
