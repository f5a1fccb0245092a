// Randomized physics properties of the kinetic theory, 200 mixtures per property from
// fixed seeds (random_mixtures.hpp):
//  - the settled ratios make every ξ_k equal to 1e-10 of the rate scale, or the solver says why
//    (NumericalError naming itself);
//  - from equal temperatures, every T_k stays positive and finite up to t = 1e12, and the MSD (VACF
//    form) increases and starts ballistic, 3 T_k t²/m_k;
//  - constant ε < 1, from the settled state: the VACF MSD is v2 Eq. (22) at all times and grows as
//    6 D_k τ₀ ln t at late times (v2 Eq. 23);
//  - viscoelastic: the MSD grows as t^(1/6) at late times (v1 Fig. 9 text).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "model/errors.hpp"
#include "random_mixtures.hpp"
#include "theory/rates/collision_rates.hpp"
#include "theory/rates/diffusion.hpp"
#include "theory/histories/msd.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/histories/temperature_history.hpp"

using namespace granmix;
using namespace granmix::theory;

namespace {

constexpr int cases = 200;

CollisionRates rates_of(const test::RandomMixture& m) {
  return CollisionRates(m.mixture, m.law, model::dilute_contact_values(m.mixture.size()));
}

// ξ_k and τ_v,k⁻¹ at the temperatures T.
struct RatesAt {
  std::vector<double> xi, inv;
};
RatesAt rates_at(const CollisionRates& r, const std::vector<double>& T) {
  RatesAt a{std::vector<double>(T.size()), std::vector<double>(T.size())};
  r.xi_and_inv_tau_v_all(T.data(), a.xi.data(), a.inv.data());
  return a;
}

// max_k |ξ_k − ξ_1| / scale with the solver's own scale max_k(|ξ_k|, τ_v,k⁻¹) (settled_ratios.hpp):
// ξ_1 alone is no scale at ε = 1, where every ξ_k is 0.
double settled_residual(const CollisionRates& r, const std::vector<double>& T) {
  const std::size_t N = T.size();
  const auto [xi, inv] = rates_at(r, T);
  double scale = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < N; ++k) scale = std::max({scale, std::abs(xi[k]), inv[k]});
  for (std::size_t k = 1; k < N; ++k) worst = std::max(worst, std::abs(xi[k] - xi[0]));
  return worst / scale;
}

}  // namespace

TEST_CASE("property: settled ratios equalise the cooling rates to 1e-10 or the solver reports its limit", "[property]") {
  test::MixtureSampler sample(15001);
  int solved = 0, refused = 0;
  double worst = 0.0;
  for (int c = 0; c < cases; ++c) {
    const test::RandomMixture m = sample.next();
    INFO("case " << c << ": " << m.describe());
    const CollisionRates r = rates_of(m);
    try {
      const SettledState s = settled_temperatures(r);
      const double res = settled_residual(r, s.T);
      worst = std::max(worst, res);
      CHECK(res <= 1e-10);
      for (double T : s.T) CHECK((std::isfinite(T) && T > 0));
      ++solved;
    } catch (const NumericalError& e) {
      const std::string what = e.what();
      INFO(what);
      CHECK(what.find("settled temperature ratios") != std::string::npos);
      ++refused;
    }
  }
  std::printf("settled ratios: %d solved (worst residual %.2e), %d refused with NumericalError\n", solved, worst, refused);
}

// Cases 67 and 71 (elastic, 23 and 26 species) fail with CV_CONV_FAILURE under unpreconditioned
// GMRES; the automatic solver takes dense LU there (temperature_history.cpp). Viscoelastic mixtures here have at most 3 species: a history to 1e12 with the VACF takes ~5000
// right-hand sides of N(N+1)/2 quadrature pairs (8 species: 5 s of CPU each, 40 of them).
TEST_CASE("property: temperatures stay positive and finite to t = 1e12 - MSD increasing and ballistic at short times", "[property]") {
  test::MixtureSampler sample(15002, 3);
  double worst_ballistic = 0.0;
  for (int c = 0; c < cases; ++c) {
    const test::RandomMixture m = sample.next();
    INFO("case " << c << ": " << m.describe());
    const CollisionRates r = rates_of(m);
    const std::size_t N = m.mixture.size();
    const std::vector<double> T0(N, 1.0);
    // The ballistic check time: 1e-4 of the fastest rate of any species, where the MSD is
    // 3 T t²/m (1 + O(t/τ)); the O(t/τ) terms are bounded by t (τ_v,k⁻¹ + |ξ_k|) (bound below).
    const auto [xi, inv] = rates_at(r, T0);
    double fastest = 0.0;
    for (std::size_t k = 0; k < N; ++k) fastest = std::max(fastest, inv[k] + std::abs(xi[k]));
    const double t_ball = 1e-4 / fastest;
    TemperatureOptions opt;
    opt.vacf = true;
    opt.t_first = t_ball;
    const TemperatureHistory h(r, T0, 1e12, opt);
    std::vector<double> prev(N, 0.0);
    for (int j = 0; j <= 40; ++j) {  // log grid t_ball .. 1e12
      const double t = t_ball * std::pow(1e12 / t_ball, j / 40.0);
      for (std::size_t k = 0; k < N; ++k) {
        const double T = h.temperature(t, k), msd = h.msd_vacf(t, k);
        INFO("t = " << t << ", species " << k + 1 << ": T = " << T << ", msd = " << msd);
        REQUIRE((std::isfinite(T) && T > 0));
        REQUIRE(std::isfinite(msd));
        REQUIRE(msd > prev[k]);
        prev[k] = msd;
      }
    }
    for (std::size_t k = 0; k < N; ++k) {
      const double ballistic = 3.0 * t_ball * t_ball / m.mixture[k].mass;  // T_k(0) = 1
      const double dev = std::abs(h.msd_vacf(t_ball, k) / ballistic - 1);
      worst_ballistic = std::max(worst_ballistic, dev / (t_ball * (inv[k] + std::abs(xi[k])) + 1e-6));
      INFO("species " << k + 1 << ": msd/ballistic - 1 = " << dev);
      // bound: the O(t/τ) corrections plus the integrator's accuracy (1e-6: the companions'
      // absolute tolerance at t_first is rtol times their size there, rtol = 1e-11, over < 1e5 steps)
      CHECK(dev <= t_ball * (inv[k] + std::abs(xi[k])) + 1e-6);
    }
  }
  std::printf("ballistic start: worst deviation %.2f of its bound\n", worst_ballistic);
}

// From the settled state, T_k = T_k*/(1 + t/τ₀)² and every rate ∝ 1/(τ₀ + t); the VACF ODE
// dJ/dt = 3T_k/m_k − J(τ_v,k⁻¹ + ξ_k/2), J(0) = 0, with ξ = 2/(τ₀+t) and a = τ₀/τ_v,k is then solved by
// J = 3 D_k τ₀/(τ₀+t) · [1 − (1+t/τ₀)^(−a)], i.e. ⟨R²⟩ = 2∫J dt is v2 Eq. (22) exactly (msd_closed).
// Check 1: the ODE against it at 25 times from 1e-4 of the fastest time to the end, to 1e-6 (CVODE at
//   rtol 1e-11 over < 1e5 steps; measured below). A decay rate without ξ/2 (docs/physics.md §3) changes
//   ⟨R²⟩ by O(ξ τ_v) at t ~ τ_v, a wrong time unit by O(1).
// Check 2, the late-time law (v2 Eq. 23): between t₁ and t₂ = 10 t₁, the slope Δ⟨R²⟩/Δ ln t differs
//   from 6 D_k τ₀ by the two corrections of Eq. (22): ln(1+t/τ₀) against ln t, at most τ₀/t₁, and the
//   transient, whose share of the slope is (1+t₁/τ₀)^(−a)(1 − 10^(−a))/(a ln 10) <= (t₁/τ₀)^(−a). A
//   species is in the ln t regime once that share is below 1e-4: t₁ = τ₀ max(1e4, 1e4^(1/a)), taken
//   while t₁ <= 1e8 τ₀ (slower species are covered by check 1 only). Tolerance: the sum + 1e-6.
TEST_CASE("property: constant eps < 1 - the MSD is v2 Eq. 22 and grows as 6 D_k tau0 ln t at late times", "[property]") {
  test::MixtureSampler sample(15003);
  int checked = 0, law_species = 0, species = 0;
  double worst_closed = 0.0, worst_law = 0.0;
  for (int c = 0; c < cases; ++c) {
    const test::RandomMixture m = sample.next();
    if (m.viscoelastic || m.eps == 1.0) continue;
    INFO("case " << c << ": " << m.describe());
    const CollisionRates r = rates_of(m);
    const std::size_t N = m.mixture.size();
    SettledDiffusion d;
    try {
      d = settled_diffusion(r);
    } catch (const NumericalError&) {
      continue;  // counted by the settled-ratio property
    }
    double tau_v_min = d.tau0, t1 = 1e4 * d.tau0;
    for (double tv : d.tau_v) {
      tau_v_min = std::min(tau_v_min, tv);
      const double need = d.tau0 * std::pow(1e4, std::max(1.0, tv / d.tau0));
      if (need <= 1e8 * d.tau0) t1 = std::max(t1, need);
    }
    const double t2 = 10 * t1, t_first = 1e-4 * tau_v_min;
    TemperatureOptions opt;
    opt.vacf = true;
    opt.t_first = t_first;
    const TemperatureHistory h(r, d.T, t2, opt);
    for (std::size_t k = 0; k < N; ++k) {
      ++species;
      for (int j = 0; j <= 24; ++j) {
        const double t = t_first * std::pow(t2 / t_first, j / 24.0);
        const double closed = msd_closed(d.D[k], d.tau_v[k], d.tau0, t), dev = std::abs(h.msd_vacf(t, k) / closed - 1);
        worst_closed = std::max(worst_closed, dev);
        INFO("species " << k + 1 << ", t = " << t << ": VACF MSD / Eq. 22 - 1 = " << dev);
        CHECK(dev <= 1e-6);
      }
      const double a = d.tau0 / d.tau_v[k], transient = std::pow(t1 / d.tau0, -a);
      if (transient > 1e-4) continue;
      ++law_species;
      const double slope = (h.msd_vacf(t2, k) - h.msd_vacf(t1, k)) / std::log(10.0);
      const double expected = 6 * d.D[k] * d.tau0, tol = d.tau0 / t1 + transient + 1e-6;
      const double dev = std::abs(slope / expected - 1);
      worst_law = std::max(worst_law, dev / tol);
      INFO("species " << k + 1 << ": slope " << slope << ", 6 D tau0 " << expected << ", tol " << tol);
      CHECK(dev <= tol);
    }
    ++checked;
  }
  std::printf("constant eps MSD: %d mixtures, %d species; VACF against Eq. 22: worst %.1e (bound 1e-6); "
              "ln t law reached by %d species, worst deviation %.2f of its bound\n",
              checked, species, worst_closed, law_species, worst_law);
  CHECK(checked > cases / 2);
  CHECK(law_species > species / 2);
}

// Viscoelastic gas at late times (docs/physics.md §2–3): T ∝ t^(−5/3) and ν_k = τ_v,k⁻¹ + ξ_k/2 ∝ √T, so
// once J follows its quasi-static value 3T_k/(m_k ν_k) the MSD grows as ∫ T/ν dt ∝ t^(1/6). The
// decade exponent p = log10(Δ⟨R²⟩[10t₁, 100t₁] / Δ⟨R²⟩[t₁, 10t₁]) then equals 1 − q_k + r_k with the
// measured exponents q_k = −Δln T_k/Δln t, r_k = −Δln ν_k/Δln t over [t₁, 100t₁] (5/3 and 5/6 in the
// limit: their departures, from the residual dissipation ∝ T^(1/10) and the drift of the ratios, are
// part of the bound), up to the lag of J behind its quasi-static value, a relative 1/(ν_k t) that
// changes the exponent by less than 1/(ν_k t₁). So |p − 1/6| <= |q_k − 5/3| + |r_k − 5/6| +
// 1/(ν_k t₁) + 1e-6. t₁ = 1e24 t_c (t_c = 2/ξ̄(0)). The bound is small only where the species has
// reached the late-time regime: where it is below 1/12 (half the 1/6 by which a ln t law, p = 0,
// would miss) the check discriminates; at least 3/4 of the species must be there (those left out
// are partners of very different mass whose ratios still drift towards equipartition: T ∝ t^(−1.8)).
// At these times a (1 − ε) moment quadrature through 1 − restitution() gives up with GSL "roundoff
// error" (case 35): model::restitution_deficit avoids the cancellation.
TEST_CASE("property: viscoelastic - the MSD grows as t^(1/6) at late times", "[property]") {
  test::MixtureSampler sample(15006, 3);
  int checked = 0, species = 0, late = 0;
  double worst = 0.0;
  for (int c = 0; c < cases && checked < 12; ++c) {
    const test::RandomMixture m = sample.next();
    if (!m.viscoelastic) continue;
    INFO("case " << c << ": " << m.describe());
    const CollisionRates r = rates_of(m);
    const std::size_t N = m.mixture.size();
    const std::vector<double> T0(N, 1.0);
    const std::vector<double> xi0 = rates_at(r, T0).xi;
    double loss = 0.0, energy = 0.0;
    for (std::size_t k = 0; k < N; ++k) loss += m.mixture[k].density * xi0[k], energy += m.mixture[k].density;
    const double t1 = 1e24 * 2.0 / (loss / energy), t2 = 10 * t1, t3 = 100 * t1;
    TemperatureOptions opt;
    opt.vacf = true;
    const TemperatureHistory h(r, T0, t3, opt);
    auto nu_at = [&](double t) {  // ν_k = τ_v,k⁻¹ + ξ_k/2, the VACF's decay rate
      std::vector<double> T(N), nu(N);
      h.temperatures(t, T.data());
      const auto [xi, inv] = rates_at(r, T);
      for (std::size_t k = 0; k < N; ++k) nu[k] = inv[k] + xi[k] / 2;
      return nu;
    };
    const std::vector<double> nu1 = nu_at(t1), nu3 = nu_at(t3);
    for (std::size_t k = 0; k < N; ++k) {
      const double p = std::log10((h.msd_vacf(t3, k) - h.msd_vacf(t2, k)) / (h.msd_vacf(t2, k) - h.msd_vacf(t1, k)));
      const double q = -std::log10(h.temperature(t3, k) / h.temperature(t1, k)) / 2;
      const double rk = -std::log10(nu3[k] / nu1[k]) / 2;
      const double bound = std::abs(q - 5.0 / 3) + std::abs(rk - 5.0 / 6) + 1 / (nu1[k] * t1) + 1e-6;
      worst = std::max(worst, std::abs(p - 1.0 / 6) / bound);
      INFO("species " << k + 1 << ": exponent " << p << ", T exponent " << -q << ", nu exponent " << -rk << ", bound " << bound);
      CHECK(std::abs(p - 1.0 / 6) <= bound);
      ++species;
      if (bound < 1.0 / 12) ++late;
    }
    ++checked;
  }
  std::printf("viscoelastic MSD ~ t^(1/6): %d mixtures, %d of %d species in the late regime (bound < 1/12), "
              "worst deviation %.2f of its bound\n", checked, late, species, worst);
  CHECK(checked == 12);
  CHECK(4 * late >= 3 * species);
}
