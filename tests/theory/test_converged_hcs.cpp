// The mixture's HCS without the Sonine truncation of its own distributions (theory/grid/converged_hcs.hpp): an exact limit
// (elastic: equal temperatures, Maxwellian), the tracer limit's intruder solved by the other code path
// (tracer_temperature.hpp, ζ given instead of found), and MG Figs. 4–5's DSMC.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "theory/grid/converged_hcs.hpp"
#include "theory/grid/converged_hcs_diffusion.hpp"
#include "theory/grid/partner_axial_shape.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/grid/speed_grid.hpp"
#include "theory/grid/tracer_temperature.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;

namespace {

CollisionRates mg(double mu, double delta, double alpha) {
  return CollisionRates(model::montanero_garzo_binary(mu, delta, 1.0, 0.0), model::Restitution::constant(2, alpha), model::dilute_contact_values(2));
}

// The settled D_k/D_1 of the converged tracer problem (kinetic-converged's D) at a converged HCS state, written out
// here independently of the level kinetic-converged-hcs: its T_k, a₂, a₃ as the species' and partners' shapes, its ζ
// (code units at its T). basis: the tracer problem's own truncation of each ratio, |D(size) − D(size − 1)|/D of
// species k and of species 1, summed.
// full: every species' solved density as its partners' shape and its own source (partner_axial_shape.hpp).
std::vector<double> d_ratios_at(const CollisionRates& r, const SettledHcs& c, std::vector<double>* basis = nullptr, bool full = false) {
  GalerkinOptions opt;
  opt.zeta = c.zeta;
  std::vector<double> a2;
  for (double ck : c.hcs.c) a2.push_back(0.5 * ck);
  opt.a2 = a2.data(), opt.a3 = c.hcs.a3.data();
  std::vector<AxialShape> shapes;
  for (std::size_t k = 0; full && k < r.size(); ++k) shapes.emplace_back(c.density[k], c.hcs.T[k] / r.mixture()[k].mass);
  if (full) opt.full = &shapes;
  std::vector<ConvergedDiffusion> d;
  for (std::size_t k = 0; k < r.size(); ++k) d.push_back(converged_tracer_diffusion(r, k, c.hcs.T.data(), opt));
  std::vector<double> ratios;
  if (basis != nullptr) basis->clear();
  for (std::size_t k = 0; k < r.size(); ++k) {
    ratios.push_back(d[k].D / d[0].D);
    if (basis != nullptr) basis->push_back(converged_diffusion_change(d[k]) + converged_diffusion_change(d[0]));
  }
  return ratios;
}
double d_ratio_at(const CollisionRates& r, const SettledHcs& c) { return d_ratios_at(r, c)[1]; }

// The largest relative change of a ratio D_k/D_1 (k > 1) from `to` to `from`.
double largest_change(const std::vector<double>& from, const std::vector<double>& to) {
  double worst = 0.0;
  for (std::size_t k = 1; k < to.size(); ++k) worst = std::max(worst, std::abs(from[k] / to[k] - 1.0));
  return worst;
}

// The four parts of the D ratios' model error (converged_hcs_diffusion.hpp), transcribed here from their definitions,
// each the largest over the species k > 1: the HCS grid's (twice the largest change with knots 3/2 apart, the
// 16-point rule or the domain 9/7 as wide), the HCS partners' truncation (partners through their full densities), the
// tracer problem's partners' (its partners and source through the solved densities), its basis (one function fewer,
// species k and 1 summed). c: converged_hcs(r, true).
struct RatioErrorParts {
  std::vector<double> d;
  double grid = 0.0, hcs_partners = 0.0, partners = 0.0, basis = 0.0;
};
RatioErrorParts ratio_error_parts(const CollisionRates& r, const ConvergedHcs& c) {
  RatioErrorParts p;
  std::vector<double> basis;
  p.d = d_ratios_at(r, c, &basis);
  for (const SettledHcs& v : c.grid_variants) p.grid = std::max(p.grid, 2.0 * largest_change(d_ratios_at(r, v), p.d));
  p.hcs_partners = largest_change(d_ratios_at(r, c.partners_full), p.d);
  p.partners = largest_change(d_ratios_at(r, c, nullptr, true), p.d);
  p.basis = *std::max_element(basis.begin() + 1, basis.end());
  return p;
}

}  // namespace

TEST_CASE("converged HCS: an elastic mixture settles at equal temperatures, Maxwellian", "[theory]") {
  // Detailed balance for any masses and sizes: a momentum transfer with the masses swapped (β of the wrong species)
  // or a partner at the wrong temperature misses by O(1). What the grid leaves (the spline Maxwellian is not exact;
  // ζ, found from the temperature, absorbs it) must lie within the solver's own grid estimate.
  const ConvergedHcs c = converged_hcs(mg(4.0, 0.25, 1.0), true);
  std::printf("elastic MG mixture mu 4, delta 0.25: gamma - 1 = %.1e (grid estimate %.1e), c %.1e %.1e, a3 %.1e %.1e, zeta* %.1e\n", c.hcs.gamma() - 1.0,
              c.grid_change.T, c.hcs.c[0], c.hcs.c[1], c.hcs.a3[0], c.hcs.a3[1], c.hcs.zeta_star);
  CHECK(std::abs(c.hcs.gamma() - 1.0) < c.grid_change.T);
  CHECK(c.grid_change.T < 1e-4);
  // Maxwellian densities leave no rest beyond the Sonine shape but the grid's own error: the partners' truncation lies
  // within the grid estimate (measured 3.6e-6 against 6.2e-5; a rest built at the wrong temperature or normalisation
  // moves γ by O(1e-2)).
  std::printf("elastic: partners' truncation of gamma %.1e\n", c.partner_truncation.T);
  CHECK(c.partner_truncation.T < c.grid_change.T);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(std::abs(c.hcs.c[k]) < 3e-4);  // c ≈ 0.2 at α = 0.3
    CHECK(std::abs(c.hcs.a3[k]) < 1e-4);
  }
  CHECK(std::abs(c.hcs.zeta_star) < 1e-4);  // ζ* ≈ 0.9 at α = 0.5
}

TEST_CASE("converged distributions: an elastic mixture's Phi is the Maxwellian at every speed, to the grid's error", "[theory]") {
  // MG Figs. 3, 7's mixture (μ = 4, δ = 1/2) elastic: Φ_k(v*) = (λ_k/π)^(3/2) exp(−λ_k v*²) exactly. The solved density's
  // pointwise error (converged_distribution: w_z by panels cut at the integrand's kinks), species
  // 1 / 2: ≤ 2.1e-4 / 2.4e-4 from 0.05 to 0.2 thermal widths, ≤ 9.1e-5 / 9.0e-5 from 0.2 to one width, ≤ 6.7e-6 /
  // 1.3e-5 from one to two, ≤ 1.7e-4 from two to 5.5 (the knots' and the domain's, the same with any rule). The
  // 256-point Gauss–Hermite rule (1.4% / 5.3%, 6.8e-4 / 2.4e-3, 8.5e-5 / 3.0e-4) fails the first three
  // ranges, the 64-point one (13.7% / 75% over MG Fig. 3's first bin) every one; the panels cut at the sphere's pass
  // through 0 alone (1.9e-3 / 5.2e-3 in the first) fail it too. A density read at the wrong v₀ (2% off) or with the
  // wrong normalisation misses by several % at two widths.
  const SettledHcs d = converged_distribution(mg(4.0, 0.5, 1.0), DistributionVariant::solved);
  for (std::size_t k = 0; k < 2; ++k) {
    const double lambda = d.hcs.lambda[k], width = 1.0 / std::sqrt(2.0 * lambda);
    double lowest = 0.0, low = 0.0, near = 0.0, far = 0.0;
    for (double x = 0.05; x < 5.5; x += 0.01) {
      const double e = std::abs(d.density[k].phi(x * width) / maxwellian_phi(lambda, x * width) - 1.0);
      double& range = x < 0.2 ? lowest : x < 1.0 ? low : x < 2.0 ? near : far;
      range = std::max(range, e);
    }
    std::printf("elastic MG mixture, species %zu: Phi against the Maxwellian %.2e (0.05-0.2 widths), %.2e (0.2-1), %.2e (1-2), "
                "%.2e (2-5.5)\n", k + 1, lowest, low, near, far);
    CHECK(lowest < 1e-3);
    CHECK(low < 3e-4);
    CHECK(near < 5e-5);
    CHECK(far < 3e-4);
  }
}

TEST_CASE("converged distributions: the densities fall smoothly (the drift's outflow term at the grid's edge)", "[theory]") {
  // MG Fig. 7's mixture at α = 0.3 and 0.5. Without the outflow term species 1's stationary density alternates in sign
  // from ~3.5 thermal widths on (P(v*) = −0.28 at 1.5, +1.26 at 2.5, where the Maxwellian is 0.07 and 5e-7) while its
  // moments are right. With it P > 0 up to 5.5 widths (min P/v*² ≥ 6.9e-5 measured) and Φ falls by at least
  // 2.7% per twentieth of a width from half a width to five (measured: ≤ 0.973 per step).
  for (double alpha : {0.3, 0.5}) {
    const SettledHcs d = converged_distribution(mg(4.0, 0.5, alpha), DistributionVariant::solved);
    for (std::size_t k = 0; k < 2; ++k) {
      const double width = 1.0 / std::sqrt(2.0 * d.hcs.lambda[k]);
      INFO("alpha = " << alpha << ", species " << k + 1);
      for (double x = 0.05; x < 5.5; x += 0.05) CHECK(speed_density_at(d.density[k].h, d.density[k].P, x * width) > 0.0);
      for (double x = 0.5; x < 5.0; x += 0.05) CHECK(d.density[k].phi((x + 0.05) * width) < d.density[k].phi(x * width));
    }
  }
}

TEST_CASE("converged HCS: the partners' truncation, computed with their full densities (v1 Fig. 4, n2 = 0.01, 0.03)", "[theory]") {
  // partner_truncation is the change when every partner is seen through its full solved density (its rest beyond
  // 1 + a₂S₂ + a₃S₃ as point masses) instead of a₂, a₃. Reference: a separate prototype that solves the
  // main HCS itself with full partners — its own spline evaluation, rests from the densities at 4 Gauss points per knot
  // interval, settled to 1e-7 — gives T₂/T₁ 169.3503 → 166.9747 (−1.403%) at n₂ = 0.01 and 78.3191 → 78.1925 (−0.162%)
  // at 0.03. The check's variant settles to ~1% of its change, so 3% here; the cruder estimate (partners through a₂
  // alone: 3.15%, 0.42%) and no rest at all (0) both fail.
  for (const auto& [n2, want] : {std::pair{0.01, 0.01403}, std::pair{0.03, 0.00162}}) {
    const ConvergedHcs c = converged_hcs(test::constant_rates({{1.0, 1.0, 0.1}, {100.0, 1.0, n2}}, 0.5), true);
    std::printf("v1 Fig. 4, n2 = %g: partners' truncation of T2/T1 %.4f%% (prototype %.4f%%)\n", n2, 100.0 * c.partner_truncation.T, 100.0 * want);
    CHECK(c.partner_truncation.T == Approx(want).epsilon(0.03));
  }
}

TEST_CASE("converged HCS: a rare species is the tracer limit's intruder in the converged gas", "[theory]") {
  // n₂/n₁ = 1e-8: the intruder's effect on the gas is ~1e-8. The tracer code solves the intruder in a gas of the shape
  // and cooling rate this solver found (ζ given, θ the result); the mixture solver found ζ from the equal-rates
  // condition. They share the grid's assembly, not the self-consistency, normalisation or MG units: a wrong ζ*
  // conversion, a mixed-up species or partner temperature moves θ by far more than 1e-5.
  const CollisionRates r = test::constant_rates({{1.0, 1.0, 0.1}, {4.0, std::cbrt(4.0), 1e-9}}, 0.7);
  const ConvergedHcs c = converged_hcs(r);
  const model::Mixture& mix = r.mixture();
  const double m1 = mix[0].mass, m2 = mix[1].mass, v0sq = 2.0 * (m1 + m2) / (m1 * m2);
  // ζ* back to code units at T₁ = 1: ζ(⟨T⟩ = 1) = ζ* n σ₁₂² v0, and ζ ∝ √T.
  const double zeta1 = c.hcs.zeta_star * mix.total_density() * std::pow(mix.sigma(0, 1), 2) * std::sqrt(v0sq) / std::sqrt(c.hcs.T[0]);
  const double theta = c.hcs.T[1] / c.hcs.T[0];
  const TracerTemperature t = converged_tracer_temperature(r, zeta1, {1.0, 0.5 * c.hcs.c[0], c.hcs.a3[0]}, theta);
  std::printf("rare species m2 = 4, eps = 0.7: mixture solver theta = %.8f, tracer solver %.8f; a2 %.6f / %.6f; gas a2 %.6f\n", theta, t.theta,
              0.5 * c.hcs.c[1], t.a2, 0.5 * c.hcs.c[0]);
  CHECK(std::abs(t.theta / theta - 1.0) < 1e-5);
  CHECK(std::abs(t.a2 - 0.5 * c.hcs.c[1]) < 1e-5);
  CHECK(std::abs(t.a3 - c.hcs.a3[1]) < 1e-5);
}

TEST_CASE("converged HCS: MG gamma within 0.3% of DSMC at all 18 points of Figs. 4-5", "[theory][slow]") {
  // DSMC: the mean of the paper-fidelity runs, seeds 1–3, of mg-fig04-mu* and mg-fig05-delta* (2e4 particles x 64
  // replicas each; docs/validation.md; σ of the mean ≈ 0.1%), as scripts/mg_gamma_sonine_orders.py holds them.
  // The first Sonine (MG App. A) is within 0.3% at 15 of the 18 (worst −0.43%, μ = 4, δ = 0.25, α = 0.5), orders 3 and 4
  // at 15 and 17; the target is 0.3% at every point. (~17 s: [slow], not under the sanitizers.)
  struct Point {
    double mu, delta, gamma[3];
  };
  const Point points[] = {{2, 2, {1.53621, 1.34396, 1.11925}},      {10, 2, {5.31174, 3.79934, 1.94476}}, {0.1, 2, {0.12653, 0.18872, 0.45708}},
                          {4, 0.25, {3.45248, 2.38897, 1.35309}}, {4, 1, {2.69027, 2.05299, 1.32944}},   {4, 4, {2.36696, 1.88790, 1.30998}}};
  const double alphas[3] = {0.3, 0.5, 0.8};
  double worst = 0.0, worst_sonine = 0.0;
  for (const Point& p : points)
    for (int a = 0; a < 3; ++a) {
      const CollisionRates r = mg(p.mu, p.delta, alphas[a]);
      const double sonine = sonine_hcs(r.mixture(), r.law(), r.contact_values()).gamma() / p.gamma[a] - 1.0;
      const ConvergedHcs c = converged_hcs(r);
      const double gap = c.hcs.gamma() / p.gamma[a] - 1.0;
      std::printf("MG mu %g delta %g alpha %g: DSMC gamma %.5f, first Sonine %+.3f%%, converged %+.3f%% (%d passes)\n", p.mu, p.delta, alphas[a],
                  p.gamma[a], 100.0 * sonine, 100.0 * gap, c.passes);
      worst = std::max(worst, std::abs(gap)), worst_sonine = std::max(worst_sonine, std::abs(sonine));
      CHECK(std::abs(gap) < 0.003);
    }
  std::printf("MG Figs. 4-5, 18 points: converged HCS within %.3f%% of DSMC, first Sonine within %.3f%%\n", 100.0 * worst, 100.0 * worst_sonine);
}

namespace {

// The fixed `relative` of an MG scene is its level's largest computed model error over the DSMC points, rounded up to
// two digits: it must cover the live computation and be no more than 10% above it. A change to the level that moves its
// computed error beyond either side fails here, and the scene's number is then rewritten after review.
model::Scene mg_scene(const std::string& name) { return theory::load_scene(std::string(GRANMIX_SOURCE_DIR) + "/compare/scenes/" + name + ".toml"); }

void check_fixed_tolerance(const model::Scene& s, const char* quantity, double computed) {
  const auto q = std::find_if(s.compare.begin(), s.compare.end(), [&](const model::CompareQuantity& c) { return c.name == quantity; });
  REQUIRE(q != s.compare.end());
  INFO(s.name << " " << quantity << ": relative " << q->relative << ", computed " << computed);
  CHECK(q->correction_from.empty());
  CHECK(q->error_column.empty());
  CHECK(q->relative >= computed);
  CHECK(q->relative <= 1.1 * computed);
}

}  // namespace

TEST_CASE("converged HCS: the MG scenes' fixed tolerances are their computed model errors", "[theory][slow]") {
  // At every DSMC point (the scene's [dsmc] at) of the scenes judged at the level kinetic-hcs-converged, the two
  // computed parts of γ's and c's model error (converged_hcs.hpp): the grid's (twice the largest change with knots 3/2
  // apart, the 16-point rule or the domain 9/7 as wide) and the partners' truncation (full partners against a₂, a₃).
  // A scene's `relative` is the largest sum over its points (compare/scenes/mg-fig0[2456]*.toml).
  struct Scene {
    const char* name;
    const char* quantity;
    double mu, delta;
  };
  const Scene scenes[] = {{"mg-fig02", "c", 2, 1},           {"mg-fig04-mu0.1", "gamma", 0.1, 2},  {"mg-fig04-mu2", "gamma", 2, 2},
                          {"mg-fig04-mu10", "gamma", 10, 2}, {"mg-fig05-delta0.25", "gamma", 4, 0.25}, {"mg-fig05-delta1", "gamma", 4, 1},
                          {"mg-fig05-delta4", "gamma", 4, 4}};
  for (const Scene& sc : scenes) {
    const model::Scene s = mg_scene(sc.name);
    const model::Mixture m = model::montanero_garzo_binary(sc.mu, sc.delta, 1.0, 0.0);
    for (std::size_t k = 0; k < 2; ++k) {  // the scene is the mixture named here
      CHECK(s.mixture[k].mass / s.mixture[0].mass == Approx(m[k].mass / m[0].mass).epsilon(1e-12));
      CHECK(s.mixture[k].diameter / s.mixture[0].diameter == Approx(m[k].diameter / m[0].diameter).epsilon(1e-12));
    }
    REQUIRE(s.dsmc.at.size() == 3);
    double error = 0.0;
    for (double alpha : s.dsmc.at) {
      const ConvergedHcs c = converged_hcs(mg(sc.mu, sc.delta, alpha), true);
      error = std::max(error, std::string(sc.quantity) == "c" ? c.grid_change.a2 + c.partner_truncation.a2 : c.grid_change.T + c.partner_truncation.T);
    }
    check_fixed_tolerance(s, sc.quantity, error);
  }
  // MG Fig. 6 (μ = 2, δ = 1/2, w = 2; Enskog χ of MG Eq. 26): γ(n*)/γ(0), whose model error is the sum of both γ's
  // (their parts need not cancel), at the DSMC points n*.
  for (const char* name : {"mg-fig06-alpha0.6", "mg-fig06-alpha0.8"}) {
    const model::Scene s = mg_scene(name);
    const double alpha = s.restitution.eps(0, 0);
    const auto error_at = [alpha](double n_star) {
      const model::Mixture mix = model::montanero_garzo_binary(2.0, 0.5, 2.0, n_star);
      const auto chi = n_star > 0.0 ? model::enskog_contact_values(mix) : model::dilute_contact_values(2);
      const ConvergedHcs c = converged_hcs(CollisionRates(mix, model::Restitution::constant(2, alpha), chi), true);
      return c.grid_change.T + c.partner_truncation.T;
    };
    const double dilute = error_at(0.0);
    double ratio_error = 0.0;
    for (double n_star : s.dsmc.at) ratio_error = std::max(ratio_error, dilute + error_at(n_star));
    check_fixed_tolerance(s, "gamma_ratio", ratio_error);
  }
}

TEST_CASE("kinetic-converged-hcs: kinetic-converged's D ratio where the Sonine HCS is converged already, at the converged HCS", "[theory][slow]") {
  // v1 Fig. 4 (m = 1, 100; σ = 1, 1; n₁ = 0.1; ε = 0.5) at n₂ = 0.1, 0.3: the converged HCS's T₂/T₁ is within 0.1% of
  // the first Sonine's and its partners' truncation 1.4e-4, 2.1e-4, so the level's D₂/D₁ must come back to
  // kinetic-converged's within 0.3% (measured 0.08%, 0.10%); and everywhere it is the D of this file's own transcription
  // (d_ratio_at) at converged_hcs's state: a ζ in the wrong units, a species' shape in the wrong slot, the Sonine state
  // left in, move either by far more. Printed: n₂ = 0.01 (−2.8% from kinetic-converged; DSMC's increments 2.4–3.6% below
  // it) and v1 Fig. 5 (σ₂ = 100^(1/3), n₂ = 0.1) at ε = 0.2, 0.5, 0.8 against quick seed 1's DSMC 0.3641(19),
  // 0.2521(14), 0.1464(9) (kinetic-converged: 0.3752, 0.2545, 0.1483).
  const auto sonine = make_theory_level("kinetic-converged"), converged = make_theory_level("kinetic-converged-hcs");
  auto compare = [&](const CollisionRates& r, const std::string& what) {
    const double d = sonine->diffusion_at(r, sonine->settled_temperatures(r)).D_ratio[1];
    const double dc = converged->diffusion_at(r, converged->settled_temperatures(r)).D_ratio[1];
    const ConvergedHcs c = converged_hcs(r, true);
    std::printf("%s: D2/D1 kinetic-converged %.5f, kinetic-converged-hcs %.5f (%+.2f%%; T ratio %.4f, partners' truncation %.1e)\n", what.c_str(), d,
                dc, 100.0 * (dc / d - 1.0), c.hcs.T[1] / c.hcs.T[0], c.partner_truncation.T);
    CHECK(std::abs(dc / d_ratio_at(r, c) - 1.0) < 1e-9);
    // Its model error (converged_hcs_diffusion.hpp, theory.tsv's D_ratio_error): the four parts as transcribed here.
    const RatioErrorParts p = ratio_error_parts(r, c);
    const ConvergedRatioError e = converged_d_ratio_error(r, c);
    CHECK(e.grid[1] == Approx(p.grid).epsilon(1e-6).margin(1e-12));
    CHECK(e.hcs_partners[1] == Approx(p.hcs_partners).epsilon(1e-6).margin(1e-12));
    CHECK(e.partners[1] == Approx(p.partners).epsilon(1e-6).margin(1e-12));
    CHECK(e.basis[1] == Approx(p.basis).epsilon(1e-6).margin(1e-12));
    CHECK(e.total()[0] == 0.0);
    return std::tuple{dc / d - 1.0, c.partner_truncation.T, c};
  };
  for (const double n2 : {0.1, 0.3}) {
    const auto [shift, truncation, c] = compare(test::constant_rates({{1.0, 1.0, 0.1}, {100.0, 1.0, n2}}, 0.5), "v1 Fig. 4, n2 = " + std::to_string(n2).substr(0, 3));
    CHECK(truncation < 3e-4);
    CHECK(std::abs(shift) < 3e-3);
  }
  compare(test::constant_rates({{1.0, 1.0, 0.1}, {100.0, 1.0, 0.01}}, 0.5), "v1 Fig. 4, n2 = 0.01");
  for (const double eps : {0.2, 0.5, 0.8})
    compare(test::constant_rates({{1.0, 1.0, 0.1}, {100.0, std::cbrt(100.0), 0.1}}, eps), "v1 Fig. 5, eps = " + std::to_string(eps).substr(0, 3));
  // The level hands the same error on (its own checked state): bo1-fig05's ε = 0.2, 0.40% (the largest of its points).
  const CollisionRates r = test::constant_rates({{1.0, 1.0, 0.1}, {100.0, std::cbrt(100.0), 0.1}}, 0.2);
  const RatioErrorParts p = ratio_error_parts(r, converged_hcs(r, true));
  CHECK(converged->d_ratio_error(r)[1] == Approx(p.grid + p.hcs_partners + p.partners + p.basis).epsilon(1e-6));
  CHECK_THROWS_AS(sonine->d_ratio_error(r), std::logic_error);  // kinetic-converged computes none
}

TEST_CASE("converged HCS at v1 Fig. 4's n2 = 0.01: its grid estimate covers a wider domain's gamma and c1 (regression pins)",
          "[theory][regression]") {
  // The grid estimate covers the domain's truncation. At n₂ = 0.01 the light species' tail is strongly overpopulated
  // (a₃ = −0.61): this solver with its domain 10 widths wide instead of 7 (knots as far apart;
  // 8 and 9 widths: γ 0.0059021, 0.0059007) gives γ = 0.00590042 and c₁ = 1.01231, 7.5e-4 and 1.8% from the solve's;
  // from knots 3/2 apart and the 16-point rule alone the estimate would be 9.3e-5 and 0.30%: 8× and 6× short.
  // Its D₂/D₁ moves by 2e-5 only. The wider solve's numbers are the code's own (the domain is no setting of
  // converged_hcs): pins, which move when the solver does.
  const ConvergedHcs c = converged_hcs(test::constant_rates({{1.0, 1.0, 0.1}, {100.0, 1.0, 0.01}}, 0.5), true);
  std::printf("v1 Fig. 4, n2 = 0.01: gamma %.8f, c1 %.6f; grid estimate: T %.2e, c %.2e\n", c.hcs.gamma(), c.hcs.c[0], c.grid_change.T, c.grid_change.a2);
  CHECK(c.grid_change.T > std::abs(c.hcs.gamma() / 0.00590042 - 1.0));
  CHECK(c.grid_change.a2 > std::abs(c.hcs.c[0] / 1.01231 - 1.0));
}

TEST_CASE("kinetic-converged-hcs: the model error parts of the D-ratio scenes' tolerances", "[.tolerances]") {
  // Not run by ctest: `granmix_tests_theory "[.tolerances]"` prints, at the DSMC points of the D-ratio scenes judged at
  // the level kinetic-converged-hcs, the computed parts of their D_k/D_1's model error, as relative changes of the
  // settled ratio (the judged increments come from the same memory), the largest over the species k > 1: the HCS grid's
  // (twice the largest change with knots 3/2 apart, the 16-point rule or the domain 9/7 as wide), the HCS partners'
  // truncation (partners through their full densities), the tracer problem's partners' (its partners and source
  // through the solved densities), its basis (one function fewer, species k and 1 summed). The scenes judge with the sum per point and species, which the
  // level computes itself (theory.tsv column D_ratio_error, error_column); this prints the parts behind it. ~30 s.
  auto v1_binary = [](double sigma2, double n2, double eps) { return test::constant_rates({{1.0, 1.0, 0.1}, {100.0, sigma2, n2}}, eps); };
  auto v1_fig07 = [](double eps) {
    return test::constant_rates({{1.0, 1.0, 0.1}, {2.0, std::cbrt(2.0), 0.1}, {3.0, std::cbrt(3.0), 0.1}, {4.0, std::cbrt(4.0), 0.1}}, eps);
  };
  struct Scene {
    const char* name;
    std::function<CollisionRates(double)> rates;
    double at[3];
  };
  const double same = std::cbrt(100.0);
  const Scene scenes[] = {{"bo1-fig05", [&](double eps) { return v1_binary(same, 0.1, eps); }, {0.2, 0.5, 0.8}},
                          {"bo1-fig05-equal-sizes", [&](double eps) { return v1_binary(1.0, 0.1, eps); }, {0.2, 0.5, 0.8}},
                          {"bo1-fig04", [&](double n2) { return v1_binary(1.0, n2, 0.5); }, {0.01, 0.1, 0.3}},
                          {"bo1-fig04-same-material", [&](double n2) { return v1_binary(same, n2, 0.5); }, {1e-3, 1e-2, 0.1}},
                          {"bo1-fig07", v1_fig07, {0.2, 0.5, 0.8}}};
  for (const Scene& s : scenes) {
    double largest = 0.0;
    for (const double x : s.at) {
      const CollisionRates r = s.rates(x);
      const RatioErrorParts p = ratio_error_parts(r, converged_hcs(r, true));
      std::printf("%s at %g: D_k/D_1", s.name, x);
      for (std::size_t k = 1; k < p.d.size(); ++k) std::printf(" %.5f", p.d[k]);
      std::printf(", model error parts: HCS grid %.1e, HCS partners %.1e, D's partners %.1e, basis %.1e\n", p.grid, p.hcs_partners, p.partners, p.basis);
      largest = std::max(largest, p.grid + p.hcs_partners + p.partners + p.basis);
    }
    std::printf("%s: largest model error of D_k/D_1 %.2e\n", s.name, largest);
  }
}
