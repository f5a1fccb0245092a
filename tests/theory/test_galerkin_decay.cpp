// The converged tracer problem in time (theory/grid/galerkin_decay.hpp): its pair tables against direct assembly, and its
// forward VACF ODE against the settled adjoint problem of tracer_diffusion_galerkin.hpp — the MSD of the ODE at
// settled ratios is the closed form of galerkin_memory at every time, elastic and inelastic.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "model/mixture_generators.hpp"
#include "theory/grid/galerkin_decay.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/histories/temperature_history.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"
#include "theory/rates/velocity_memory.hpp"
#include "theory_fixtures.hpp"

using namespace granmix;
using namespace granmix::theory;

TEST_CASE("converged memory in time: the interpolated pair tables are the direct assembly to 1e-4", "[theory]") {
  // Catmull–Rom on the ln ρ grid (step 1/8, the heavy species' smooth basis 1/6) is third order: 4.2e-5 at worst here
  // (the light species at T₂/T₁ = 92.1, ρ = 0.92; 4.8e-5 without the flux factor √(λ + ρ) in the tables, 4.3e-4 with
  // its step 1/6); a node off by one or a wrong weight is an error of order the step (~10%), the flux factor taken
  // back at the node's ρ instead of the current one ~5%.
  // bo1-fig05's 1:100 binary at ε = 0.5, off the grid (T ratios not on a node), with partner shapes a₂, a₃.
  const CollisionRates r = test::constant_rates(test::bo_binary(), 0.5);
  const std::vector<double> Tref = settled_temperatures(r).T;
  const GalerkinDecay decay(r, Tref);
  const double a2[2] = {0.03, -0.08}, a3[2] = {-0.01, 0.02};
  for (double ratio : {1.0, 7.3, 31.7, 92.1}) {
    const std::vector<double> T = {1.0, ratio};
    for (std::size_t k = 0; k < 2; ++k) {
      const Eigen::MatrixXd A = decay.collision_operator(k, T.data(), a2, a3), B = decay.collision_operator_exact(k, T.data(), a2, a3);
      INFO("T2/T1 = " << ratio << ", species " << k + 1);
      CHECK((A - B).norm() / B.norm() < 1e-4);
    }
  }
}

TEST_CASE("converged memory in time: a power-law mixture's interpolated operator is the direct assembly to 1e-5", "[theory]") {
  // v1 Fig. 8's power law cut at 16 species (n_k = 0.1 k^-3, m_k = k, σ_k = k^(1/3), ε = 0.5), partner shapes on, at
  // four states between the equal start and the settled ratios (T_k = T_ref,k^s): the steps of galerkin_decay.hpp —
  // 1/8, the smooth bases' 1/6, the coarse pairs' 1/4 — with the tables over √(λ + ρ). Measured 7.6e-6 of each
  // operator's largest entry (all at 1/8: 3.8e-6; the smooth bases at 1/5: 1.7e-5, which fails; at 1/8
  // without the flux factor 8.8e-6).
  model::PowerLaw p;
  p.n1_particles = 16 * 16 * 16;  // keeps k ≤ 16
  const model::Mixture mix = model::power_law_mixture(p);
  const std::size_t N = mix.size();
  REQUIRE(N == 16);
  const CollisionRates r(mix, model::Restitution::constant(N, 0.5), model::dilute_contact_values(N));
  const std::vector<double> Tref = settled_temperatures(r).T;
  const GalerkinDecay decay(r, Tref);
  const std::vector<double> a2(N, 0.05), a3(N, -0.02);
  double worst = 0.0;
  for (double s : {0.13, 0.37, 0.61, 0.89}) {
    std::vector<double> T(N);
    for (std::size_t k = 0; k < N; ++k) T[k] = std::pow(Tref[k], s);
    for (std::size_t k = 0; k < N; ++k) {
      const Eigen::MatrixXd A = decay.collision_operator(k, T.data(), a2.data(), a3.data());
      const Eigen::MatrixXd B = decay.collision_operator_exact(k, T.data(), a2.data(), a3.data());
      worst = std::max(worst, (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff());
    }
  }
  std::printf("power-law pair tables (16 species): worst entry %.2e of its operator's largest\n", worst);
  CHECK(worst < 1e-5);
}

TEST_CASE("converged memory in time: decays of one scene share their pair tables, others keep their own", "[theory]") {
  // The judged level and its `converged` companion hand one store to their decays (scene_theory.cpp): the second
  // decay finds the first one's nodes and computes none again; its operator is the unshared decay's exactly. A decay
  // built on other reference temperatures (another basis) must not read them: it gets tables of its own.
  const CollisionRates r = test::constant_rates(test::bo_binary(), 0.5);
  const std::vector<double> Tref = settled_temperatures(r).T;
  const auto store = std::make_shared<GalerkinPairTables>();
  const auto node_count = [&store] {
    std::size_t n = 0;
    for (const auto& pair : store->pairs) n += pair.size();
    return n;
  };
  const GalerkinDecay first(r, Tref, converged_diffusion_basis, store);
  const std::size_t nodes = node_count();
  CHECK(nodes > 0);
  const GalerkinDecay second(r, Tref, converged_diffusion_basis, store), alone(r, Tref);
  CHECK(node_count() == nodes);
  const std::vector<double> T = {1.0, 23.9};
  const double a2[2] = {0.03, -0.08}, a3[2] = {-0.01, 0.02};
  for (std::size_t k = 0; k < 2; ++k) CHECK((second.collision_operator(k, T.data(), a2, a3) - alone.collision_operator(k, T.data(), a2, a3)).norm() == 0.0);
  // Another basis: 10% hotter reference temperatures move x₀, and with it every table entry.
  const std::vector<double> hotter = {1.1 * Tref[0], Tref[1]};
  const GalerkinDecay other(r, hotter, converged_diffusion_basis, store), other_alone(r, hotter);
  CHECK(store->T_ref == Tref);
  for (std::size_t k = 0; k < 2; ++k) {
    const Eigen::MatrixXd A = other.collision_operator(k, T.data(), a2, a3), B = other_alone.collision_operator(k, T.data(), a2, a3);
    CHECK((A - B).norm() == 0.0);
    CHECK((A - alone.collision_operator(k, T.data(), a2, a3)).norm() > 1e-6 * B.norm());  // the bases do differ
  }
}

// [slow]: 31 s under ASan (two 16-species operators assembled directly at two states) for a check of a numerical choice;
// the sanitizers see the same pair kernel in the other tests of this file (CI's budget).
TEST_CASE("converged memory in time: the rare partners' coarse pair rule moves the operator by < 1e-5", "[theory][slow]") {
  // v1 Fig. 8's power law cut at 16 species (n_k = 0.1 k^-3, m_k = k, σ_k = k^(1/3), ε = 0.5): the partners whose share
  // of a species' collisions is below coarse_pair_share (k ≥ 12 or so for every species; 10× that for a species of a
  // smooth basis, x₀ ≥ 1.5: smooth_basis_share_factor) take the 20 × 12 rule. Each
  // species' operator, at the settled state and at the equal start (ρ = m_k/m_i, e^(3.7) from there), partner shapes
  // on, against every pair at its basis's rule (coarse share 0), relative to its largest entry: measured 6.8e-6 worst
  // (1.4e-6 without the smooth bases' factor; with a factor 30: 1.8e-5, which fails);
  // every pair at the coarse rule (share 1.1): 3.5e-4, which fails.
  model::PowerLaw p;
  p.n1_particles = 16 * 16 * 16;  // keeps k ≤ 16
  model::Mixture mix = model::power_law_mixture(p);
  const std::size_t N = mix.size();
  REQUIRE(N == 16);
  const CollisionRates r(mix, model::Restitution::constant(N, 0.5), model::dilute_contact_values(N));
  const std::vector<double> Tref = settled_temperatures(r).T, equal(N, 1.0);
  const GalerkinDecay coarse(r, Tref), fine(r, Tref, converged_diffusion_basis, nullptr, 0.0);
  std::vector<double> a2(N, 0.05), a3(N, -0.02);
  double worst = 0.0;
  for (const std::vector<double>* T : {&Tref, &equal})
    for (std::size_t k = 0; k < N; ++k) {
      const Eigen::MatrixXd A = coarse.collision_operator_exact(k, T->data(), a2.data(), a3.data());
      const Eigen::MatrixXd B = fine.collision_operator_exact(k, T->data(), a2.data(), a3.data());
      worst = std::max(worst, (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff());
    }
  std::printf("coarse rule for partners below %.0e of the collisions (%.0e for smooth bases): operator moves by %.2e of its largest entry\n",
              coarse_pair_share, coarse_pair_share * smooth_basis_share_factor, worst);
  CHECK(worst > 0.0);  // some pairs did take the coarse rule
  CHECK(worst < 1e-5);
}

TEST_CASE("converged memory in time: viscoelastic tables (ln theta_k and ln rho) are the direct assembly to 1e-4", "[theory]") {
  // v1 Fig. 10's law on its 1:100 binary, at temperatures six decades apart, off both grids; the grid in ln θ_k (step 2)
  // carries ε(u), which varies as θ^(1/10) (at step 1 it added ≤ 1.5e-6). Here with 4 functions (the tables' machinery
  // at half the cost): worst 1.5e-5 (2.0e-5 without the flux factor √(λ + ρ); 2.2e-5 at step 1). With the level's 8 (step 1): ≤ 1.6e-5 except
  // the light species at T₂/T₁ = 61.3, 5.5e-4 at every T₁ (the higher functions are rougher in ρ there; at constant ε
  // the same ratio gives < 1e-4). A wrong θ scaling (the tables are stored over √(2θ_k)) or a node off by one is an
  // error of order 1e-2 to 1.
  const CollisionRates r = test::viscoelastic_rates(test::bo_binary(), 0.09);
  const GalerkinDecay decay(r, settled_temperatures(r).T, 4);  // 4 functions: the tables' machinery at half the cost
  const double a2[2] = {0.03, -0.08}, a3[2] = {-0.01, 0.02};
  double worst = 0.0;
  for (double T1 : {0.93, 2.2e-7})  // six decades apart (each new T₁ costs 64 table nodes: 87 s under the sanitizers with four)
    for (double ratio : {1.0, 13.7, 61.3}) {
      const std::vector<double> T = {T1, ratio * T1};
      for (std::size_t k = 0; k < 2; ++k) {
        const Eigen::MatrixXd A = decay.collision_operator(k, T.data(), a2, a3), B = decay.collision_operator_exact(k, T.data(), a2, a3);
        INFO("T1 = " << T1 << ", T2/T1 = " << ratio << ", species " << k + 1);
        CHECK((A - B).norm() / B.norm() < 1e-4);
        worst = std::max(worst, (A - B).norm() / B.norm());
      }
    }
  std::printf("viscoelastic pair tables: worst relative error %.1e\n", worst);
}

namespace {

// The MSD of the forward ODE along a history that stays at settled ratios (Maxwellian closures from the Maxwellian
// settled temperatures: every ξ_k is the common ζ) against the settled memory's closed form (same basis, ζ, T).
void check_settled_history(double eps, double tol) {
  const CollisionRates r = test::constant_rates(test::bo_binary(), eps);
  const std::vector<double> T0 = settled_temperatures(r).T;
  TemperatureOptions opt;
  opt.vacf = true;
  opt.rtol = 1e-10;
  opt.decay = std::make_shared<GalerkinDecay>(r, T0);
  const double t_end = 1e4;
  const TemperatureHistory h(r, T0, t_end, opt);
  std::vector<double> xi(2);
  r.xi_all(T0.data(), xi.data());
  const double tau0 = xi[0] > 0.0 ? 2.0 / xi[0] : std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < 2; ++k) {
    GalerkinOptions g;
    g.zeta = xi[k];
    const TracerGalerkin p = tracer_galerkin(r, k, T0.data(), collision_weighted_basis(converged_diffusion_basis, converged_basis_x0(r, k, T0.data())), g);
    const VelocityMemory m = *galerkin_memory(p);
    for (double t : {0.01, 0.3, 3.0, 30.0, 300.0, 1e4}) {
      INFO("eps = " << eps << ", species " << k + 1 << ", t = " << t);
      CHECK(h.msd_vacf(t, k) == Approx(msd_increment(m, tau0, 0.0, t)).epsilon(tol));
    }
  }
}

}  // namespace

TEST_CASE("converged memory in time: at settled ratios the forward ODE is the settled memory's closed form", "[theory]") {
  // Duality: the forward moments (Aᵀ) and the adjoint problem (A) give the same correlation; the scaling term with
  // ξ_k and the read-out Q = U₀ are right only if the MSD matches at every time. A wrong sign of the scaling term
  // moves the ε = 0.5 MSD at t = 1e4 by tens of percent, a wrong source factor by the same factor.
  // The bound is the tables' interpolation (above; 1.8e-6 of the MSD at worst) and CVODE's rtol 1e-10.
  check_settled_history(1.0, 1e-5);
  check_settled_history(0.5, 1e-5);
  check_settled_history(0.2, 1e-5);
}

TEST_CASE("converged memory in time: its Jacobian-times-vector is the Q-derivative of its rates", "[theory]") {
  // The rates are affine in Q, so dQ(Q + v) − dQ(Q) is exactly Jv (GMRES's product in TemperatureHistory), for a
  // shaped, unsettled state of the binary (partners' a's on, one species far from its settled ratio). A wrong sign of
  // the scaling term, a missing ξ_k/2 or a stale operator would be off by O(1) of the entries.
  const CollisionRates r = test::constant_rates(test::bo_binary(), 0.5);
  const std::vector<double> Tref = settled_temperatures(r).T;
  const GalerkinDecay d(r, Tref);
  const std::size_t N = 2, n = N * d.modes();
  const double T[2] = {1.0, 7.0}, xi[2] = {0.3, 0.2}, a2[2] = {0.05, -0.1}, a3[2] = {-0.01, 0.02};
  std::vector<double> Q(n), v(n), dQ(n), dQv(n), Jv(n), nu(N);
  for (std::size_t j = 0; j < n; ++j) Q[j] = std::sin(1.0 + double(j)), v[j] = std::cos(2.0 * double(j));
  std::vector<double> Qv = Q;
  for (std::size_t j = 0; j < n; ++j) Qv[j] += v[j];
  d.correlation_rates(r, T, xi, Qv.data(), dQv.data(), nu.data(), a2, a3);
  d.correlation_rates(r, T, xi, Q.data(), dQ.data(), nu.data(), a2, a3);
  REQUIRE(d.offers_correlation_jacobian());
  d.correlation_jacobian_times(v.data(), Jv.data());
  double worst = 0.0, scale = 0.0;
  for (std::size_t j = 0; j < n; ++j) worst = std::max(worst, std::abs(dQv[j] - dQ[j] - Jv[j])), scale = std::max(scale, std::abs(Jv[j]));
  std::printf("Galerkin decay Jv against dQ(Q + v) - dQ(Q): %.1e of its largest entry %.3g\n", worst / scale, scale);
  CHECK(scale > 0.1);
  CHECK(worst < 1e-12 * scale);
}

TEST_CASE("converged memory in time: a pair keeps its nodes only while its stencil does - rates equal a fresh decay's", "[theory]") {
  // prefetch keeps the previous call's node pointers for every pair whose stencil has the same nodes, and looks up
  // the rest. Along a sequence of states that stays in a cell, moves to the next, jumps back and passes through a
  // one-species operator (the tests' collision_operator, which fills one species' pairs alone), the rates must be a
  // fresh decay's at the same state bit for bit; a pointer kept across a cell change is off by the change of a node
  // (~ the grid step, 12%, of the pair's sources).
  const CollisionRates r = test::constant_rates(test::bo_binary(), 0.5);
  const std::vector<double> Tref = settled_temperatures(r).T;
  const auto store = std::make_shared<GalerkinPairTables>();
  const GalerkinDecay kept(r, Tref, converged_diffusion_basis, store);
  const std::size_t N = 2, n = N * kept.modes();
  const double xi[2] = {0.3, 0.2}, a2[2] = {0.05, -0.1}, a3[2] = {-0.01, 0.02};
  std::vector<double> Q(n), dQ(n), fresh_dQ(n), nu(N);
  for (std::size_t j = 0; j < n; ++j) Q[j] = std::sin(1.0 + double(j));
  // T₂/T₁ = 7.0, 7.05 (same cell of ln ρ, step 1/8), 7.9 (the next), 7.0 again, then 31.7 after a one-species call.
  for (const double ratio : {7.0, 7.05, 7.9, 7.0, -1.0, 31.7}) {
    if (ratio < 0.0) {
      const double T[2] = {1.0, 15.0};
      (void)kept.collision_operator(1, T, a2, a3);
      continue;
    }
    const double T[2] = {1.0, ratio};
    kept.correlation_rates(r, T, xi, Q.data(), dQ.data(), nu.data(), a2, a3);
    const GalerkinDecay fresh(r, Tref, converged_diffusion_basis, store);
    fresh.correlation_rates(r, T, xi, Q.data(), fresh_dQ.data(), nu.data(), a2, a3);
    INFO("T2/T1 = " << ratio);
    CHECK(dQ == fresh_dQ);
  }
}

TEST_CASE("converged memory in time: GMRES with its own Jacobian-times-vector gives dense LU's history", "[theory]") {
  // TemperatureHistory's jtimes (the memory's block exact, ln T and the cumulants by a difference quotient, the
  // memory's dependence on T left out) only steers Newton: the solution is the same to CVODE's tolerance. From equal
  // temperatures (ratios move by 1e2 over the history, so the left-out block is not small); rtol 1e-10.
  const CollisionRates r = test::constant_rates(test::bo_ternary(), 0.5);
  const std::vector<double> T0(3, 1.0), Tref = settled_temperatures(r).T;
  TemperatureOptions opt;
  opt.vacf = true;
  opt.rtol = 1e-10;
  opt.decay = std::make_shared<GalerkinDecay>(r, Tref);
  opt.solver = TemperatureOptions::Solver::dense;
  const TemperatureHistory dense(r, T0, 1e4, opt);
  opt.solver = TemperatureOptions::Solver::gmres;
  const TemperatureHistory gmres(r, T0, 1e4, opt);
  double worst = 0.0;
  for (double t : {0.01, 0.3, 3.0, 30.0, 300.0, 1e4})
    for (std::size_t k = 0; k < 3; ++k) worst = std::max(worst, std::abs(gmres.msd_vacf(t, k) / dense.msd_vacf(t, k) - 1.0));
  std::printf("Galerkin decay history, GMRES with jtimes against dense LU: MSD %.1e; Newton iterations %ld against %ld, steps %ld against %ld, "
              "linear iterations %ld\n",
              worst, gmres.stats().nonlinear_iterations, dense.stats().nonlinear_iterations, gmres.stats().steps, dense.stats().steps,
              gmres.stats().linear_iterations);
  CHECK(gmres.stats().linear_iterations > 0);
  CHECK(worst < 1e-7);
}
