// Displacements (v1 Eq. 15) against theory: the elastic limit, where the exact answer is known, and
// the binary of v1 Fig. 2, where the first-approximation theory has a model error we measure.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "dsmc/ensemble.hpp"
#include "model/enskog.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/histories/msd.hpp"
#include "theory/histories/tamsd.hpp"
#include "theory/histories/temperature_history.hpp"

using namespace granmix;

TEST_CASE("elastic gas: MSD = 6D[t - tau_v(1 - exp(-t/tau_v))] with the Chapman-Enskog correction", "[dsmc]") {
  dsmc::DsmcSetup s;
  s.mixture = model::Mixture({{1, 1, 0.1}});
  s.law = model::Restitution::constant(1, 1.0);
  s.counts = {20000}, s.T0 = {1.0}, s.times = {0.2, 50.0}, s.replicas = 4, s.msd = true, s.seed = 77;
  const dsmc::DsmcResult r = dsmc::run_ensemble(s);
  const theory::CollisionRates rates(s.mixture, s.law, model::dilute_contact_values(1));
  const theory::SettledDiffusion d = theory::diffusion_at(rates, {1.0});
  const double early = theory::msd_closed(d.D[0], d.tau_v[0], d.tau0, 0.2), late = theory::msd_closed(d.D[0], d.tau_v[0], d.tau0, 50.0);
  std::printf("elastic MSD: t=0.2 ratio %.4f +- %.4f; t=50 ratio %.4f +- %.4f\n", r.msd.mean[0] / early, r.msd.err[0] / early,
              r.msd.mean[1] / late, r.msd.err[1] / late);
  // Early: ballistic and exact, z bound 4. Late: the exact hard-sphere D is 1.019 times the first
  // Chapman–Enskog value the theory uses (Chapman & Cowling); at t = 50 τ_v the offset term still
  // weighs 2%: expect a ratio in [1.0, 1.025] (z bound 4 around that band).
  CHECK(std::abs(r.msd.mean[0] - early) < 4 * r.msd.err[0]);
  CHECK(r.msd.mean[1] / late > 1.0 - 4 * r.msd.err[1] / late);
  CHECK(r.msd.mean[1] / late < 1.025 + 4 * r.msd.err[1] / late);
}

TEST_CASE("v1 Fig. 2 binary: DSMC MSD against Eq. (17)", "[dsmc]") {
  dsmc::DsmcSetup s;
  s.mixture = model::Mixture({{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}});
  s.law = model::Restitution::constant(2, 0.5);
  s.counts = {10000, 10000}, s.T0 = {1.0, 1.0}, s.times = {0.05, 1.0, 10.0, 100.0, 1e4}, s.replicas = 4, s.msd = true;
  const dsmc::DsmcResult r = dsmc::run_ensemble(s);
  const theory::CollisionRates rates(s.mixture, s.law, model::dilute_contact_values(2));
  theory::TemperatureOptions o;
  o.reduced_time = true;
  const theory::TemperatureHistory h(rates, {1.0, 1.0}, 1e4, o);
  for (std::size_t j = 0; j < s.times.size(); ++j)
    for (std::size_t k = 0; k < 2; ++k) {
      const double th = theory::msd_eq17(h, k, s.times[j]), v = r.msd.mean[j * 2 + k];
      const double rel = v / th - 1, z = (v - th) / r.msd.err[j * 2 + k];
      std::printf("Fig. 2 MSD t=%-6g species %zu: DSMC/theory - 1 = %+.4f (z %.1f)\n", s.times[j], k + 1, rel, z);
      if (k == 1 || s.times[j] < 0.5) {
        // Heavy species at all times and both species in the ballistic regime: within 5%.
        CHECK(std::abs(rel) < 0.05);
      } else {
        // Light species after the first collisions: Eq. (17) (Maxwellian rates, exponential velocity
        // memory) overestimates the MSD by 8–13%; the engine is exact here (elastic test above), so
        // this is the theory's model error. Bound 15%: the measured 13% plus statistical room.
        CHECK(rel < 0.0);
        CHECK(rel > -0.15);
      }
    }
}

TEST_CASE("TAMSD equals the ensemble MSD in an elastic gas and falls below it in a cooling one", "[dsmc]") {
  auto run = [](double eps) {
    dsmc::DsmcSetup s;
    s.mixture = model::Mixture({{1, 1, 0.1}});
    s.law = model::Restitution::constant(1, eps);
    s.counts = {5000}, s.T0 = {1.0}, s.times = {0.1, 1.0, 10.0}, s.replicas = 8, s.msd = true, s.seed = 21;
    s.tamsd_measurement_time = 50.0, s.tamsd_lags = s.times, s.tamsd_tracers = 200;
    return dsmc::run_ensemble(s);
  };
  const dsmc::DsmcResult elastic = run(1.0), cooling = run(0.5);
  for (std::size_t l = 0; l < 3; ++l) {
    // Stationary gas: time average = ensemble average at every lag (different estimators of one
    // expectation; z bound 4 with the errors combined as independent).
    const double z = (elastic.tamsd.mean[l] - elastic.msd.mean[l]) / std::hypot(elastic.tamsd.err[l], elastic.msd.err[l]);
    std::printf("elastic lag %g: TAMSD %.4g +- %.2g, MSD %.4g +- %.2g (z %.2f); cooling: TAMSD %.4g, MSD %.4g\n", std::vector<double>{0.1, 1.0, 10.0}[l],
                elastic.tamsd.mean[l], elastic.tamsd.err[l], elastic.msd.mean[l], elastic.msd.err[l], z, cooling.tamsd.mean[l],
                cooling.msd.mean[l]);
    CHECK(std::abs(z) < 4);
  }
  // Cooling gas: the window [0, 𝒯] includes slow late times, so δ²(Δ) < ⟨R²(Δ)⟩ (docs/physics.md §4).
  CHECK(cooling.tamsd.mean[2] + 4 * cooling.tamsd.err[2] < cooling.msd.mean[2]);
}

TEST_CASE("TAMSD of a cooling gas follows the settled-state model in the ballistic regime", "[dsmc]") {
  // A uniform grid of start times over [0, 𝒯] would overweight the hot start (τ0 ≪ 𝒯) and
  // give 2.5 times the ballistic TAMSD. Start at Haff's law (one species, settled by definition).
  const double e = 0.5;
  dsmc::DsmcSetup s;
  s.mixture = model::Mixture({{1, 1, 0.1}});
  s.law = model::Restitution::constant(1, e);
  s.counts = {10000}, s.T0 = {1.0}, s.times = {0.01, 0.1}, s.replicas = 8, s.seed = 31;
  s.tamsd_measurement_time = 1e3, s.tamsd_lags = s.times, s.tamsd_tracers = 500;
  const dsmc::DsmcResult r = dsmc::run_ensemble(s);
  const theory::CollisionRates rates(s.mixture, s.law, model::dilute_contact_values(1));
  const theory::SettledDiffusion d = theory::diffusion_at(rates, {1.0});
  for (std::size_t l = 0; l < 2; ++l) {
    const double th = theory::tamsd(d.D[0], d.tau_v[0], d.tau0, 1e3, s.times[l]);
    std::printf("cooling TAMSD lag %g: DSMC %.4g +- %.2g, model %.4g (rel %+.3f)\n", s.times[l], r.tamsd.mean[l], r.tamsd.err[l], th,
                r.tamsd.mean[l] / th - 1);
    // Ballistic: ⟨v²⟩ averaged over the window; the model's Haff τ0 lacks the Sonine factor 1 + 3a₂/16
    // (1%) and the start grid's trapezoid errs by ~1e-4 (its ratio 1.027 per start): 1.1% plus 4σ. An
    // average that stopped at the grid's last start below 𝒯 − Δ (972.7 for 999.99) would come out 2.7% high.
    CHECK(std::abs(r.tamsd.mean[l] - th) < 0.011 * th + 4 * r.tamsd.err[l]);
  }
}
