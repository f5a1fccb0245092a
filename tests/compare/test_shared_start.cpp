// Guard for a part theory and DSMC share (docs/reliability.md, "Guards for the parts theory and DSMC share"): a tracer
// scene's start. Were DSMC to start the intruders at the judged level's own θ, a wrong θ in that level would move DSMC's
// start with it, and the comparison could not see it. Both start at the scene's start ratio (tracer_start_theta), and
// the judged level relaxes from there.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "compare/run_cli.hpp"
#include "dsmc/scene_dsmc.hpp"
#include "model/scene.hpp"
#include "theory/grid/tracer_form.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/scene_theory.hpp"

using namespace granmix;

TEST_CASE("bo2-fig05: DSMC's start is the same whichever level is judged, and the judged level starts there too", "[compare]") {
  model::Scene s = theory::load_scene(test::scene_path("bo2-fig05.toml"));
  const theory::CollisionRates rates = theory::scene_rates(s, s.mixture, s.restitution);
  const std::vector<double> T0 = dsmc::plan_scene_dsmc(s, {}).at(0).T0;
  REQUIRE(T0.size() == 2);
  CHECK(T0[0] == 1.0);
  // The scene's start, θ₀ = 493.6: the large-mass closed form θ ≈ (1 − ε²)² M³ σ₁₁⁴/(8(1 + ε)² σ₁₂⁴) (docs/physics.md §4),
  // written out here from the scene's parameters (the scene rounds it to four digits).
  const double M = s.mixture[1].mass / s.mixture[0].mass, eps = s.restitution.eps(0, 0), s11 = s.mixture[0].diameter;
  const double s12 = 0.5 * (s.mixture[0].diameter + s.mixture[1].diameter);
  CHECK(T0[1] == Approx(std::pow(1.0 - eps * eps, 2) * M * M * M * std::pow(s11, 4) / (8.0 * std::pow(1.0 + eps, 2) * std::pow(s12, 4))).epsilon(1e-4));
  // Levels whose stationary θ differ by far more than 2% (paper 412.9, kinetic 504.6, kinetic-converged 579.74): as
  // good as a planted error in the judged level's θ. Judging each in turn leaves DSMC's start bit for bit.
  double lo = 1e300, hi = 0.0;
  for (const char* level : {"paper", "kinetic", "kinetic-converged"}) {
    s.theory.level = level;
    const double theta = theory::make_theory_level(level)->tracer(rates).theta;
    lo = std::min(lo, theta), hi = std::max(hi, theta);
    INFO(level << ": its theta " << theta << ", DSMC's start " << dsmc::plan_scene_dsmc(s, {}).at(0).T0[1]);
    CHECK(dsmc::plan_scene_dsmc(s, {}).at(0).T0 == T0);
  }
  CHECK(hi / lo > 1.02);
  // The judged level and its companion start where DSMC does: T₂/T₁ = T0[1] at t → 0, ballistic MSD 3θ₀/m₂ t².
  for (const char* level : {"kinetic-converged", "kinetic-converged-reshaped"}) {
    const auto form = theory::make_theory_level(level)->tracer_form(rates, T0[1], 10.0);
    const double t = 1e-4, m2 = rates.mixture()[1].mass;
    const std::array<double, 2> T = form->temperatures(t);
    INFO(level);
    CHECK(T[0] == Approx(1.0).epsilon(1e-4));
    CHECK(T[1] / T[0] == Approx(T0[1]).epsilon(1e-5));
    CHECK(form->msd(1, t) == Approx(3.0 * T0[1] / m2 * t * t).epsilon(1e-4));
  }
}
