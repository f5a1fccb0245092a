// The path from a scene file to the theory's inputs, against definitions written here: the Enskog
// contact values a dense scene's rates carry, and MG's time unit. Both enter theory and DSMC alike
// or cancel in the judged ratios, so no theory–DSMC comparison can see an error in them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "model/enskog.hpp"
#include "model/scene.hpp"
#include "theory/rates/collision_rates.hpp"
#include "theory/scene_theory.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;
using std::numbers::pi;

TEST_CASE("a dense scene's theory rates carry the Carnahan-Starling chi: two identical species at n sigma^3 = 0.3, rates = dilute x chi_CS", "[theory]") {
  // The path from a scene to its rates (theory/scene_theory.cpp), against χ written here: for
  // identical species the Enskog contact value is Carnahan–Starling, χ = (1 − φ/2)/(1 − φ)³,
  // φ = π n σ³/6 with the total n (MG Eq. 26 with equal sizes). Every rate of the dense gas is the dilute rate times χ, so a wrong χ
  // anywhere on that path shows here at the size of the error (ratios of rates would hide it).
  const model::Scene s = theory::load_scene_text(R"([scene]
name = "dense-identical-species"
[mixture]
species = [{ mass = 1, diameter = 1, density = 0.05 }, { mass = 1, diameter = 1, density = 0.05 }]
[collisions]
restitution = 0.8
[observables]
gamma = true
[theory]
sweep = { parameter = "n_star", from = 0, to = 0.4, points = 3 }
[time]
times = [50, 100]
)",
                                                "dense-identical-species.toml");
  const model::Scene p = model::sweep_point(s, 0.3);
  REQUIRE(p.enskog);
  REQUIRE((p.mixture[0].density + p.mixture[1].density) * std::pow(p.mixture[0].diameter, 3) == Approx(0.3).epsilon(1e-12));
  const double phi = pi * 0.3 / 6.0, chi_cs = (1.0 - phi / 2.0) / std::pow(1.0 - phi, 3);
  const CollisionRates dense = scene_rates(p, p.mixture, p.restitution);
  const CollisionRates dilute(p.mixture, p.restitution, model::dilute_contact_values(2));
  const double T[] = {1.7, 0.6};  // unequal: the (X − 1) terms take part
  std::printf("identical species, n sigma^3 = 0.3: chi_CS = %.9f, xi ratio = %.9f, 1/tau_v ratio = %.9f\n", chi_cs,
              dense.xi_species(0, T) / dilute.xi_species(0, T), dense.inv_tau_v_species(0, T) / dilute.inv_tau_v_species(0, T));
  CHECK(dense.xi_species(0, T) / dilute.xi_species(0, T) == Approx(chi_cs).epsilon(1e-12));  // a 3% χ error is 3e10 times this bound
  CHECK(dense.inv_tau_v_species(0, T) / dilute.inv_tau_v_species(0, T) == Approx(chi_cs).epsilon(1e-12));
}

TEST_CASE("MG time unit: t0 = lambda11 / v01(0), lambda11 = 1/(sqrt(2) pi n1 sigma11^2), v01 = sqrt(2 T1/m1) - mg-fig01", "[theory]") {
  // docs/physics.md §MG (Montanero & Garzó 2002, Sec. IV): times in units of the mean free time of species 1
  // at the start. mg-fig01 starts at equal temperatures, ⟨T⟩ = 1, so T1(0) = 1.
  const model::Scene s = theory::load_scene(std::string(GRANMIX_SOURCE_DIR) + "/compare/scenes/mg-fig01.toml");
  const model::Species& a = s.mixture[0];
  const double lambda11 = 1.0 / (std::sqrt(2.0) * pi * a.density * a.diameter * a.diameter);
  const double t0 = lambda11 / std::sqrt(2.0 * 1.0 / a.mass);
  std::printf("mg-fig01: n1 = %.9g, sigma11 = %.9g, m1 = %.9g: t0 = %.12g, scene unit = %.12g\n", a.density, a.diameter,
              a.mass, t0, scene_time_unit(s));
  CHECK(scene_time_unit(s) == Approx(t0).epsilon(1e-13));  // a 3% unit error is 3e11 times this bound
}

TEST_CASE("a sweep's points on two threads give the one-thread table, rows in sweep order", "[theory]") {
  // sweep_table runs its points on OpenMP threads, each with a level object of its own (a level keeps a memo); each
  // point is computed wholly on one thread and its rows go in at the point's place, so the table must be the
  // one-thread table bit for bit (granmix's reproducibility rule) with x increasing. The converged level (its memo,
  // its Galerkin pair problems, the increment history with its own pair tables) on a binary, 5 points of ε.
  const model::Scene s = theory::load_scene_text(R"([scene]
name = "sweep-threads"
[mixture]
species = [{ mass = 1, diameter = 1, density = 0.1 }, { mass = 4, diameter = 1.5874, density = 0.1 }]
[collisions]
restitution = 0.5
[observables]
d_ratio = true
gamma = true
[theory]
level = "kinetic-converged"
sweep = { parameter = "eps", from = 0.2, to = 1.0, points = 5 }
[time]
times = [50, 500]
[dsmc]
at = [0.5]
quick = { particles = 1000, replicas = 2 }
paper = { particles = 1000, replicas = 2 }
)",
                                                "sweep-threads.toml");
  auto run = [&] { return run_level(s, "kinetic-converged").table; };
  const model::Table one = test::with_threads(1, run), two = test::with_threads(2, run);
  REQUIRE(one.columns == two.columns);
  REQUIRE(one.rows.size() == two.rows.size());
  std::size_t differ = 0;  // bit for bit, NaN (the empty cells) equal to NaN
  for (std::size_t j = 0; j < one.rows.size(); ++j)
    for (std::size_t c = 0; c < one.columns.size(); ++c)
      differ += std::memcmp(&one.rows[j][c], &two.rows[j][c], sizeof(double)) != 0;
  CHECK(differ == 0);
  REQUIRE(one.rows.size() == 6 * 3);  // 5 points and dsmc.at's 0.5; γ's row (species 0) and one per species at each
  for (std::size_t j = 1; j < one.rows.size(); ++j) CHECK(one.rows[j][0] >= one.rows[j - 1][0]);
  const auto inc = std::find(one.columns.begin(), one.columns.end(), "D_ratio_increment");
  REQUIRE(inc != one.columns.end());
  CHECK(std::isfinite(one.rows[2][std::size_t(inc - one.columns.begin())]));  // species 2's increment ratio at ε = 0.2
}

TEST_CASE("kinetic-converged-hcs's increments carry DSMC's start: a rare heavy species' memory of it", "[theory]") {
  // v1 Fig. 4 same-material at n₂ = 0.001, 0.3. kinetic-converged-hcs's MSD is the closed form from its own settled
  // state; DSMC (and kinetic-converged-cooling3's VACF history) start at the Maxwellian HCS, T₂/T₁ = 82.3 against
  // 89.3, Maxwellian shapes, and at n₂ = 0.001 the heavy grain remembers it over [50, 5000]: the closed form alone
  // is 1.05% above cooling3's history (4.9191 against 4.8677), DSMC (18 + 18 seeds, bo2-fig02's 20) with the history.
  // With the start's effect carried (increment_ratios), the two levels differ by what their settled states do
  // (+0.25%: cooling3's own closed form is 4.9068); at n₂ = 0.3 the memory is short and the effect vanishes.
  const model::Scene s = theory::load_scene_text(R"([scene]
name = "start-memory"
[mixture]
species = [{ mass = 1, diameter = 1, density = 0.1 }, { mass = 100, diameter = 4.641588833612779, density = 0.1 }]
[collisions]
restitution = 0.5
[observables]
d_ratio = true
[theory]
level = "kinetic-converged-hcs"
sweep = { parameter = "density", species = 2, from = 0.001, to = 0.3, points = 2 }
[time]
times = [50, 5000]
[dsmc]
at = [0.001, 0.3]
quick = { particles = 1000, replicas = 2 }
paper = { particles = 1000, replicas = 2 }
)",
                                                "start-memory.toml");
  auto column = [](const model::Table& t, const std::string& name, std::size_t row) {
    const auto c = std::find(t.columns.begin(), t.columns.end(), name);
    REQUIRE(c != t.columns.end());
    return t.rows.at(row)[std::size_t(c - t.columns.begin())];
  };
  const model::Table hcs = run_level(s, "kinetic-converged-hcs").table, cooling3 = run_level(s, "kinetic-converged-cooling3").table;
  REQUIRE(hcs.rows.size() == 4);  // species 1 and 2 at n₂ = 0.001, 0.3
  const double rare = column(hcs, "D_ratio_increment", 1) / column(cooling3, "D_ratio_increment", 1);
  std::printf("n2 = 0.001: increments kinetic-converged-hcs %.5f, kinetic-converged-cooling3 %.5f (%+.2f%%)\n", column(hcs, "D_ratio_increment", 1),
              column(cooling3, "D_ratio_increment", 1), 100.0 * (rare - 1.0));
  CHECK(std::abs(rare - 1.0) < 4e-3);  // 1.05% without the start's effect
  CHECK(column(hcs, "D_ratio_increment", 3) == Approx(column(hcs, "D_ratio", 3)).epsilon(1e-4));
  // The start factor's model error joins D_ratio_error: the same factor by kinetic-converged (first Sonine temperatures
  // in time) against cooling3's, measured 0.16% at n₂ = 0.001 and 6e-6 at n₂ = 0.3, where the memory is short.
  auto start_part = [&](double n2, std::size_t row) {
    const model::Scene p = model::sweep_point(s, n2);
    const CollisionRates rates = scene_rates(p, p.mixture, p.restitution);
    return column(hcs, "D_ratio_error", row) - make_theory_level("kinetic-converged-hcs")->d_ratio_error(rates)[1];
  };
  const double rare_start = start_part(0.001, 1), dense_start = start_part(0.3, 3);
  std::printf("start factor's model error: n2 = 0.001 %.3f%%, n2 = 0.3 %.1e; the whole model error at n2 = 0.001 %.3f%%\n", 100.0 * rare_start,
              dense_start, 100.0 * column(hcs, "D_ratio_error", 1));
  CHECK(rare_start > 1e-3);
  CHECK(rare_start < 3e-3);
  CHECK(std::abs(dense_start) < 1e-4);
  // Both routes to the increments (the closed form with the start's factor, cooling3's history) within that error.
  CHECK(std::abs(rare - 1.0) < column(hcs, "D_ratio_error", 1));
}
