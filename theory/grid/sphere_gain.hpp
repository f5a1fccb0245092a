#pragma once
// What a collision sends into the speed grid's cubic B-splines (speed_grid.hpp), exact over σ̂. For hard spheres
// the post-collision velocity v′ = v − β(g·σ̂)σ̂, weighted by (g·σ̂)Θ dσ̂, is uniform on the sphere of radius R = βg/2
// about c = v − βg/2 (with χ = 2θ the angle to ĝ, (ĝ·σ̂)dσ̂ = dΩ_χ/4: total π). So |v′|² is uniform on
// [(|c| − R)², (|c| + R)²], the speed s = |v′| has the density s/(2|c|R) there, and every gain the grid needs is
// Σ_p W_p ∫ N_m(s) sᵖ ds (p = 0, 1, 2) over that range: the speed density's (W₁ = 1/(2|c|R)) and the l = 1 harmonic's
// (the circle |v′| = s averages v̂·v′ to (v̂·ĉ)(s² + |c|² − R²)/(2|c|)). Piecewise polynomials, integrated exactly — where a rule of 30
// folded σ̂ directions would sample a cubic spline across ~10 knot intervals.
// How: the range's integral is F_m(s_hi) − F_m(s_lo), F_m(s) = Σ_p W_p ∫₀ˢ N_m(σ)σᵖ dσ. At a speed s = h(q + t) in knot
// interval q, F_m is the whole of every spline that ends below q (m < q), a polynomial in t for the four nonzero there
// (m = q … q + 3; its t⁰ term their parts below q), 0 above. So each end adds its weights times tⁿ to interval q's
// power sums, and finish() turns those into the splines' gains once per speed u, with the polynomials' coefficients
// tabulated once per grid size. Against evaluating the moment polynomials at both ends of each collision: the same
// numbers to rounding (tests/theory/test_sphere_gain.cpp), v1 Fig. 7's judged level 6.4 s of CPU instead of 7.4 s
// (means of three runs, one thread; the assembly is ~60% of it).
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace granmix::theory {

class SphereGain {
 public:
  // nb splines N_m(s) = spline(s/h − m + 3) (speed_grid.cpp), m = 0 … nb − 1.
  SphereGain(std::size_t nb, double h);
  SphereGain(const SphereGain&) = delete;  // sums_ points into storage_
  SphereGain& operator=(const SphereGain&) = delete;
  void clear();
  // Adds Σ_p W[p] ∫ N_m(s) sᵖ ds over s ∈ [s_lo, s_hi]; beyond the last spline's support the gain leaves the grid.
  void add_range(double s_lo, double s_hi, const std::array<double, 3>& W);
  // Adds weight · N_m(s): a collision whose sphere is a point (R or |c| ≈ 0).
  void add_point(double s, double weight);
  // The gain into spline m, once every range is added; the caller may subtract its loss in place (clear() starts the
  // next speed).
  std::vector<double>& finish();

  // tⁿ, n = 0 … 6: ∫₀ᵗ τʲ N_e(τ) dτ has degree ≤ j + 4 ≤ 6; n = 0 carries the spline's intervals below the end's.
  static constexpr std::size_t powers = 7;
  // An interval's power sums are stored 8 apart and every end adds all 8 (the 8th, and a low p's top terms, are never
  // read): same-width aligned vector adds, so an end landing in the interval of the one before reads its sums straight
  // from the store buffer (a 7-wide mix of vector and scalar adds stalls there: half of add_end's time, v1 Fig. 7).
  static constexpr std::size_t stride = 8;

 private:
  void add_end(double x, const std::array<double, 3>& a);

  double h_, inv_h_;
  std::size_t nb_;
  std::vector<double> gain_;   // three entries past the last spline: a speed in the last knot interval reaches them
  std::vector<double> storage_;  // sums_ and up to 7 doubles before it: sums_ starts a 64-byte line
  double* sums_;                 // [p][q][n], n < stride: Σ over the ends in interval q of ±h^(p+1) W_p tⁿ
  std::array<bool, 3> used_{};  // the powers p added since clear()
  struct Terms {
    std::vector<double> interval;              // [p][q][e][n]: F of spline q + e at t in interval q = Σ_n interval tⁿ
    std::vector<std::array<double, 3>> whole;  // [m][p]: ∫₀^∞ N_m(s) (s/h)ᵖ d(s/h), the spline wholly passed
  };
  static const Terms& terms(std::size_t nb);
  const Terms& terms_;
};

// add_range and add_end are inline: the speed grid's innermost loop calls them, twice per gas node and speed.
// One end x = s/h of a range, a_p = ±h^(p+1) W_p: interval q's power sums (n ≤ p + 4 reach the splines).
inline void SphereGain::add_end(double x, const std::array<double, 3>& a) {
  const std::size_t q = std::min(std::size_t(x), nb_ - 1);
  const double t = x - double(q);
  const double t2 = t * t, t4 = t2 * t2;
  alignas(64) const double tn[stride] = {1.0, t, t2, t2 * t, t4, t4 * t, t4 * t2, t4 * t2 * t};
  for (std::size_t p = 0; p < 3; ++p) {
    if (a[p] == 0.0) continue;
    double* s = static_cast<double*>(__builtin_assume_aligned(sums_ + (p * nb_ + q) * stride, 64));
    for (std::size_t n = 0; n < stride; ++n) s[n] += a[p] * tn[n];
  }
}

inline void SphereGain::add_range(double s_lo, double s_hi, const std::array<double, 3>& W) {
  const double x_lo = s_lo * inv_h_, x_hi = std::min(s_hi * inv_h_, double(nb_));  // beyond: only the dropped entries
  if (x_lo >= x_hi) return;
  const std::array<double, 3> a = {h_ * W[0], h_ * h_ * W[1], h_ * h_ * h_ * W[2]};
  for (std::size_t p = 0; p < 3; ++p) used_[p] = used_[p] || a[p] != 0.0;
  add_end(x_hi, a);
  add_end(x_lo, {-a[0], -a[1], -a[2]});
}

}  // namespace granmix::theory
