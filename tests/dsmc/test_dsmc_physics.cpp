// The exact event-driven DSMC against exact limits and theory, with fixed seeds. Every statistical
// check states its z bound (4 unless said) and prints its z-scores.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "dsmc/ensemble.hpp"
#include "dsmc_fixtures.hpp"
#include "dsmc/event_loop.hpp"
#include "dsmc/selectors.hpp"
#include "model/enskog.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/histories/initial_state.hpp"
#include "theory/histories/msd.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/histories/temperature_history.hpp"

using namespace granmix;
using namespace granmix::dsmc;
using std::numbers::pi;

namespace {

DsmcSetup setup(std::vector<model::Species> s, double eps, std::vector<std::size_t> counts, std::vector<double> times,
                std::size_t replicas, Method m = Method::automatic) {
  return test::dsmc_setup(std::move(s), eps, std::move(counts), std::move(times), replicas, m);
}

// Collisions per particle of species k with species i up to sample j.
double per_particle(const DsmcResult& r, const DsmcSetup& s, std::size_t j, std::size_t k, std::size_t i, bool err) {
  const std::size_t M = r.species, a = std::min(i, k), b = std::max(i, k);
  const double v = (err ? r.pair_collisions.err : r.pair_collisions.mean)[j * M * M + a * M + b];
  return (i == k ? 2.0 : 1.0) * v / double(s.counts[k]);
}

}  // namespace

TEST_CASE("elastic gas: collision frequency 4 sqrt(pi) n sigma^2 sqrt(T/m) for every selector", "[dsmc]") {
  for (Method m : {Method::direct, Method::lowrank, Method::bird, Method::bird_global}) {
    DsmcSetup s = setup({{1, 1, 0.1}}, 1.0, {10000}, {2.0}, 8, m);
    const DsmcResult r = run_ensemble(s);
    const double nu = 4 * std::sqrt(pi) * 0.1, t = 2.0;
    const double z = (per_particle(r, s, 0, 0, 0, false) / t - nu) / (per_particle(r, s, 0, 0, 0, true) / t);
    std::printf("elastic frequency, %s: z = %.2f; T = %.6f\n", to_string(m), z, r.T.mean[0]);
    CHECK(std::abs(z) < 4);
    CHECK(r.T.mean[0] == Approx(1.0).epsilon(1e-12));  // energy is conserved exactly (rescaled start)
  }
}

TEST_CASE("elastic binary: collisions per species pair against nu_ki", "[dsmc]") {
  // ν_ki = 2√(2π) n_i σ_ki² √(T_k/m_k + T_i/m_i) (docs/physics.md §1).
  const std::vector<model::Species> sp = {{1, 1, 0.1}, {10, 2, 0.05}};
  for (Method m : {Method::direct, Method::lowrank, Method::bird, Method::bird_global}) {
    DsmcSetup s = setup(sp, 1.0, {8000, 4000}, {3.0}, 8, m);
    const DsmcResult r = run_ensemble(s);
    for (std::size_t k = 0; k < 2; ++k)
      for (std::size_t i = 0; i < 2; ++i) {
        const double sig = 0.5 * (sp[k].diameter + sp[i].diameter);
        const double nu = 2 * std::sqrt(2 * pi) * sp[i].density * sig * sig * std::sqrt(1 / sp[k].mass + 1 / sp[i].mass);
        const double z = (per_particle(r, s, 0, k, i, false) / 3.0 - nu) / (per_particle(r, s, 0, k, i, true) / 3.0);
        std::printf("binary frequency %s, %zu-%zu: z = %.2f\n", to_string(m), k + 1, i + 1, z);
        CHECK(std::abs(z) < 4);
      }
  }
}

namespace {

// χ² of the proposed species pairs against the selector's own class weights W_i = Σ_u∈i N_u bound_u
// times N_k σ_ik² (Bird: N_k σ_max², its majorant does not know the pair), and the total rate against
// the same sum written out.
template <class Selector>
void check_pair_proposals(std::size_t classes, const char* name, bool bird = false) {
  const model::Mixture mix({{1, 1, 0.1}, {2, 1.26, 0.08}, {3, 1.44, 0.06}, {4, 1.59, 0.04}, {5, 1.71, 0.02}});
  Rng rng(9, 0);
  const std::vector<std::size_t> counts = {500, 400, 300, 200, 100};
  Particles p = maxwellian_particles(mix, counts, {1, 1, 1, 1, 1}, false, true, rng);
  const PairTable pairs(mix, {}, 1500 / 0.3);  // dilute
  const Selector sel(pairs, p, classes);
  const SpeedClasses& c = sel.classes();
  const int draws = 1000000;
  std::vector<double> hits(25, 0.0), w(25);
  std::size_t outside = 0;
  for (int j = 0; j < draws; ++j) {
    const Proposal q = sel.propose(rng, p);
    hits[q.i * 5 + q.k] += 1;
    outside += q.a < p.begin(q.i) || q.a >= p.end(q.i) || q.b < p.begin(q.k) || q.b >= p.end(q.k);
    // The acceptance weight·|g|/scale is σ_ik²|g| / (σ_max² (bound_a + bound_b)) for Bird, |g|/(bound_a + bound_b) otherwise.
    if (j < 1000) CHECK(q.weight / q.scale == Approx((bird ? pairs.sigma2(q.i, q.k) / pairs.sigma2_max : 1.0) /
                                                       (c.bound(c.unit_of(q.a, q.i)) + c.bound(c.unit_of(q.b, q.k)))).epsilon(1e-14));
  }
  CHECK(outside == 0);
  double total = 0.0;
  for (std::size_t i = 0; i < 5; ++i) {
    double wi = 0.0;
    for (std::size_t u = i * classes; u < (i + 1) * classes; ++u) wi += double(c.count(u)) * c.bound(u);
    if (classes == 1) CHECK(wi == Approx(counts[i] * speed_max(p, i)).epsilon(1e-14));  // the paper's N_i vmax_i
    for (std::size_t k = 0; k < 5; ++k) total += w[i * 5 + k] = wi * counts[k] * (bird ? pairs.sigma2_max : pairs.sigma2(i, k));
  }
  double chi2 = 0.0;
  for (std::size_t x = 0; x < 25; ++x) chi2 += std::pow(hits[x] - draws * w[x] / total, 2) / (draws * w[x] / total);
  std::printf("%s, %zu speed classes: species-pair proposals chi2 = %.1f (24 dof)\n", name, classes, chi2);
  CHECK(chi2 < 51.2);  // χ² with 24 degrees of freedom: P(> 51.2) = 1e-3
  CHECK(sel.total_rate() == Approx(pi / pairs.volume * total).epsilon(1e-12));  // rounding only
}

// χ² of the proposed speed classes within each species against N_u bound_u (the second level of
// the two-level selection): 5 species × 8 classes, empty classes left out of the sum.
void check_class_proposals() {
  const model::Mixture mix({{1, 1, 0.1}, {2, 1.26, 0.08}, {3, 1.44, 0.06}, {4, 1.59, 0.04}, {5, 1.71, 0.02}});
  Rng rng(10, 0);
  Particles p = maxwellian_particles(mix, {500, 400, 300, 200, 100}, {1, 1, 1, 1, 1}, false, true, rng);
  const PairTable pairs(mix, {}, 1500 / 0.3);
  const LowRankSelector sel(pairs, p, 8);
  const SpeedClasses& c = sel.classes();
  const int draws = 1000000;
  std::vector<double> hits(40, 0.0), per_species(5, 0.0);
  for (int j = 0; j < draws; ++j) {
    const Proposal q = sel.propose(rng, p);
    hits[c.unit_of(q.a, q.i)] += 1, per_species[q.i] += 1;
  }
  double chi2 = 0.0;
  int dof = 0;
  for (std::size_t u = 0; u < 40; ++u) {
    const std::size_t i = u / 8;
    const double expect = per_species[i] * double(c.count(u)) * c.bound(u) / c.weight(i);
    if (c.count(u) == 0) {
      CHECK(hits[u] == 0);
      continue;
    }
    chi2 += std::pow(hits[u] - expect, 2) / expect, ++dof;
  }
  dof -= 5;  // the species totals are given
  const double bound = dof + 4.0 * std::sqrt(2.0 * dof);  // χ² ≈ normal(dof, 2 dof) at dof ≈ 30: 4σ
  std::printf("speed classes within species: chi2 = %.1f (%d dof, bound %.1f)\n", chi2, dof, bound);
  CHECK(chi2 < bound);
}

}  // namespace

TEST_CASE("low-rank, direct and Bird selectors propose species pairs with the majorant probabilities - 1 and 8 speed classes", "[dsmc]") {
  for (std::size_t classes : {1, 8}) {
    check_pair_proposals<LowRankSelector>(classes, "low-rank");
    check_pair_proposals<DirectSelector>(classes, "direct");
    check_pair_proposals<BirdSelector>(classes, "Bird", true);
  }
  check_class_proposals();
}

TEST_CASE("speed classes: after 2e5 collisions every particle is within its class bound - classes tile each species", "[dsmc]") {
  const model::Mixture mix({{1, 1, 0.1}, {10, 2, 0.05}, {100, 4, 0.01}});
  Rng rng(4, 0);
  Particles p = maxwellian_particles(mix, {3000, 1500, 300}, {1, 1, 1}, true, true, rng);
  const PairTable pairs(mix, {}, 4800 / 0.16);
  LowRankSelector sel(pairs, p, 8);
  Counters c;
  const model::Restitution law = model::Restitution::constant(3, 0.8);  // the loop keeps a reference
  EventLoop<LowRankSelector> loop(p, sel, law, rng, c, 1000000000);  // no refresh: moves only
  while (c.accepted < 200000) loop.run_until(loop.time() + 1.0);
  const SpeedClasses& cls = sel.classes();
  std::size_t violations = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(cls.begin(k * 8) == p.begin(k));
    CHECK(cls.begin(k * 8 + 7) + cls.count(k * 8 + 7) == p.end(k));
    for (std::size_t u = k * 8; u < k * 8 + 8; ++u)
      for (std::size_t a = cls.begin(u); a < cls.begin(u) + cls.count(u); ++a) violations += std::sqrt(norm2(p.v[a])) > cls.bound(u);
  }
  CHECK(violations == 0);  // the majorant bound(class a) + bound(class b) >= |g| holds for every pair
}

TEST_CASE("energy balance at every refresh: mass ratio 1e4 stays within rounding - an unbooked energy change stops the run", "[dsmc]") {
  const model::Mixture mix({{1, 1, 0.1}, {1e4, 20, 0.001}});
  Rng rng(7, 0);
  Particles p = maxwellian_particles(mix, {4000, 400}, {1, 1}, true, true, rng);
  const PairTable pairs(mix, {}, 4400 / 0.101);
  LowRankSelector sel(pairs, p, 3);
  Counters c;
  const model::Restitution law = model::Restitution::constant(2, 0.8);  // the loop keeps a reference
  EventLoop<LowRankSelector> loop(p, sel, law, rng, c, p.size());
  while (c.refreshes < 40) REQUIRE_NOTHROW(loop.run_until(loop.time() + 0.5));  // 40 refreshes within 4 (N + n) eps_mach E
  // One particle slowed by 0.1% without a collision to book it (what a rule breaking v1 Eq. 3 does):
  // the next refresh finds the energy balance broken, whatever the sign of the error.
  bool once = true;
  loop.at_refresh([&] {
    if (once) p.v[0] = {0.999 * p.v[0].x, 0.999 * p.v[0].y, 0.999 * p.v[0].z}, once = false;
  });
  const std::uint64_t before = c.refreshes;
  CHECK_THROWS_WITH(([&] { while (c.refreshes < before + 3) loop.run_until(loop.time() + 0.5); }()),
                    Catch::Contains("energy balance broken"));
}

TEST_CASE("selectors agree: 5 species - eps = 0.7 - temperatures and collisions per pair", "[dsmc]") {
  const std::vector<model::Species> sp = {{1, 1, 0.1}, {2, 1.26, 0.08}, {3, 1.44, 0.06}, {4, 1.59, 0.04}, {5, 1.71, 0.02}};
  std::vector<DsmcResult> r;
  for (Method m : {Method::direct, Method::lowrank, Method::bird, Method::bird_global})
    r.push_back(run_ensemble(setup(sp, 0.7, {2000, 1600, 1200, 800, 400}, {1.0, 5.0}, 8, m)));
  double worst = 0.0;
  for (std::size_t a = 1; a < r.size(); ++a)
    for (std::size_t j = 0; j < 10; ++j) {
      const double z = (r[a].T.mean[j] - r[0].T.mean[j]) / std::hypot(r[a].T.err[j], r[0].T.err[j]);
      worst = std::max(worst, std::abs(z));
    }
  for (std::size_t a = 1; a < r.size(); ++a)
    for (std::size_t j = 0; j < r[0].pair_collisions.mean.size(); ++j) {
      if (r[0].pair_collisions.mean[j] == 0.0) continue;  // i > k cells are empty by construction
      const double z = (r[a].pair_collisions.mean[j] - r[0].pair_collisions.mean[j]) /
                       std::hypot(r[a].pair_collisions.err[j], r[0].pair_collisions.err[j]);
      worst = std::max(worst, std::abs(z));
    }
  std::printf("selector equivalence (T_k and collisions per pair, 2 times): max |z| = %.2f over 180 comparisons\n", worst);
  CHECK(worst < 4.6);  // 180 comparisons: 4.6 keeps the chance of a false alarm below 1e-3 (180 × 4.2e-6)
}

TEST_CASE("Haff's law with the first-Sonine cooling rate - eps = 0.9", "[dsmc]") {
  const double e = 0.9;
  DsmcSetup s = setup({{1, 1, 0.1}}, e, {20000}, {10.0, 50.0, 200.0}, 8);
  const DsmcResult r = run_ensemble(s);
  // ζ = ζ_Maxwell (1 + 3a₂/16), c = 2a₂ from van Noije–Ernst (docs/physics.md §2, §6).
  const double c = 32 * (1 - e) * (1 - 2 * e * e) / (81 - 17 * e + 30 * e * e * (1 - e));
  const double tau0 = 3 / (2 * std::sqrt(pi) * (1 - e * e) * 0.1) / (1 + 3 * c / 32);
  for (std::size_t j = 0; j < 3; ++j) {
    const double t = s.times[j], haff = 1 / std::pow(1 + t / tau0, 2);
    const double z = (r.T.mean[j] - haff) / r.T.err[j];
    std::printf("Haff eps=0.9, t=%g: T = %.5f +- %.5f, Sonine-Haff %.5f (rel %.2e, z %.2f)\n", t, r.T.mean[j], r.T.err[j], haff,
                r.T.mean[j] / haff - 1, z);
    // Model tolerance: a₂ relaxes from 0 (Maxwellian start) to its HCS value over a few collisions;
    // that transient shifts T by at most |3a₂/16| × (collisions spent) / (collisions so far) < 0.3%.
    CHECK(std::abs(r.T.mean[j] - haff) < 4 * r.T.err[j] + 3e-3 * haff);
  }
}

TEST_CASE("binary m = 1 - 100 of one material - eps = 0.5: temperature ratio settles to theory within the Maxwellian model error", "[dsmc]") {
  const std::vector<model::Species> sp = {{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}};
  DsmcSetup s = setup(sp, 0.5, {10000, 10000}, {1e3}, 4);
  const DsmcResult r = run_ensemble(s);
  const theory::CollisionRates rates(s.mixture, s.law, model::dilute_contact_values(2));
  const double theory_ratio = theory::settled_ratios(rates)[1];
  const double ratio = r.T.mean[1] / r.T.mean[0];
  const double ratio_err = ratio * std::hypot(r.T.err[0] / r.T.mean[0], r.T.err[1] / r.T.mean[1]);
  std::printf("binary settled T2/T1: DSMC %.4f +- %.4f, theory (Maxwellian) %.4f, rel %.4f\n", ratio, ratio_err, theory_ratio,
              ratio / theory_ratio - 1);
  // Measured −2.2% with a statistical error of ~0.3%. DSMC solves the
  // Boltzmann equation exactly, the theory closes it with Maxwellians (v1 Eq. A2): the gap is that
  // closure's model error (the first-Sonine γ should close most of it). Model tolerance 3%: the measured
  // gap plus four standard errors.
  CHECK(std::abs(ratio / theory_ratio - 1) < 0.03);
}

TEST_CASE("reproducible: same seed gives identical results on 1 and 2 threads - another seed differs", "[dsmc]") {
  DsmcSetup s = setup({{1, 1, 0.1}, {4, 1.5, 0.05}}, 0.8, {3000, 1500}, {1.0, 4.0}, 4);
  s.msd = true, s.cumulant = true;
  s.threads = 1;
  const DsmcResult a = run_ensemble(s);
  s.threads = 2;
  const DsmcResult b = run_ensemble(s);
  CHECK(a.T.mean == b.T.mean);  // bit for bit
  CHECK(a.msd.mean == b.msd.mean);
  CHECK(a.cumulant.err == b.cumulant.err);
  CHECK(a.accepted == b.accepted);
  s.seed += 1;
  CHECK(run_ensemble(s).T.mean != a.T.mean);
}

TEST_CASE("elastic binary: temperatures stay put and cumulants stay 0", "[dsmc]") {
  DsmcSetup s = setup({{1, 1, 0.1}, {3, 1.5, 0.05}}, 1.0, {8000, 4000}, {3.0}, 8);
  s.cumulant = true;
  const DsmcResult r = run_ensemble(s);
  for (std::size_t k = 0; k < 2; ++k) {
    std::printf("elastic binary species %zu: T - 1 = %.2e (z %.2f), c = %.4f (z %.2f)\n", k + 1, r.T.mean[k] - 1,
                (r.T.mean[k] - 1) / r.T.err[k], r.cumulant.mean[k], r.cumulant.mean[k] / r.cumulant.err[k]);
    CHECK(std::abs(r.T.mean[k] - 1) < 4 * r.T.err[k]);  // equal start, no dissipation: no drift
    CHECK(std::abs(r.cumulant.mean[k]) < 4 * r.cumulant.err[k]);  // Maxwellian stays Maxwellian
  }
  CHECK((r.T.mean[0] * 8000 + r.T.mean[1] * 4000) / 12000 == Approx(1.0).epsilon(1e-12));  // energy conserved
}

TEST_CASE("impurity with equal temperatures (docs/physics.md section 7) keeps T1 = T2", "[dsmc]") {
  // x1 -> 0 with (σ12/σ22)^4 = μ(1+μ)/2: w = 2 gives μ = m1/m2 = 2.721; Maxwellian theory γ = 1.
  DsmcSetup s = setup({{2.721, 2, 0.001}, {1, 1, 0.1}}, 0.5, {400, 40000}, {20.0, 200.0}, 8);
  const DsmcResult r = run_ensemble(s);
  for (std::size_t j = 0; j < 2; ++j) {
    const double g = r.T.mean[2 * j] / r.T.mean[2 * j + 1];
    const double err = g * std::hypot(r.T.err[2 * j] / r.T.mean[2 * j], r.T.err[2 * j + 1] / r.T.mean[2 * j + 1]);
    std::printf("impurity t=%g: T1/T2 = %.4f +- %.4f\n", s.times[j], g, err);
    // x1 = 0.01 shifts the Maxwellian value by ~1e-3; the first-Sonine shift is of the same order.
    CHECK(std::abs(g - 1.0) < 4 * err + 0.005);
  }
}

TEST_CASE("aged start: the gas cools to <T> = 1 and the measurement starts there", "[dsmc]") {
  DsmcSetup s = setup({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.001}}, 0.5, {20000, 200}, {1e-9, 1.0}, 8);
  s.T0 = {100.0, 100.0};
  s.aged = true;
  s.msd = true;
  const DsmcResult r = run_ensemble(s);
  const double mean = (20000 * r.T.mean[0] + 200 * r.T.mean[1]) / 20200;
  CHECK(mean == Approx(1.0).margin(1e-3));  // stops within one collision's loss: O(1/N)
  CHECK(r.msd.mean[0] < 1e-15);             // displacements were reset at the start
  CHECK(r.pair_collisions.mean[0] < 100);   // so were the collision counts (1e-9 after the reset)
  const theory::CollisionRates rates(s.mixture, s.law, model::dilute_contact_values(2));
  model::InitialState aged;
  aged.kind = model::InitialState::Kind::aged;
  aged.T_hot = 100.0;
  const std::vector<double> T = theory::initial_temperatures(aged, rates);
  const double ratio = r.T.mean[1] / r.T.mean[0];
  std::printf("aged start: T2/T1 = %.3f, Maxwellian theory %.3f (rel %.3f)\n", ratio, T[1] / T[0], ratio / (T[1] / T[0]) - 1);
  // The ratio is still in its transient (see the theory test), where the Maxwellian closure errs
  // more than in the settled state: measured +5%; stated model tolerance 10%.
  CHECK(ratio == Approx(T[1] / T[0]).epsilon(0.10));
}

TEST_CASE("time-step scheme (MG Sec. 3) agrees with the event-driven loop for every step size", "[dsmc]") {
  auto run = [](Method m, double factor) {
    DsmcSetup s = setup({{1, 1, 0.1}}, 0.5, {20000}, {30.0}, 8, m);
    s.cumulant = true;
    s.time_step_factor = factor;
    return run_ensemble(s);
  };
  const DsmcResult ed = run(Method::direct, 0.0);
  // docs/physics.md §7 expects an O(Δt) bias of c. With velocities updated collision by collision inside a
  // step and acceptance at the current |g| (as MG describe), only the candidate count is discretised,
  // and no bias is measurable down to the statistical error (±0.003 on c) even at Δt = 10 λ/v0.
  for (double factor : {10.0, 1.0, 3e-3}) {
    const DsmcResult ts = run(Method::timestep, factor);
    const double zc = (ts.cumulant.mean[0] - ed.cumulant.mean[0]) / std::hypot(ts.cumulant.err[0], ed.cumulant.err[0]);
    const double zT = (ts.T.mean[0] - ed.T.mean[0]) / std::hypot(ts.T.err[0], ed.T.err[0]);
    std::printf("time step %.0e lambda/v0 (%llu steps): c = %.4f vs event-driven %.4f (z %.2f), T z %.2f\n", factor,
                static_cast<unsigned long long>(ts.steps / 8), ts.cumulant.mean[0], ed.cumulant.mean[0], zc, zT);
    CHECK(std::abs(zc) < 4);
    CHECK(std::abs(zT) < 4);
  }
}

TEST_CASE("viscoelastic one-species gas: DSMC with the exact contact law follows the theory", "[dsmc]") {
  DsmcSetup s = setup({{1, 1, 0.1}}, 1.0, {10000}, {10.0, 300.0}, 8);
  s.law = model::Restitution::viscoelastic(s.mixture, 0.09, model::ViscoelasticForm::exact);
  const DsmcResult r = run_ensemble(s);
  const theory::CollisionRates rates(s.mixture, s.law, model::dilute_contact_values(1));
  const theory::TemperatureHistory h(rates, {1.0}, 300.0);
  for (std::size_t j = 0; j < 2; ++j) {
    const double th = h.temperature(s.times[j], 0);
    std::printf("viscoelastic t=%g: T = %.5f +- %.5f, theory (exact eps quadrature) %.5f, rel %.4f\n", s.times[j], r.T.mean[j],
                r.T.err[j], th, r.T.mean[j] / th - 1);
    // Theory closes the collision integral with Maxwellians; DSMC does not. Measured +0.2% at
    // t = 10 and +0.7% at t = 300 (the non-Maxwellian correction grows as the gas cools and ε(g)
    // spreads). Stated model tolerance 1% plus 4σ.
    CHECK(std::abs(r.T.mean[j] - th) < 4 * r.T.err[j] + 1e-2 * th);
  }
}

TEST_CASE("rescaled time t_s: equal to t in an elastic gas and tau0 ln(1 + t/tau0) under Haff's law", "[dsmc]") {
  DsmcSetup elastic = setup({{1, 1, 0.1}}, 1.0, {2000}, {5.0}, 2);
  const DsmcResult a = run_ensemble(elastic);
  CHECK(a.rescaled_time.mean[0] == Approx(5.0).epsilon(1e-12));  // T_1 never changes: rounding only
  const double e = 0.9;
  DsmcSetup s = setup({{1, 1, 0.1}}, e, {20000}, {50.0, 200.0}, 8);
  const DsmcResult r = run_ensemble(s);
  const double c = 32 * (1 - e) * (1 - 2 * e * e) / (81 - 17 * e + 30 * e * e * (1 - e));
  const double tau0 = 3 / (2 * std::sqrt(pi) * (1 - e * e) * 0.1) / (1 + 3 * c / 32);  // as in the Haff test
  for (std::size_t j = 0; j < 2; ++j) {
    const double th = tau0 * std::log1p(s.times[j] / tau0);
    std::printf("t_s at t = %g: %.5f +- %.5f, Sonine-Haff %.5f\n", s.times[j], r.rescaled_time.mean[j], r.rescaled_time.err[j], th);
    // Same model tolerance as the Haff test (0.3%: the a₂ transient), plus 4σ.
    CHECK(std::abs(r.rescaled_time.mean[j] - th) < 4 * r.rescaled_time.err[j] + 3e-3 * th);
  }
}

TEST_CASE("velocity distribution of an elastic gas is the Maxwellian in MG units", "[dsmc]") {
  // 32 replicas: a z from replica errors follows Student's t with R − 1 degrees of freedom, whose
  // tails at R = 8 made the 4.5 bound below a 9% false alarm over 32 bins; at R = 32 it is 0.3%.
  DsmcSetup s = setup({{1, 1, 0.1}}, 1.0, {5000}, {2.0}, 32);
  s.distribution_bins = 32, s.distribution_vmax = 3.2;
  const DsmcResult r = run_ensemble(s);
  // One species: v0² = 2T(m+m)/m² = 4T/m, so Φ(v*) = (2/π)^(3/2) exp(−2v*²); the exact mean over a
  // shell uses the Maxwellian CDF F(x) = erf(√2 x) − 2√(2/π) x exp(−2x²).
  auto F = [](double x) { return std::erf(std::sqrt(2.0) * x) - 2.0 * std::sqrt(2.0 / pi) * x * std::exp(-2.0 * x * x); };
  double worst = 0.0;
  for (std::size_t b = 0; b < 32; ++b) {
    const double lo = 0.1 * b, hi = lo + 0.1, shell = 4.0 * pi / 3.0 * (hi * hi * hi - lo * lo * lo);
    const double expect = (F(hi) - F(lo)) / shell;
    if (r.distribution.err[b] > 0) worst = std::max(worst, std::abs(r.distribution.mean[b] - expect) / r.distribution.err[b]);
  }
  std::printf("elastic distribution: max |z| over 32 bins = %.2f\n", worst);
  CHECK(worst < 4.5);
}
