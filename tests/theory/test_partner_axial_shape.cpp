// A species' full density as the tracer problem sees it (theory/grid/partner_axial_shape.hpp): on a density of known
// Sonine shape it must give back the Sonine forms the tracer problem uses without it — E[f/f_M | c_z] = 1 + a₂S₂ᵃˣ(y)
// + a₃S₃ᵃˣ(y), whatever the density's speed scale, and the tracer problem's D ratio of the Sonine shapes. (The source
// r alone differs in its high basis functions, whose x⁶ reaches past the density's 7 widths where the Sonine form
// extends a polynomial tail to infinity: 1–30% of entries ~1e-1; D moves by 5e-7.)
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "theory/grid/converged_hcs_diffusion.hpp"
#include "theory/grid/partner_axial_shape.hpp"
#include "theory/sonine/sonine_polynomials.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/grid/speed_grid.hpp"
#include "theory_fixtures.hpp"

using namespace granmix::theory;

namespace {

// P(v) = 4πv² f_M(v)(1 + a₂S₂(c²) + a₃S₃(c²)) at the temperature `scale` (its own units: v = v₀v*, v₀ arbitrary),
// least-squares on cubic B-splines h apart over 7 thermal widths (the converged HCS's grid), the basis functions
// read through speed_density_at itself.
SpeedDensity sonine_density(double a2, double a3, double scale, double h) {
  const double U = 7.0 * std::sqrt(scale);
  const auto intervals = std::size_t(std::ceil(U / h));
  const Eigen::Index n = Eigen::Index(intervals + 3), samples = Eigen::Index(intervals * 12);
  Eigen::MatrixXd X(samples, n);
  Eigen::VectorXd y(samples);
  for (Eigen::Index s = 0; s < samples; ++s) {
    const double v = (double(s) + 0.5) * double(intervals) * h / double(samples), x = v * v / (2.0 * scale);
    y[s] = 4.0 * std::numbers::pi * v * v * std::exp(-x) / std::pow(2.0 * std::numbers::pi * scale, 1.5) * (1.0 + a2 * sonine_S2(x) + a3 * sonine_S3(x));
    for (Eigen::Index j = 0; j < n; ++j) X(s, j) = speed_density_at(h, Eigen::VectorXd::Unit(n, j), v);
  }
  return {h, X.colPivHouseholderQr().solve(y)};
}

}  // namespace

TEST_CASE("AxialShape: a density of Sonine shape gives back 1 + a2 S2ax + a3 S3ax", "[theory]") {
  // v1 Fig. 4's light species at n₂ = 0.01 has a₂ = 0.50, a₃ = −0.61 (the converged HCS): the largest shapes the D
  // ratios meet. The density in its own units (scale 0.37), the tracer at θ = 2.3; knots 1/16 of a thermal width apart:
  // the least-squares fit's own error (3.5e-5 at 1/8, 2.4e-6 at 1/16: its h⁴) is what is left.
  const double a2 = 0.5, a3 = -0.61, scale = 0.37, theta = 2.3;
  const AxialShape shape(sonine_density(a2, a3, scale, 0.0625 * std::sqrt(scale)), theta);
  double worst = 0.0;
  for (double y = 0.0; y <= 8.0; y += 0.05) {
    const double want = 1.0 + a2 * sonine_axial_S2(y) + a3 * sonine_axial_S3(y);
    // relative to the Maxwellian's marginal weight there: what the pair integrals see
    worst = std::max(worst, std::abs(shape.at(y) - want) * std::exp(-y));
  }
  std::printf("AxialShape of a Sonine density (a2 %.2f, a3 %.2f): largest |E[f/f_M|c_z] - Sonine| e^(-y) %.1e\n", a2, a3, worst);
  CHECK(worst < 1e-5);
  // A wrong a₃ (−0.60) moves the shape by 1e-2·|S₃ᵃˣ| e^(−y) ≥ 1e-3 somewhere: the check discriminates.
  CHECK(std::abs(shape.at(0.0) - (1.0 + a2 * sonine_axial_S2(0.0) - 0.60 * sonine_axial_S3(0.0))) > 1e-3);
  CHECK(shape.at(60.0) == 0.0);  // beyond the grid
}

TEST_CASE("the D ratios' partners' truncation: full densities of Sonine shape give back the Sonine tracer problem", "[theory]") {
  // v1 Fig. 4 at n₂ = 0.01 (m = 1, 100; σ = 1, 1; n₁ = 0.1; ε = 0.5), the converged HCS's state: its densities
  // replaced by ones of exactly its a₂, a₃ (least-squares splines), the tracer problem fed through them
  // (partner_axial_shape.hpp: partners' axial shapes, the species' own source) must give the D₂/D₁ of the Sonine
  // shapes: measured 5e-7 (the splines' fit and the density's domain, 7 widths, which cuts the source's
  // high basis functions' tails and moves D by nothing measurable). With the solved densities themselves it moves by
  // +0.66% (the truncation the level's model error carries; the a₃ term's size, a cruder estimate of it, is 1.47%),
  // so the bound discriminates by four orders.
  const CollisionRates r = granmix::test::constant_rates({{1.0, 1.0, 0.1}, {100.0, 1.0, 0.01}}, 0.5);
  const ConvergedHcs c = converged_hcs(r, false);
  SettledHcs sonine = c;
  for (std::size_t k = 0; k < 2; ++k) sonine.density[k] = sonine_density(0.5 * c.hcs.c[k], c.hcs.a3[k], 1.0 + double(k), 0.125);
  const double d = converged_d_ratios(r, c)[1], full = converged_d_ratios(r, c, nullptr, true)[1];
  const double back = converged_d_ratios(r, sonine, nullptr, true)[1];
  std::printf("v1 Fig. 4, n2 = 0.01: D2/D1 %.7f; through its solved densities %+.3e, through Sonine-shaped densities %+.1e\n", d, full / d - 1.0,
              back / d - 1.0);
  CHECK(std::abs(back / d - 1.0) < 1e-5);
  CHECK(std::abs(full / d - 1.0) > 3e-3);  // the effect the level carries as its partners' truncation
  CHECK(std::abs(full / d - 1.0) < 1e-2);
}
