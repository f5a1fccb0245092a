#include "theory/grid/converged_hcs.hpp"

#include <Eigen/Dense>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "model/errors.hpp"
#include "theory/sonine/sonine_polynomials.hpp"
#include "theory/grid/speed_grid.hpp"

namespace granmix::theory {

namespace {

// The check's finer collision rule (the solve uses speed_grid_rule_points = 12; the rule covers the partners' velocities,
// the gain is exact over σ̂). On MG's 18 points of Figs. 4–5 (measured with the rule covering σ̂ too): 8 → 12 points
// move γ by up to 2.3e-4, 12 → 16 by ≤ 3e-5; knots 3/2 as far apart ≤ 1e-6.
constexpr std::size_t fine_rule_points = 16;
constexpr double wider_domain_widths = 9.0;  // the check's domain (the solve's: speed_grid_widths = 7)
constexpr int max_passes = 60;  // v1 Fig. 4 at n2 = 0.01 (T2/T1 = 169, the light species' a2 = 0.50, a3 = −0.61) takes 10
// Settled: 5–7 passes from the order-3 start for MG's binaries (settle's quasi-Newton); γ then moves by < 1e-7.
constexpr double settled_rates = 1e-8;   // |ζ_k − ζ_0| / τ_v,0⁻¹
constexpr double settled_shapes = 1e-7;  // the largest change of any a₂, a₃ in a pass

// How a species sees its partners: Maxwellians at T_j times 1 + a₂S₂ + a₃S₃ (the moments' solve), or that plus the rest
// of each partner's own solved density (speed_density_rest, following the passes, as fine as Settings::rest: the
// moments' truncation check and the settled distributions).
enum class Partners { sonine, full };

struct Settings {
  double widths;  // the grid spans U = widths √(T_k/m_k)
  double step_scale;
  const CollisionRule* rule;
  Partners partners;
  // Settled also once the residuals are this share of the first pass's (0: the absolute bounds alone). The checks'
  // variants start from the solved state, so their first residual is the size of the change they measure; at 1% it is
  // known to ~1% (the passes gain 10–30× each), one or two passes fewer than to 1e-8 (17 → 12
  // passes for v1 Fig. 7's four variants at ε = 0.5).
  double relative_stop = 0.0;
  RestResolution rest{};  // Partners::full: how finely the rests are taken
};

struct State {
  std::vector<double> T;  // T_0 stays where it started; ratios are what settles
  std::vector<PartnerShape> shapes;
  double zeta0 = 0.0;  // species 0's ζ at these T (code units)
  int passes = 0;
  Eigen::MatrixXd jacobian;  // settle's quasi-Newton matrix (empty: start from the Maxwellian one)
  std::vector<SpeedDensityRest> rest;  // Partners::full: each species' rest from the last pass (empty before the first)
  std::vector<std::pair<double, Eigen::VectorXd>> density;  // each species' knot step and density of the last pass (∫ = 1)
};

// Species k's stationary density at the cooling rate ζ for which its temperature is the T_k its partners were given.
struct SpeciesSolution {
  double zeta, a2, a3;
  SpeedDensityRest rest;  // Partners::full only
  double h;               // the density's knot step and coefficients, ∫ P du = 1 (code units)
  Eigen::VectorXd P;
};

// Why a species' grid operator can be singular, said in the mixture's terms: the partner that moves fastest against the
// species' own thermal speed, and the share of the energy it carries. Met where a rare heavy species runs away (the
// Santos–Dufty ordered phase: v1 Fig. 4's mixture at n₂ = 0.001, m₂/m₁ = 10⁴, ε = 0.3 — species 2 holds 99.8% of the
// energy and moves 2.4× as fast as species 1, whose grid spans 7 of its thermal widths).
std::string singular_grid(const CollisionRates& rates, const State& s, std::size_t k) {
  const model::Mixture& mix = rates.mixture();
  std::size_t fastest = k;
  double energy = 0.0;
  for (std::size_t j = 0; j < mix.size(); ++j) {
    energy += mix[j].density * s.T[j];
    if (s.T[j] / mix[j].mass > s.T[fastest] / mix[fastest].mass) fastest = j;
  }
  const std::string why = fmt::format("converged HCS: the speed grid's operator is singular for species {}", k + 1);
  if (fastest == k) return why;
  return why + fmt::format(" (species {} moves {:.3g}x as fast and holds {:.3g}% of the energy: a rare heavy species running away, the "
                           "Santos-Dufty ordered phase; its kicks leave species {}'s grid of {:g} thermal widths); level kinetic or "
                           "kinetic-converged computes this mixture",
                           fastest + 1, std::sqrt((s.T[fastest] / mix[fastest].mass) / (s.T[k] / mix[k].mass)),
                           100.0 * mix[fastest].density * s.T[fastest] / energy, k + 1, speed_grid_widths);
}

SpeciesSolution solve_species(const CollisionRates& rates, std::size_t k, const State& s, const Settings& set, double zeta_guess, double nu) {
  const model::Mixture& mix = rates.mixture();
  const double width = std::sqrt(s.T[k] / mix[k].mass);
  const double U = set.widths * width;  // the tracer limit's intruder grid (speed_grid.hpp)
  const auto K = std::size_t(std::ceil(set.widths * speed_grid_knots / set.step_scale));
  SpeedGrid grid;
  Eigen::MatrixXd collisions;
  SpeedGridProblem self{};
  for (std::size_t j = 0; j < mix.size(); ++j) {
    SpeedGridProblem p = speed_grid_pair(rates, k, j, s.T[j], s.shapes[j]);
    if (set.partners == Partners::full && !s.rest.empty()) p.rest = partner_rest_nodes(s.rest[j], s.T[j], set.rest);
    SpeedGrid g = assemble_speed_grid(p, U, K, *set.rule, SpeedGridParts::density);
    if (j == 0) {
      collisions = g.collisions, grid = std::move(g), self = p;
    } else {
      collisions += g.collisions;
    }
  }
  // θ_k(ζ) rises with ζ (the scaling's outward drift); secant on θ_k(ζ)/T_k − 1 from the guess.
  Eigen::VectorXd P;
  auto theta_at = [&](double zeta, SpeedMoments* m) {
    P = stationary_speed_density(collisions, grid, zeta);
    if (P.size() == 0) throw NumericalError(singular_grid(rates, s, k));
    const SpeedMoments r = speed_moments(grid, self, P);
    if (m != nullptr) *m = r;
    return r.theta / s.T[k] - 1.0;
  };
  double z0 = zeta_guess, z1 = zeta_guess + 1e-3 * nu;
  double f0 = theta_at(z0, nullptr);
  SpeedMoments m{};
  for (int it = 0; it < 60; ++it) {
    const double f1 = theta_at(z1, &m);
    // θ(ζ) carries the solve's rounding, ~1e-12 relative at strong dissipation (v1 Fig. 5, ε = 0.1: a secant to a tighter bound
    // wanders in it until it gives up); 1e-11 is far inside the passes' settled 1e-8.
    if (std::abs(f1) < 1e-11 || std::abs(z1 - z0) < 1e-13 * nu) {
      const Eigen::VectorXd density = P / grid.mass.dot(P);
      return {z1, m.a2, m.a3,
              set.partners == Partners::full ? speed_density_rest(grid.h, mix[k].mass, density, m, set.rest) : SpeedDensityRest{},
              grid.h, density};
    }
    if (f1 == f0) break;
    const double z2 = z1 - f1 * (z1 - z0) / (f1 - f0);
    z0 = z1, f0 = f1, z1 = z2;
  }
  throw NumericalError("converged HCS: no cooling rate gives species " + std::to_string(k) + " its temperature (secant in zeta did not settle)");
}

// The a₄ a rest carries (its S₄ moment over ⟨S₄²⟩_M = 315/128): how settle follows the rests from pass to pass.
double rest_a4(const SpeedDensityRest& rest, double mass) {
  double sum = 0.0;
  for (const auto& [u, m] : rest.masses) sum += m * sonine_S4(mass * u * u / (2.0 * rest.theta));
  return sum / (315.0 / 128.0);
}

// The Maxwellian rates' (v1 Eq. A2) Jacobian of the residuals r_k = (ξ_k − ξ_0)/ν in x_j = ln T_j (k, j ≥ 1): the
// quasi-Newton start.
Eigen::MatrixXd maxwellian_jacobian(const CollisionRates& rates, const std::vector<double>& T, double nu) {
  const std::size_t N = T.size(), n = N - 1;
  std::vector<double> xi(N), xp(N), Tp = T;
  rates.xi_all(T.data(), xi.data());
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  constexpr double h = 1e-6;
  for (std::size_t j = 1; j < N; ++j) {
    Tp = T, Tp[j] *= std::exp(h);
    rates.xi_all(Tp.data(), xp.data());
    for (std::size_t k = 1; k < N; ++k) J(Eigen::Index(k - 1), Eigen::Index(j - 1)) = ((xp[k] - xi[k]) - (xp[0] - xi[0])) / (h * nu);
  }
  return J;
}

// One quasi-Newton iteration for the whole state x = (ln T_k for k ≥ 1; a₂,k; a₃,k), residuals r = ((ζ_k − ζ_0)/ν for
// k ≥ 1; the solved a₂,k, a₃,k minus the partners' ones). Start: the Maxwellian block for the temperatures and −1 on the
// shapes (its first step is the plain pass: partners take the shapes just solved), Broyden's update after every pass —
// it learns how shapes and temperatures move each other, so the passes converge faster than linearly (MG Fig. 4, μ = 2:
// 9–12 passes with the shapes by plain substitution, 5–7 so; v1 Fig. 4 at n₂ = 0.01: 34 and 10).
State settle(const CollisionRates& rates, State s, const Settings& set) {
  const std::size_t N = s.T.size(), n = N - 1;
  const auto dim = Eigen::Index(n + 2 * N);
  std::vector<double> zeta(N), inv_tau(N);
  rates.xi_and_inv_tau_v_all(s.T.data(), zeta.data(), inv_tau.data());  // the first pass's guesses
  const double nu = inv_tau[0];
  if (s.jacobian.size() == 0) {
    s.jacobian = -Eigen::MatrixXd::Identity(dim, dim);
    if (n > 0) s.jacobian.topLeftCorner(Eigen::Index(n), Eigen::Index(n)) = maxwellian_jacobian(rates, s.T, nu);
  }
  Eigen::MatrixXd& J = s.jacobian;
  Eigen::VectorXd dx_prev, r_prev;
  double stop_rates = settled_rates, stop_shapes = settled_shapes, stop_rest = settled_shapes;
  // Partners::full from a state without rests (a Sonine-partners solve): its rests from the densities it holds, at the
  // temperatures and shapes it settled to (a pass with Sonine partners finds the same to ~1e-8).
  const bool full = set.partners == Partners::full;
  if (full && s.rest.empty()) {
    constexpr double unused = std::numeric_limits<double>::quiet_NaN();  // the gas side's moments: not read
    if (s.density.size() != N) throw std::logic_error("converged HCS: full partners need a solved state's densities");
    for (std::size_t k = 0; k < N; ++k)
      s.rest.push_back(speed_density_rest(s.density[k].first, rates.mixture()[k].mass, s.density[k].second,
                                          {s.T[k], s.shapes[k].a2, s.shapes[k].a3, unused, unused, unused}, set.rest));
  }
  std::vector<double> a4(N, 0.0);
  for (std::size_t k = 0; k < s.rest.size(); ++k) a4[k] = rest_a4(s.rest[k], rates.mixture()[k].mass);
  for (int pass = 1; pass <= max_passes; ++pass) {
    Eigen::VectorXd r(dim);
    std::vector<SpeedDensityRest> rest;
    double rest_moved = 0.0;
    s.density.clear();
    for (std::size_t k = 0; k < N; ++k) {
      SpeciesSolution sol = solve_species(rates, k, s, set, zeta[k], nu);
      zeta[k] = sol.zeta;
      s.density.emplace_back(sol.h, std::move(sol.P));
      r[Eigen::Index(n + k)] = sol.a2 - s.shapes[k].a2, r[Eigen::Index(n + N + k)] = sol.a3 - s.shapes[k].a3;
      if (full) {
        const double a4k = rest_a4(sol.rest, rates.mixture()[k].mass);
        rest_moved = std::max(rest_moved, std::abs(a4k - a4[k])), a4[k] = a4k;
        rest.push_back(std::move(sol.rest));
      }
    }
    if (full) s.rest = std::move(rest);  // the next pass's partners (substitution: the rests are small and follow)
    for (std::size_t k = 1; k < N; ++k) r[Eigen::Index(k - 1)] = (zeta[k] - zeta[0]) / nu;
    s.zeta0 = zeta[0], s.passes = pass;
    const double moved = r.tail(Eigen::Index(2 * N)).cwiseAbs().maxCoeff(), off = n == 0 ? 0.0 : r.head(Eigen::Index(n)).cwiseAbs().maxCoeff();
    if (pass == 1) {
      stop_rates = std::max(stop_rates, set.relative_stop * off), stop_shapes = std::max(stop_shapes, set.relative_stop * moved);
      stop_rest = std::max(stop_rest, set.relative_stop * rest_moved);
    }
    if (off < stop_rates && moved < stop_shapes && rest_moved <= stop_rest) {
      for (std::size_t k = 0; k < N; ++k) s.shapes[k].a2 += r[Eigen::Index(n + k)], s.shapes[k].a3 += r[Eigen::Index(n + N + k)];
      return s;
    }
    // Broyden
    if (dx_prev.size() != 0) J += ((r - r_prev) - J * dx_prev) * dx_prev.transpose() / dx_prev.squaredNorm();
    const Eigen::VectorXd dx = -J.fullPivLu().solve(r);
    if (!dx.allFinite()) throw NumericalError("converged HCS: the quasi-Newton step is not finite");
    for (std::size_t k = 1; k < N; ++k) s.T[k] *= std::exp(dx[Eigen::Index(k - 1)]);
    for (std::size_t k = 0; k < N; ++k) s.shapes[k].a2 += dx[Eigen::Index(n + k)], s.shapes[k].a3 += dx[Eigen::Index(n + N + k)];
    dx_prev = dx, r_prev = r;
  }
  throw NumericalError("converged HCS: the temperatures and shapes did not settle in " + std::to_string(max_passes) + " passes");
}

// How far another settled state b is from a: the largest relative difference of the T_k/T_0 (one species: of ζ at
// T_0), and of the a₂,k.
Change change(const State& a, const State& b) {
  Change d;
  if (a.T.size() == 1) d.T = std::abs(b.zeta0 / a.zeta0 - 1.0);
  for (std::size_t k = 1; k < a.T.size(); ++k) d.T = std::max(d.T, std::abs((b.T[k] / b.T[0]) / (a.T[k] / a.T[0]) - 1.0));
  for (std::size_t k = 0; k < a.T.size(); ++k) d.a2 = std::max(d.a2, std::abs(b.shapes[k].a2 / a.shapes[k].a2 - 1.0));
  return d;
}

Change larger(const Change& x, const Change& y) { return {std::max(x.T, y.T), std::max(x.a2, y.a2)}; }

// A settled state in MG's reduced form (sonine_hcs.hpp): Σ x_k T_k = 1; ζ scales as √T (hard spheres, constant ε).
SettledHcs reduced(const model::Mixture& mix, const State& s, const std::vector<double>& beta) {
  const std::size_t N = mix.size();
  double mean = 0.0;
  for (std::size_t k = 0; k < N; ++k) mean += mix.fraction(k) * s.T[k];
  const double m1 = mix[0].mass, m2 = mix[N > 1 ? 1 : 0].mass, v0sq = 2.0 * (m1 + m2) / (m1 * m2);
  const double nu_ref = mix.total_density() * std::pow(mix.sigma(0, N > 1 ? 1 : 0), 2) * std::sqrt(v0sq);
  SettledHcs out;
  SonineHcs& h = out.hcs;
  h.beta = beta;
  out.zeta = s.zeta0 / std::sqrt(mean);
  h.zeta_star = out.zeta / nu_ref;
  // v* = v/v₀ with v₀² = v0sq · mean in code units: P(v*) = v₀ P(v₀v*), knots h/v₀ apart.
  const double v0 = std::sqrt(v0sq * mean);
  for (std::size_t k = 0; k < N; ++k) {
    h.T.push_back(s.T[k] / mean);
    h.c.push_back(2.0 * s.shapes[k].a2);
    h.a3.push_back(s.shapes[k].a3);
    h.lambda.push_back(mix[k].mass * v0sq / (2.0 * h.T[k]));
    out.density.push_back({s.density[k].first / v0, v0 * s.density[k].second});
  }
  return out;
}

}  // namespace

double SpeedDensity::phi(double v) const { return speed_density_at(h, P, v) / (4.0 * std::numbers::pi * v * v); }

namespace {

void refuse_viscoelastic(const CollisionRates& rates) {
  if (rates.law().is_viscoelastic()) throw std::invalid_argument("converged HCS: constant restitution only (a viscoelastic mixture has no settled state)");
}

// The start of every solve: the order-3 Sonine HCS, which also gives β_k (the mixture's alone).
struct Start {
  State state;
  std::vector<double> beta;
};
Start sonine_start(const CollisionRates& rates) {
  refuse_viscoelastic(rates);
  const model::Mixture& mix = rates.mixture();
  const SonineHcs start = sonine_hcs(mix, rates.law(), rates.contact_values(), false, SonineSolver::automatic, 3);
  Start out{{}, start.beta};
  out.state.T = start.T;
  for (std::size_t k = 0; k < mix.size(); ++k) out.state.shapes.push_back({1.0, 0.5 * start.c[k], start.a3[k]});
  return out;
}

constexpr double to_change = 1e-2;  // each variant's change to ~1% (Settings::relative_stop)

}  // namespace

ConvergedHcs converged_hcs(const CollisionRates& rates, bool check) {
  const Start start = sonine_start(rates);
  const model::Mixture& mix = rates.mixture();
  // The moments alone: 3 speeds per knot interval (speed_grid.hpp; the distributions below keep 4).
  static const CollisionRule rule(speed_grid_rule_points, moment_collision_speeds), finer(fine_rule_points, moment_collision_speeds);
  const State best = settle(rates, start.state, {speed_grid_widths, 1.0, &rule, Partners::sonine});

  ConvergedHcs out;
  static_cast<SettledHcs&>(out) = reduced(mix, best, start.beta);
  out.passes = best.passes;
  if (check) {
    // Twice the largest change: the elastic limit (exact: equal temperatures) is missed by 1.3× it (MG μ = 4, δ = 0.25:
    // γ − 1 = 4.0e-5 against a change of 3.1e-5; test_converged_hcs.cpp; 3.1e-5 against 2.3e-5 with the σ̂ rule).
    // The domain 9/7 as wide (knots as far apart): where a species' tail is strongly overpopulated it matters more than
    // the knots and the rule — v1 Fig. 4 at n₂ = 0.01 (the light species' a₃ = −0.61): from U = 7 to 10 widths its c
    // moves by 1.8% and γ by 7.5e-4, where the knots and the rule alone gave an estimate of 0.30% and 9.3e-5; its D
    // ratio by 2e-5 (test "kinetic-converged-hcs: …"). Over MG's mixtures (α = 0.3): γ ≤ 2e-6.
    const State wider = settle(rates, best, {speed_grid_widths, 1.5, &rule, Partners::sonine, to_change});
    const State finer_rule = settle(rates, best, {speed_grid_widths, 1.0, &finer, Partners::sonine, to_change});
    const State wider_domain = settle(rates, best, {wider_domain_widths, 1.0, &rule, Partners::sonine, to_change});
    const State partners_full = settle(rates, best, {speed_grid_widths, 1.0, &rule, Partners::full, to_change});
    const Change g = larger(larger(change(best, wider), change(best, finer_rule)), change(best, wider_domain));
    out.grid_change = {2.0 * g.T, 2.0 * g.a2};
    out.partner_truncation = change(best, partners_full);
    out.grid_variants = {reduced(mix, wider, start.beta), reduced(mix, finer_rule, start.beta), reduced(mix, wider_domain, start.beta)};
    out.partners_full = reduced(mix, partners_full, start.beta);
  }
  return out;
}

namespace {

// The distributions' rule (converged_hcs.hpp) and its coarser variant: panels twice as wide, half the |w_⊥|² points.
// Against a finer reference (12 points per panel of half a width, 256 in |w_⊥|²) the rule errs by ≤ 2.5e-6 / 1.9e-4 of
// MG Fig. 3's Φ₁ / Φ₂, 2e-5 of Δ₁ and MG Fig. 7's G₁ (v* ≤ 1.2), and the coarser rule's change is larger at each of them:
// 5.6e-5 / 8.8e-4, 8.3e-4, 3.5e-5 (5 points per panel, 6 with 128 in |w_⊥|²: 1e-1, 1.6e-2 of Φ₂).
// The distributions' partners: each through its full solved density, its rest at 2 speeds per knot interval and 8
// directions; checked against 4 and 16. On MG Fig. 3 (against the level's Δ₁, Φ₁, Φ₂ with 2 and 4):
// the directions set it — 8 move Δ₁ at its zero crossing (v* = 0.525, Δ₁ = 0.026) by 5.8e-4, 16 by 5.6e-4 — and 4
// speeds move nothing beyond 4e-7 of Φ.
constexpr RestResolution distribution_rests{2, 8}, finer_rests{4, 16};
CollisionRule distribution_rule() { return CollisionRule(distribution_panel_points, distribution_panel_width, distribution_perp_points); }
CollisionRule distribution_rule_coarser() {
  return CollisionRule(distribution_panel_points, 2.0 * distribution_panel_width, distribution_perp_points / 2);
}

// The distributions' state of a mixture (distribution_rule()), solved once per process: the level and its four
// companions each ask for it, and under the sanitizers five solves would cost CI a minute (in a release build the MG
// scenes' theory takes ~2 s with one solve, 3.4 s with five). Keyed by CollisionRates::key(); the last few mixtures are kept.
struct DistributionState {
  Start start;
  State best;
};
struct DistributionStates {
  std::mutex guard;
  std::map<std::vector<double>, std::shared_ptr<const DistributionState>> solved;
};
DistributionStates& distribution_states() {
  static DistributionStates states;
  return states;
}
std::shared_ptr<const DistributionState> distribution_state(const CollisionRates& rates) {
  auto& [guard, solved] = distribution_states();
  const std::vector<double> key = rates.key();
  {
    const std::lock_guard<std::mutex> lock(guard);
    const auto found = solved.find(key);
    if (found != solved.end()) return found->second;
  }
  static const CollisionRule fine = distribution_rule();
  Start start = sonine_start(rates);
  // Sonine partners first (the quasi-Newton's start), then every partner through its full solved density.
  State best = settle(rates, start.state, {speed_grid_widths, 1.0, &fine, Partners::sonine});
  best = settle(rates, std::move(best), {speed_grid_widths, 1.0, &fine, Partners::full, 0.0, distribution_rests});
  auto state = std::make_shared<const DistributionState>(DistributionState{std::move(start), std::move(best)});
  const std::lock_guard<std::mutex> lock(guard);
  if (solved.size() >= 8) solved.clear();
  return solved.emplace(key, std::move(state)).first->second;
}

}  // namespace

void forget_converged_distributions() {
  DistributionStates& states = distribution_states();
  const std::lock_guard<std::mutex> lock(states.guard);
  states.solved.clear();
}

SettledHcs converged_distribution(const CollisionRates& rates, DistributionVariant variant) {
  refuse_viscoelastic(rates);
  const std::shared_ptr<const DistributionState> solved = distribution_state(rates);
  const Start& start = solved->start;
  const State& best = solved->best;
  static const CollisionRule fine = distribution_rule(), coarser = distribution_rule_coarser();
  switch (variant) {
    case DistributionVariant::solved: return reduced(rates.mixture(), best, start.beta);
    case DistributionVariant::sparser_knots:
      return reduced(rates.mixture(), settle(rates, best, {speed_grid_widths, 1.5, &fine, Partners::full, to_change, distribution_rests}), start.beta);
    case DistributionVariant::coarser_rule:
      return reduced(rates.mixture(), settle(rates, best, {speed_grid_widths, 1.0, &coarser, Partners::full, to_change, distribution_rests}), start.beta);
    case DistributionVariant::partners_finer:
      return reduced(rates.mixture(), settle(rates, best, {speed_grid_widths, 1.0, &fine, Partners::full, to_change, finer_rests}), start.beta);
    case DistributionVariant::wider_domain:
      return reduced(rates.mixture(), settle(rates, best, {wider_domain_widths, 1.0, &fine, Partners::full, to_change, distribution_rests}), start.beta);
  }
  throw std::invalid_argument("converged distribution: unknown variant");
}

}  // namespace granmix::theory
