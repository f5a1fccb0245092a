#include "theory/grid/speed_grid.hpp"

#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "model/errors.hpp"
#include "theory/numerics/parallel_each.hpp"
#include "theory/sonine/sonine_polynomials.hpp"
#include "theory/grid/sphere_gain.hpp"
#include "theory/numerics/vector_clones.hpp"

namespace granmix::theory {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
// The cardinal cubic B-spline on [0, 4] and its derivative.
double spline(double x) {
  if (x <= 0.0 || x >= 4.0) return 0.0;
  if (x > 2.0) x = 4.0 - x;
  if (x < 1.0) return x * x * x / 6.0;
  x -= 1.0;
  return (1.0 + 3.0 * x + 3.0 * x * x - 3.0 * x * x * x) / 6.0;
}
double spline_slope(double x) {
  if (x <= 0.0 || x >= 4.0) return 0.0;
  const double s = x > 2.0 ? -1.0 : 1.0;
  if (x > 2.0) x = 4.0 - x;
  if (x < 1.0) return s * x * x / 2.0;
  x -= 1.0;
  return s * (3.0 + 6.0 * x - 9.0 * x * x) / 6.0;
}

const GaussRule& speed_rule() {
  static const GaussRule uq = legendre(speed_grid_interval_points, 0.0, 1.0);
  return uq;
}

// The integrals of the trial functions i … i + 3 (nonzero on knot interval i) against 1, u², u⁴, u⁶, G, H, u, G₄.
// And the drift, Gram and u-weighted Gram entries of interval i, test function i + r (rows) against trial i + c: a 4 × 4
// block each (the test functions nonzero there).
struct IntervalMoments {
  double m[4][8] = {};
  double drift[4][4] = {}, gram[4][4] = {}, gram_u[4][4] = {};
};

// The gas velocities w = (w_x, 0, w_z) and their weights (shape and rate included): the same for every u.
struct GasNode {
  double w_z, w_x, weight;
};

// The product rule's nodes below this share of its largest weight are left out: the tails of both rules, whose weights
// fall to 1e-17 (12 points: 18 of 144 nodes; 16: 58 of 256; 64: 3160 of 4096), carry together
// ≤ 1.3e-14 of the collisions' rate (weights times |w|, 12 points; 6e-14 for 64), so the grids move at rounding level
// while the assembly, whose cost is per node, sheds 12–77% of them.
constexpr double negligible_node = 1e-14;

std::vector<GasNode> gas_nodes(const SpeedGridProblem& p, const CollisionRule& rule) {
  const GaussRule &wz = rule.wz, &wp = rule.wp;
  std::vector<GasNode> gas;
  gas.reserve(wz.x.size() * wp.x.size() + p.rest.size());
  double largest = 0.0;
  for (std::size_t a = 0; a < wz.x.size(); ++a)
    for (std::size_t b = 0; b < wp.x.size(); ++b) {
      const double x = 0.5 * wz.x[a] * wz.x[a] + wp.x[b];  // m₁w²/(2T₁)
      const double shape = p.gas.one + p.gas.a2 * sonine_S2(x) + p.gas.a3 * sonine_S3(x);
      gas.push_back({p.sd_gas * wz.x[a], p.sd_gas * std::sqrt(2.0 * wp.x[b]), wz.weight[a] * wp.weight[b] * shape * p.rate});
      largest = std::max(largest, std::abs(gas.back().weight));
    }
  std::erase_if(gas, [&](const GasNode& g) { return std::abs(g.weight) < negligible_node * largest; });
  for (const PartnerNode& r : p.rest) gas.push_back({r.w_z, r.w_x, r.weight * p.rate});
  return gas;
}

// The partner nodes of a panel rule at the intruder's speed u (speed_grid.hpp: w_z cut at the integrand's kinks
// (i)–(iii)), into `gas` (its capacity reused from one u to the next); `z` holds the w_z nodes in the partner's widths
// with their weights. Pruned as gas_nodes, on the product of the two rules' weights (the Gaussian's, the shape apart):
// the |w_⊥|² loop stops where no later Laguerre weight can reach the threshold.
void panel_gas_nodes(const SpeedGridProblem& p, const CollisionRule& rule, double u, std::vector<GasNode>& gas,
                     std::vector<std::array<double, 2>>& z) {
  const double reach = wz_panels_reach, sd = p.sd_gas, beta = p.beta;
  std::array<double, 5> cuts{-reach, -(1.0 - beta) * u / (beta * sd), u / sd, -(2.0 - beta) * u / (beta * sd), reach};
  for (std::size_t k = 1; k + 1 < cuts.size(); ++k) cuts[k] = std::clamp(cuts[k], -reach, reach);
  std::sort(cuts.begin(), cuts.end());
  const GaussRule& unit = rule.panels.unit;
  const double norm = 1.0 / std::sqrt(2.0 * std::numbers::pi);
  z.clear();
  double largest_z = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = cuts[k], length = cuts[k + 1] - a;
    const auto n = std::size_t(std::ceil(length / rule.panels.width));
    if (n == 0) continue;  // two cuts coincide
    const double w = length / double(n);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t t = 0; t < unit.x.size(); ++t) {
        const double x = a + (double(j) + unit.x[t]) * w;
        z.push_back({x, unit.weight[t] * w * norm * std::exp(-0.5 * x * x)});
        largest_z = std::max(largest_z, z.back()[1]);
      }
  }
  const GaussRule& wp = rule.wp;
  const std::vector<double>& later = rule.panels.later_perp_weight;
  const double threshold = negligible_node * largest_z * later[0];
  gas.clear();
  for (const auto& [x0, w0] : z)
    for (std::size_t b = 0; b < wp.x.size() && w0 * later[b] >= threshold; ++b) {
      const double weight = w0 * wp.weight[b];
      if (weight < threshold) continue;
      const double x = 0.5 * x0 * x0 + wp.x[b];
      const double shape = p.gas.one + p.gas.a2 * sonine_S2(x) + p.gas.a3 * sonine_S3(x);
      gas.push_back({sd * x0, sd * std::sqrt(2.0 * wp.x[b]), weight * shape * p.rate});
    }
  for (const PartnerNode& r : p.rest) gas.push_back({r.w_z, r.w_x, r.weight * p.rate});
}

// Each gas node's collision sphere at one u, one array per field: the first loop over the nodes has no branch and no
// scattered store, so the compiler runs it on vector registers (square roots and divisions two at a time, four in the
// AVX2/AVX-512 builds of density_interval and full_interval); the second
// adds the ranges to the gains. (One loop doing both keeps every square root and division scalar; with the sums'
// layout of sphere_gain.hpp, v1 Fig. 7's judged level takes 3.1 s on one thread against that loop's 4.5 s.)
struct Spheres {
  std::vector<double> lo, hi, total, speed_w, l1_w0, l1_w2, l1_point;
  void fit(std::size_t n, bool full) {  // room for n nodes (only ever grows)
    for (std::vector<double>* a : {&lo, &hi, &total, &speed_w}) a->resize(std::max(a->size(), n));
    if (full)
      for (std::vector<double>* a : {&l1_w0, &l1_w2, &l1_point}) a->resize(std::max(a->size(), n));
  }
};
// Each thread's arrays for the nodes, kept from one interval and one assembly to the next: allocated per interval, the
// panel rule's (~7000 nodes, 0.4 MB) cost more in memset and page faults than the intervals' arithmetic (a test of MG
// Fig. 7's distributions: 1.5 s kept, 8 s allocated per interval).
struct NodeWork {
  std::vector<GasNode> gas;  // a panel rule's nodes at one u
  std::vector<std::array<double, 2>> z;
  Spheres spheres;
};
NodeWork& node_work() {
  thread_local NodeWork work;
  return work;
}

// Knot interval i: the collision columns of its four trial functions (rows every test function), its drift and Gram
// blocks. full: also the l = 1 harmonic's collisions and G, H, G₄ (SpeedGridParts::all); otherwise the speed density's
// alone. Every σ̂ integral is exact (sphere_gain.hpp: v′ uniform on a sphere of radius R about c); the partner's
// velocities w go through the collision rule, the speeds u of the collision integrals through its uq (CollisionRule::
// speeds), the splines' polynomial integrals through speed_rule. The loss term N_m(u) Σ w is the same spline values for
// every gas velocity, so it is subtracted once per u.
template <bool full>
[[gnu::always_inline]] inline void interval(const SpeedGridProblem& p, const std::vector<GasNode>& fixed_gas, const CollisionRule& rule,
                                            double h, std::size_t i, Eigen::Ref<Eigen::MatrixXd> coll, Eigen::Ref<Eigen::MatrixXd> coll1,
                                            IntervalMoments& out) {
  const GaussRule& uq = rule.speeds;
  const bool panels = !rule.panels.unit.x.empty();
  const std::size_t nb = std::size_t(coll.rows());
  SphereGain gain(nb, h), gain1(full ? nb : 0, h);
  NodeWork& work = node_work();
  const double beta = p.beta, mass_ratio = p.m2 / p.m1, pi = std::numbers::pi;
  for (std::size_t q = 0; q < uq.x.size(); ++q) {
    const double u = (double(i) + uq.x[q]) * h, wu = uq.weight[q] * h;
    if (panels) panel_gas_nodes(p, rule, u, work.gas, work.z);
    const std::vector<GasNode>& gas = panels ? work.gas : fixed_gas;
    const std::size_t nodes = gas.size();
    work.spheres.fit(nodes, full);
    double* __restrict lo = work.spheres.lo.data();
    double* __restrict hi = work.spheres.hi.data();
    double* __restrict total_of = work.spheres.total.data();
    double* __restrict speed_w = work.spheres.speed_w.data();
    double* __restrict l1_w0 = work.spheres.l1_w0.data();
    double* __restrict l1_w2 = work.spheres.l1_w2.data();
    double* __restrict l1_point = work.spheres.l1_point.data();
    // C_m(u) = ∫dw f_gas ∫dσ̂ rate (g·σ̂)Θ [N_m(|v′|) − N_m(u)]; G(u), H(u) the same average of the gas's energy gain and of u·Δv.
    gain.clear();
    if constexpr (full) gain1.clear();
    double G = 0.0, H = 0.0, G4 = 0.0, lost = 0.0;
    for (std::size_t a = 0; a < nodes; ++a) {
      const double w_x = gas[a].w_x, w_z = gas[a].w_z;
      const double gx = -w_x, gz = u - w_z, g = std::sqrt(gx * gx + gz * gz);
      const double total = gas[a].weight * g * pi;  // ∫(g·σ̂)Θ dσ̂ = πg (0 where g = 0: no collision)
      lost += total;
      // The sphere of v′ (v along z): centre c = v − βg/2, radius R = βg/2. The speed density's weight
      // total/(2|c|R) = weight π/(β|c|).
      const double R = 0.5 * beta * g, cx = -0.5 * beta * gx, cz = u - 0.5 * beta * gz, c = std::sqrt(cx * cx + cz * cz);
      lo[a] = std::abs(c - R), hi[a] = c + R, total_of[a] = total, speed_w[a] = total / (2.0 * c * R);
      if constexpr (full) {
        // ⟨v̂·v̂′⟩ on the circle |v′| = s: (ĉ_z)(s² + |c|² − R²)/(2|c|s); with the density s/(2|c|R). A point sphere:
        // ⟨v′_z⟩ = c_z at |v′| = |c| + R.
        const double A = total * (cz / c) / (4.0 * c * c * R);
        l1_w0[a] = A * (c * c - R * R), l1_w2[a] = A, l1_point[a] = total * cz / (c + R);
        // v′ − v = R(n − ĝ) and the gas's w′ − w = κ(ĝ − n), κ = (m₂/m₁)R, n uniform on the unit sphere:
        // ⟨Δv_z⟩ = −R ĝ_z; ⟨|w′|² − |w|²⟩ = 2κ w·ĝ + 2κ²; ⟨(|w′|² − |w|²)²⟩ = that² + (4/3)κ²|w + κĝ|².
        const double inv_g = 1.0 / (g > 0.0 ? g : 1.0);  // g = 0: total = 0 and every term with it
        const double kappa = mass_ratio * R, w_g = (w_x * gx + w_z * gz) * inv_g, dw2 = 2.0 * kappa * (w_g + kappa);
        const double bx = w_x + kappa * gx * inv_g, bz = w_z + kappa * gz * inv_g, ww = w_x * w_x + w_z * w_z;
        H += total * (-u * R * gz * inv_g);
        G += total * 0.5 * p.m1 * dw2;
        G4 += total * (2.0 * ww * dw2 + dw2 * dw2 + 4.0 / 3.0 * kappa * kappa * (bx * bx + bz * bz));
      }
    }
    for (std::size_t a = 0; a < nodes; ++a) {
      if (total_of[a] == 0.0) continue;
      if (hi[a] - lo[a] < 2e-9 * h) {  // 2 min(|c|, R): the sphere is a point
        gain.add_point(hi[a], total_of[a]);
        if constexpr (full) gain1.add_point(hi[a], l1_point[a]);
      } else {
        gain.add_range(lo[a], hi[a], {0.0, speed_w[a], 0.0});
        if constexpr (full) gain1.add_range(lo[a], hi[a], {l1_w0[a], 0.0, l1_w2[a]});
      }
    }
    std::vector<double>& C = gain.finish();
    std::vector<double>& C1 = gain1.finish();  // empty work when !full (no splines)
    for (std::size_t j = i; j <= i + 3; ++j) {  // the loss: every collision takes the density away from u
      const double N = lost * spline(u / h - double(j) + 3.0);
      C[j] -= N;
      if constexpr (full) C1[j] -= N;
    }
    for (std::size_t c = 0; c < 4; ++c) {  // trial function i + c
      const double Nj = spline(u / h - double(i + c) + 3.0) * wu;
      out.m[c][4] += Nj * G, out.m[c][5] += Nj * H, out.m[c][7] += Nj * G4;
      for (std::size_t m = 0; m < nb; ++m) coll(Eigen::Index(m), Eigen::Index(c)) += Nj * C[m];
      if constexpr (full)
        for (std::size_t m = 0; m < nb; ++m) coll1(Eigen::Index(m), Eigen::Index(c)) += Nj * C1[m];
    }
  }
  const GaussRule& poly = speed_rule();  // the integrals of splines times powers of u
  for (std::size_t q = 0; q < poly.x.size(); ++q) {
    const double u = (double(i) + poly.x[q]) * h, wu = poly.weight[q] * h;
    for (std::size_t c = 0; c < 4; ++c) {  // trial function i + c
      const double Nj = spline(u / h - double(i + c) + 3.0) * wu;
      for (int n = 0; n < 4; ++n) out.m[c][n] += Nj * std::pow(u, 2 * n);
      out.m[c][6] += Nj * u;
      for (std::size_t r = 0; r < 4; ++r) {  // test functions i + r, nonzero at u
        const double Nm = spline(u / h - double(i + r) + 3.0);
        out.drift[r][c] += Nj * u * spline_slope(u / h - double(i + r) + 3.0) / h;
        out.gram[r][c] += Nj * Nm, out.gram_u[r][c] += Nj * Nm * u;
      }
    }
  }
}

}  // namespace

GaussRule legendre(std::size_t n, double a, double b) {
  gsl_integration_glfixed_table* t = gsl_integration_glfixed_table_alloc(n);
  if (t == nullptr) throw NumericalError("tracer speed grid: gsl_integration_glfixed_table_alloc failed");
  GaussRule r;
  for (std::size_t j = 0; j < n; ++j) {
    double x = 0.0, w = 0.0;
    if (gsl_integration_glfixed_point(a, b, j, &x, &w, t) != 0) {
      gsl_integration_glfixed_table_free(t);
      throw NumericalError("tracer speed grid: gsl_integration_glfixed_point failed");
    }
    r.x.push_back(x), r.weight.push_back(w);
  }
  gsl_integration_glfixed_table_free(t);
  return r;
}

CollisionRule::CollisionRule(std::size_t n, std::size_t speeds_per_interval)
    : wz(golub_welsch(n, false)), wp(golub_welsch(n, true)), speeds(legendre(speeds_per_interval, 0.0, 1.0)) {}

CollisionRule::CollisionRule(std::size_t points, double width, std::size_t perp)
    : wp(golub_welsch(perp, true)), speeds(legendre(speed_grid_interval_points, 0.0, 1.0)), panels{legendre(points, 0.0, 1.0), width, {}} {
  if (!(width > 0.0)) throw std::invalid_argument("collision rule: the panels' width must be positive");
  panels.later_perp_weight = wp.weight;
  for (std::size_t b = wp.weight.size(); b-- > 1;)
    panels.later_perp_weight[b - 1] = std::max(panels.later_perp_weight[b - 1], panels.later_perp_weight[b]);
}

SpeedGridProblem speed_grid_pair(const CollisionRates& rates, std::size_t k, std::size_t j, double Tj, const PartnerShape& partner) {
  const model::Mixture& mix = rates.mixture();
  const double s = mix.sigma(k, j), mj = mix[j].mass, mk = mix[k].mass;
  return {mj, mk, std::sqrt(Tj / mj), mj * (1.0 + rates.law().eps(k, j)) / (mj + mk), mix[j].density * s * s * rates.chi(k, j), partner, {}};
}

SpeedGridProblem speed_grid_problem(const CollisionRates& rates, const PartnerShape& gas) { return speed_grid_pair(rates, 1, 0, 1.0, gas); }

Eigen::VectorXd stationary_speed_density(const Eigen::MatrixXd& collisions, const SpeedGrid& g, double zeta) {
  const double U = g.h * double(g.edge.size() - 3);
  Eigen::MatrixXd A = collisions + 0.5 * zeta * (g.drift - U * g.edge * g.edge.transpose());
  const auto last = A.rows() - 1;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(A.rows());
  A.row(last) = g.mass.transpose(), rhs[last] = 1.0;
  // Partial pivoting: the converged HCS solves this at every secant step (full pivoting takes 9% of v1 Fig. 4's judged
  // level). Singular: the reciprocal condition estimate at rounding level, or a solution that is not finite.
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  if (!(lu.rcond() > double(A.rows()) * std::numeric_limits<double>::epsilon())) return {};
  Eigen::VectorXd P = lu.solve(rhs);
  if (!P.allFinite()) return {};
  return P;
}

// The two kinds of interval, each built for AVX2 and AVX-512 too (vector_clones.hpp: this file has no FMA contraction,
// so every build gives the same numbers; byte-identical outputs measured on v1 Fig. 7, ~9% faster on one thread).
GRANMIX_VECTOR_CLONES void density_interval(const SpeedGridProblem& p, const std::vector<GasNode>& gas, const CollisionRule& rule, double h,
                                            std::size_t i, Eigen::Ref<Eigen::MatrixXd> coll, Eigen::Ref<Eigen::MatrixXd> coll1,
                                            IntervalMoments& out) {
  interval<false>(p, gas, rule, h, i, coll, coll1, out);
}
GRANMIX_VECTOR_CLONES void full_interval(const SpeedGridProblem& p, const std::vector<GasNode>& gas, const CollisionRule& rule, double h,
                                         std::size_t i, Eigen::Ref<Eigen::MatrixXd> coll, Eigen::Ref<Eigen::MatrixXd> coll1,
                                         IntervalMoments& out) {
  interval<true>(p, gas, rule, h, i, coll, coll1, out);
}

SpeedGrid assemble_speed_grid(const SpeedGridProblem& p, double U, std::size_t K, const CollisionRule& rule, SpeedGridParts parts) {
  const double h = U / double(K);
  const bool full = parts == SpeedGridParts::all;
  const std::size_t nb = K + 3;  // N_j(u) = spline(u/h − j + 3), j = 0 … K + 2
  const auto n = Eigen::Index(nb);
  Eigen::MatrixXd coll = Eigen::MatrixXd::Zero(n, Eigen::Index(4 * K));
  Eigen::MatrixXd coll1 = full ? coll : Eigen::MatrixXd::Zero(n, 0);
  std::vector<IntervalMoments> moments(K);
  const std::vector<GasNode> gas = rule.panels.unit.x.empty() ? gas_nodes(p, rule) : std::vector<GasNode>{};  // panels: per u
  parallel_each(K, [&](std::size_t i) {
    const auto cols = Eigen::Index(4 * i);
    auto c1 = full ? coll1.middleCols(cols, 4) : coll1.middleCols(0, 0);
    if (full)
      full_interval(p, gas, rule, h, i, coll.middleCols(cols, 4), c1, moments[i]);
    else
      density_interval(p, gas, rule, h, i, coll.middleCols(cols, 4), c1, moments[i]);
  });
  SpeedGrid g;
  g.h = h;
  g.collisions = g.drift = g.gram = g.gram_u = Eigen::MatrixXd::Zero(n, n);
  g.mass = g.u2 = g.u4 = g.u6 = g.u1 = Eigen::VectorXd::Zero(n);
  if (full) g.collisions_p1 = g.collisions, g.gain = g.drag = g.gain4 = g.mass;
  Eigen::VectorXd* integrals[8] = {&g.mass, &g.u2, &g.u4, &g.u6, &g.gain, &g.drag, &g.u1, &g.gain4};
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t c = 0; c < 4; ++c) {
      const auto J = Eigen::Index(i + c), col = Eigen::Index(4 * i + c);
      g.collisions.col(J) += coll.col(col);
      for (std::size_t r = 0; r < 4; ++r) {
        const auto M = Eigen::Index(i + r);
        g.drift(M, J) += moments[i].drift[r][c], g.gram(M, J) += moments[i].gram[r][c], g.gram_u(M, J) += moments[i].gram_u[r][c];
      }
      if (full) g.collisions_p1.col(J) += coll1.col(col);
      for (int m = 0; m < 8; ++m)
        if (integrals[m]->size() != 0) (*integrals[m])[J] += moments[i].m[c][m];
    }
  g.edge = Eigen::VectorXd::Zero(n);
  for (std::size_t j = K; j < nb; ++j) g.edge[Eigen::Index(j)] = spline(double(K) - double(j) + 3.0);
  return g;
}

SpeedMoments speed_moments(const SpeedGrid& g, const SpeedGridProblem& p, const Eigen::VectorXd& P) {
  const double norm = g.mass.dot(P), u2 = g.u2.dot(P) / norm, u4 = g.u4.dot(P) / norm, u6 = g.u6.dot(P) / norm;
  // Cumulants at the density's own temperature: c² = u² m₂/(2θ), ⟨c²⟩ = 3/2, a_p = ⟨S_p(c²)⟩/⟨S_p²⟩_M (docs/physics.md §6;
  // S₂, S₃ of sonine_polynomials.hpp expanded in the moments, ⟨S₂²⟩_M = 15/8, ⟨S₃²⟩_M = 35/16).
  const double theta = p.m2 * u2 / 3.0, s = p.m2 / (2.0 * theta), x2 = u4 * s * s, x3 = u6 * s * s * s;
  if (g.gain.size() == 0)  // SpeedGridParts::density: the gas's side and the drag were not assembled
    return {theta, 0.6 * x2 / (1.5 * 1.5) - 1.0, (-x3 / 6.0 + 1.75 * x2 - 35.0 / 8.0 * 1.5 + 35.0 / 16.0) / (35.0 / 16.0), nan, nan, nan};
  return {theta, 0.6 * x2 / (1.5 * 1.5) - 1.0, (-x3 / 6.0 + 1.75 * x2 - 35.0 / 8.0 * 1.5 + 35.0 / 16.0) / (35.0 / 16.0),
          g.gain.dot(P) / norm, -g.drag.dot(P) / (norm * u2), g.gain4.dot(P) / norm};
}

SpeedDensityRest speed_density_rest(double h, double m, const Eigen::VectorXd& P, const SpeedMoments& r, const RestResolution& res) {
  const GaussRule uq = legendre(res.speeds, 0.0, 1.0);
  const std::size_t K = std::size_t(P.size()) - 3;
  const double a = m / (2.0 * r.theta), maxwell = 4.0 * std::numbers::pi * std::pow(a / std::numbers::pi, 1.5);
  SpeedDensityRest out{r.theta, {}};
  double largest = 0.0;
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t q = 0; q < uq.x.size(); ++q) {
      const double u = (double(i) + uq.x[q]) * h, x = a * u * u;
      const double sonine = maxwell * u * u * std::exp(-x) * (1.0 + r.a2 * sonine_S2(x) + r.a3 * sonine_S3(x));
      const double mass = (speed_density_at(h, P, u) - sonine) * uq.weight[q] * h;
      out.masses.push_back({u, mass}), largest = std::max(largest, std::abs(mass));
    }
  std::erase_if(out.masses, [&](const std::array<double, 2>& e) { return std::abs(e[1]) < 1e-8 * largest; });
  return out;
}

double speed_density_at(double h, const Eigen::VectorXd& P, double u) {
  const double x = u / h;
  if (!(x >= 0.0) || x >= double(P.size() - 3)) return 0.0;
  const auto i = std::size_t(x);
  double density = 0.0;
  for (std::size_t j = i; j <= i + 3; ++j) density += P[Eigen::Index(j)] * spline(x - double(j) + 3.0);
  return density;
}

std::vector<PartnerNode> partner_rest_nodes(const SpeedDensityRest& rest, double T, const RestResolution& res) {
  const GaussRule angles = legendre(res.directions, -1.0, 1.0);
  const double scale = std::sqrt(T / rest.theta);
  std::vector<PartnerNode> nodes;
  nodes.reserve(rest.masses.size() * angles.x.size());
  for (const auto& [w, mass] : rest.masses)
    for (std::size_t q = 0; q < angles.x.size(); ++q) {
      const double mu = angles.x[q];
      nodes.push_back({w * scale * std::sqrt(1.0 - mu * mu), w * scale * mu, mass * 0.5 * angles.weight[q]});
    }
  return nodes;
}

Eigen::VectorXd maxwellian_speed_density(const SpeedGrid& g, double m2, double theta) {
  const GaussRule& uq = speed_rule();
  const std::size_t nb = std::size_t(g.gram.rows()), K = nb - 3;
  const double a = m2 / (2.0 * theta), norm = 4.0 * std::numbers::pi * std::pow(a / std::numbers::pi, 1.5);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(nb));
  for (std::size_t i = 0; i < K; ++i)
    for (std::size_t q = 0; q < uq.x.size(); ++q) {
      const double u = (double(i) + uq.x[q]) * g.h, f = norm * u * u * std::exp(-a * u * u) * uq.weight[q] * g.h;
      for (std::size_t m = i; m <= i + 3; ++m) rhs[Eigen::Index(m)] += f * spline(u / g.h - double(m) + 3.0);
    }
  return g.gram.ldlt().solve(rhs);
}

}  // namespace granmix::theory
