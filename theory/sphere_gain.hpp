#pragma once
// What a collision sends into the speed grid's cubic B-splines (tracer_speed_grid.hpp), exact over σ̂. For hard spheres
// the post-collision velocity v′ = v − β(g·σ̂)σ̂, weighted by (g·σ̂)Θ dσ̂, is uniform on the sphere of radius R = βg/2
// about c = v − βg/2 (with χ = 2θ the angle to ĝ, (ĝ·σ̂)dσ̂ = dΩ_χ/4: total π). So |v′|² is uniform on
// [(|c| − R)², (|c| + R)²], the speed s = |v′| has the density s/(2|c|R) there, and every gain the grid needs is
// Σ_p W_p ∫ N_m(s) sᵖ ds (p = 0, 1, 2) over that range: the speed density's (W₁ = 1/(2|c|R)) and the l = 1 harmonic's
// (the circle |v′| = s averages v̂·v′ to (v̂·ĉ)(s² + |c|² − R²)/(2|c|)). Piecewise polynomials: two end pieces per
// collision, the whole knot intervals between by running sums — where a rule of 30 folded σ̂ directions (before
// 2026-12-05) sampled a cubic spline across ~10 knot intervals.
#include <array>
#include <cstddef>
#include <vector>

namespace granmix::theory {

class SphereGain {
 public:
  // nb splines N_m(s) = spline(s/h − m + 3) (tracer_speed_grid.cpp), m = 0 … nb − 1.
  SphereGain(std::size_t nb, double h);
  void clear();
  // Adds Σ_p W[p] ∫ N_m(s) sᵖ ds over s ∈ [s_lo, s_hi]; beyond the last spline's support the gain leaves the grid.
  void add_range(double s_lo, double s_hi, const std::array<double, 3>& W);
  // Adds weight · N_m(s): a collision whose sphere is a point (R or |c| ≈ 0).
  void add_point(double s, double weight);
  // The gain into spline m, once the whole intervals are added (after the last add_range); the caller may subtract its
  // loss in place (clear() starts the next speed).
  std::vector<double>& finish();

 private:
  double h_;
  std::size_t nb_;
  std::vector<double> gain_;  // three entries past the last spline: a speed in the last knot interval reaches them
  std::vector<std::array<double, 3>> whole_;  // running sums of h^(p+1) W_p over the whole knot intervals
};

}  // namespace granmix::theory
