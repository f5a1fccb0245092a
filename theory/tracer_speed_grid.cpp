#include "tracer_speed_grid.hpp"

#include <gsl/gsl_integration.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <numbers>

#include "model/errors.hpp"
#include "parallel_each.hpp"
#include "sonine_polynomials.hpp"

namespace granmix::theory {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t speed_points = 4;  // Gauss–Legendre points in u per knot interval (exact for the Gram matrix)
// The kernel's per-(gas velocity, cos θ) buffer of speeds: CollisionRule(n) folds ⌊3n/4⌋ azimuths into pairs, ≤ 64 up
// to n = 171 (the rules in use: 12 and 16).
constexpr std::size_t max_azimuth_pairs = 64;
constexpr std::size_t max_rule_points = (4 * 2 * max_azimuth_pairs + 3) / 3;

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
// The four splines nonzero at x = j₀ + t (0 ≤ t < 1): N(x − j₀ + 3 − c) for c = 0 … 3, i.e. the value spline(x − j + 3)
// of j = j₀ + c — spline's four pieces at once.
void splines_at(double t, double out[4]) {
  const double r = 1.0 - t, t2 = t * t, t3 = t2 * t;
  out[0] = r * r * r / 6.0;
  out[1] = (4.0 - 6.0 * t2 + 3.0 * t3) / 6.0;
  out[2] = (1.0 + 3.0 * t + 3.0 * t2 - 3.0 * t3) / 6.0;
  out[3] = t3 / 6.0;
}

// The collision's gain without an angular rule (the speed density's; the l = 1 harmonic and the gas's side keep the
// rule). For hard spheres the post-collision velocity v′ = v − β(g·σ̂)σ̂, weighted by (g·σ̂)Θ dσ̂, is uniform on a sphere
// of radius R = βg/2 about c = v − βg/2 (with χ = 2θ the angle to ĝ: (ĝ·σ̂)dσ̂ = dΩ_χ/4, total π); so |v′|² is uniform
// on [(|c| − R)², (|c| + R)²] and the speed |v′| = s has the density s/(2|c|R) there. The gain into test function N_m is
// then (1/(2|c|R)) ∫ N_m(s) s ds over that range: exact piecewise polynomials, where the 12-point rule's 30 folded σ̂
// directions sampled a cubic spline across ~10 knot intervals.
// With s = h(q + t) on knot interval q, the four splines there (splines_at) integrate to h²[q P_e(t) + Q_e(t)],
// P_e(t) = ∫₀ᵗ N_e, Q_e(t) = ∫₀ᵗ τ N_e(τ) dτ.
void spline_moments_to(double t, double P[4], double Q[4]) {
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t, r = 1.0 - t;
  P[0] = (1.0 - r * r * r * r) / 24.0, P[1] = (4.0 * t - 2.0 * t3 + 0.75 * t4) / 6.0;
  P[2] = (t + 1.5 * t2 + t3 - 0.75 * t4) / 6.0, P[3] = t4 / 24.0;
  Q[0] = (0.5 * t2 - t3 + 0.75 * t4 - 0.2 * t5) / 6.0, Q[1] = (2.0 * t2 - 1.5 * t4 + 0.6 * t5) / 6.0;
  Q[2] = (0.5 * t2 + t3 + 0.75 * t4 - 0.6 * t5) / 6.0, Q[3] = 0.2 * t5 / 6.0;
}

// P_e(1) and Q_e(1): a whole knot interval.
const std::array<double, 8>& whole_interval_moments() {
  static const auto full = [] {
    std::array<double, 8> pq{};
    spline_moments_to(1.0, pq.data(), pq.data() + 4);
    return pq;
  }();
  return full;
}

// Adds scale · ∫ N_m(s) s ds over s/h ∈ [x_lo, x_hi] to C[m] (C has three entries past the last spline, as the rule's
// scatter): the two end pieces here, the whole knot intervals between through the running sum `whole` (whole[q] takes
// +scale from the first whole interval on, −scale past the last; sphere_gain_wholes adds them once per speed u).
void sphere_gain(double x_lo, double x_hi, double scale, std::vector<double>& C, std::vector<double>& whole) {
  const std::size_t nb = C.size() - 3;
  x_hi = std::min(x_hi, double(nb));  // beyond: only the dropped entries (the mass leaves the grid)
  if (x_lo >= x_hi) return;
  const auto q_lo = std::size_t(x_lo), q_hi = std::min(std::size_t(x_hi), nb - 1);
  const std::array<double, 8>& full = whole_interval_moments();
  double Pa[4], Qa[4], Pb[4], Qb[4];
  auto add = [&](std::size_t q, const double* P, const double* Q, double sign) {
    for (std::size_t e = 0; e < 4; ++e) C[q + e] += sign * scale * (double(q) * P[e] + Q[e]);
  };
  const double t_lo = x_lo - double(q_lo);
  spline_moments_to(t_lo, Pa, Qa);
  if (q_lo == q_hi) {
    spline_moments_to(x_hi - double(q_lo), Pb, Qb);
    for (std::size_t e = 0; e < 4; ++e) Pb[e] -= Pa[e], Qb[e] -= Qa[e];
    return add(q_lo, Pb, Qb, 1.0);
  }
  add(q_lo, full.data(), full.data() + 4, 1.0), add(q_lo, Pa, Qa, -1.0);  // [t_lo, 1] of interval q_lo
  if (x_hi > double(q_hi)) spline_moments_to(x_hi - double(q_hi), Pb, Qb), add(q_hi, Pb, Qb, 1.0);  // [0, t_hi] of q_hi
  whole[q_lo + 1] += scale, whole[q_hi] -= scale;
}

// The whole knot intervals: interval q (weight the running sum of `whole`) gives spline q + e its h²-free
// q P_e(1) + Q_e(1).
void sphere_gain_wholes(std::vector<double>& C, const std::vector<double>& whole) {
  const std::array<double, 8>& full = whole_interval_moments();
  double w = 0.0;
  for (std::size_t q = 0; q + 3 < C.size(); ++q) {
    w += whole[q];
    if (w != 0.0)
      for (std::size_t e = 0; e < 4; ++e) C[q + e] += w * (double(q) * full[e] + full[4 + e]);
  }
}

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

const GaussRule& speed_rule() {
  static const GaussRule uq = legendre(speed_points, 0.0, 1.0);
  return uq;
}

// The integrals of the trial functions i … i + 3 (nonzero on knot interval i) against 1, u², u⁴, u⁶, G, H, u, G₄.
struct IntervalMoments {
  double m[4][8] = {};
};

// Knot interval i: the collision, drift and Gram columns of its four trial functions (rows every test function).
// full: also the l = 1 harmonic's collisions and G, H, G₄ (SpeedGridParts::all); otherwise the speed density's alone.
// The speed density's gain is exact in σ̂ (sphere_gain); the rest keeps the collision rule's σ̂ directions. Why the
// rule's inner loop is as it is: |Δv| = kick for every σ̂, so |v′|² = u² + 2u Δv_z + kick², with Δv_z affine in cos φ —
// one multiply-add and a square root per azimuth; and the loss term N_m(u) Σ w is the same spline values for every gas
// velocity and σ̂, so it is subtracted once per u.
template <bool full>
void interval(const SpeedGridProblem& p, double h, std::size_t i, const CollisionRule& rule, Eigen::Ref<Eigen::MatrixXd> coll,
              Eigen::Ref<Eigen::MatrixXd> coll1, Eigen::Ref<Eigen::MatrixXd> drift, Eigen::Ref<Eigen::MatrixXd> gram,
              Eigen::Ref<Eigen::MatrixXd> gram_u, IntervalMoments& out) {
  const GaussRule &uq = speed_rule(), &wz = rule.wz, &wp = rule.wp, &cs = rule.cs;
  const std::size_t nb = std::size_t(coll.rows()), nf = rule.cos_phi.size();
  const double inv_h = 1.0 / h;
  // The gas velocities w = (w_x, 0, w_z) and their weights (shape included) do not depend on u.
  struct GasNode {
    double w_z, w_x, weight;
  };
  std::vector<GasNode> gas;
  for (std::size_t a = 0; a < wz.x.size(); ++a)
    for (std::size_t b = 0; b < wp.x.size(); ++b) {
      const double x = 0.5 * wz.x[a] * wz.x[a] + wp.x[b];  // m₁w²/(2T₁)
      const double shape = p.gas.one + p.gas.a2 * sonine_S2(x) + p.gas.a3 * sonine_S3(x);
      gas.push_back({p.sd_gas * wz.x[a], p.sd_gas * std::sqrt(2.0 * wp.x[b]), wz.weight[a] * wp.weight[b] * shape * p.rate});
    }
  // Three entries past the last spline: a speed in the last knot interval scatters into them, and they are dropped.
  std::vector<double> C(nb + 3), C1(full ? nb + 3 : 0), whole(nb + 3);
  for (std::size_t q = 0; q < uq.x.size(); ++q) {
    const double u = (double(i) + uq.x[q]) * h, wu = uq.weight[q] * h;
    // C_m(u) = ∫dw f_gas ∫dσ̂ rate (g·σ̂)Θ [N_m(|v′|) − N_m(u)]; G(u), H(u) the same average of the gas's energy gain and of u·Δv.
    std::fill(C.begin(), C.end(), 0.0);
    std::fill(C1.begin(), C1.end(), 0.0);
    std::fill(whole.begin(), whole.end(), 0.0);
    double G = 0.0, H = 0.0, G4 = 0.0, lost = 0.0;
    for (const GasNode& node : gas) {
      const double w_z = node.w_z, w_x = node.w_x;
      const double gx = -w_x, gz = u - w_z, g = std::sqrt(gx * gx + gz * gz);
      if (g == 0.0) continue;
      const double total = node.weight * g * std::numbers::pi;  // ∫(g·σ̂)Θ dσ̂ = πg
      lost += total;
      // The sphere of v′: centre c = v − βg/2, radius R = βg/2.
      const double R = 0.5 * p.beta * g, cx = -0.5 * p.beta * gx, cz = u - 0.5 * p.beta * gz, centre = std::sqrt(cx * cx + cz * cz);
      if (2.0 * std::min(centre, R) < 1e-9 * h) {  // a point (|c| or R ≈ 0): |v′| = |c| + R
        const double s = (centre + R) * inv_h;
        const auto j0 = std::size_t(s);
        if (j0 < nb) {
          double N[4];
          splines_at(s - double(j0), N);
          for (std::size_t e = 0; e < 4; ++e) C[j0 + e] += total * N[e];
        }
      } else {
        sphere_gain(std::abs(centre - R) * inv_h, (centre + R) * inv_h, total * h * h / (2.0 * centre * R), C, whole);
      }
      if constexpr (full) {
        const double e3[2] = {gx / g, gz / g}, e1[2] = {e3[1], -e3[0]};  // (x, z); e2 = ŷ
        const double wab = node.weight * g * 2.0 * std::numbers::pi / double(rule.azimuths);
        for (std::size_t c = 0; c < cs.x.size(); ++c) {
          const double ct = cs.x[c], st = rule.sin_theta[c], w = wab * cs.weight[c] * ct, kick = p.beta * g * ct;
          // Δv_z = dz0 + dz1 cos φ; |v′|² = base + 2u dz1 cos φ.
          const double dz0 = -kick * ct * e3[1], dz1 = -kick * st * e1[1], base = u * u + 2.0 * u * dz0 + kick * kick;
          double speeds[max_azimuth_pairs];
          for (std::size_t f = 0; f < nf; ++f) speeds[f] = std::sqrt(std::max(0.0, base + 2.0 * u * dz1 * rule.cos_phi[f]));  // vectorised
          for (std::size_t f = 0; f < nf; ++f) {
            const double speed = speeds[f], s = speed * inv_h;
            const auto j0 = std::size_t(s);
            if (j0 >= nb) continue;  // beyond the grid: the mass leaves it (converged_hcs.hpp checks a wider domain)
            const double cp = rule.cos_phi[f], wf = w * rule.phi_weight[f];
            // The gas particle: w′ = w + (m₂/m₁) kick σ̂, ΔE = (m₁/2)(2 k w·σ̂ + k²), k = (m₂/m₁) kick.
            const double k = p.m2 / p.m1 * kick, w1 = w_x * e1[0] + w_z * e1[1], w3 = w_x * e3[0] + w_z * e3[1], ww = w_x * w_x + w_z * w_z;
            const double dw2 = 2.0 * k * (st * cp * w1 + ct * w3) + k * k;  // |w′|² − |w|²
            const double dz = dz0 + dz1 * cp;
            G += wf * 0.5 * p.m1 * dw2, G4 += wf * (2.0 * ww + dw2) * dw2, H += wf * u * dz;
            double N[4];
            splines_at(s - double(j0), N);
            const double turn = speed > 0.0 ? (u + dz) / speed : 0.0;  // v̂·v̂′: the l = 1 harmonic's gain
            for (std::size_t e = 0; e < 4; ++e) C1[j0 + e] += turn * wf * N[e];
          }
        }
      }
    }
    sphere_gain_wholes(C, whole);
    for (std::size_t j = i; j <= i + 3; ++j) {  // the loss: every collision takes the density away from u
      const double N = lost * spline(u / h - double(j) + 3.0);
      C[j] -= N;
      if constexpr (full) C1[j] -= N;
    }
    for (std::size_t c = 0; c < 4; ++c) {  // trial function i + c
      const double Nj = spline(u / h - double(i + c) + 3.0) * wu;
      for (int n = 0; n < 4; ++n) out.m[c][n] += Nj * std::pow(u, 2 * n);
      out.m[c][4] += Nj * G, out.m[c][5] += Nj * H, out.m[c][6] += Nj * u, out.m[c][7] += Nj * G4;
      for (std::size_t m = 0; m < nb; ++m) coll(Eigen::Index(m), Eigen::Index(c)) += Nj * C[m];
      if constexpr (full)
        for (std::size_t m = 0; m < nb; ++m) coll1(Eigen::Index(m), Eigen::Index(c)) += Nj * C1[m];
      for (std::size_t m = i; m <= i + 3; ++m) {  // test functions nonzero at u
        const double Nm = spline(u / h - double(m) + 3.0);
        drift(Eigen::Index(m), Eigen::Index(c)) += Nj * u * spline_slope(u / h - double(m) + 3.0) / h;
        gram(Eigen::Index(m), Eigen::Index(c)) += Nj * Nm, gram_u(Eigen::Index(m), Eigen::Index(c)) += Nj * Nm * u;
      }
    }
  }
}

}  // namespace

CollisionRule::CollisionRule(std::size_t n)
    : wz(golub_welsch(n, false)), wp(golub_welsch(n, true)), cs(legendre(n / 2, 0.0, 1.0)), azimuths(3 * n / 4) {
  for (std::size_t f = 0; 2 * f < azimuths; ++f) {  // φ_f and φ_(M−1−f) = 2π − φ_f: one point, weight 2
    const double phi = 2.0 * std::numbers::pi * (double(f) + 0.5) / double(azimuths);
    cos_phi.push_back(std::cos(phi));
    phi_weight.push_back(2 * f + 1 == azimuths ? 1.0 : 2.0);  // M odd: φ = π is its own partner
  }
  for (double c : cs.x) sin_theta.push_back(std::sqrt(1.0 - c * c));
  if (cos_phi.size() > max_azimuth_pairs)
    throw std::invalid_argument("collision rule: " + std::to_string(n) + " points; the limit is " + std::to_string(max_rule_points));
}

SpeedGridProblem speed_grid_pair(const CollisionRates& rates, std::size_t k, std::size_t j, double Tj, const PartnerShape& partner) {
  const model::Mixture& mix = rates.mixture();
  const double s = mix.sigma(k, j), mj = mix[j].mass, mk = mix[k].mass;
  return {mj, mk, std::sqrt(Tj / mj), mj * (1.0 + rates.law().eps(k, j)) / (mj + mk), mix[j].density * s * s * rates.chi(k, j), partner};
}

SpeedGridProblem speed_grid_problem(const CollisionRates& rates, const PartnerShape& gas) { return speed_grid_pair(rates, 1, 0, 1.0, gas); }

Eigen::VectorXd stationary_speed_density(const Eigen::MatrixXd& collisions, const SpeedGrid& g, double zeta) {
  Eigen::MatrixXd A = collisions + 0.5 * zeta * g.drift;
  const auto last = A.rows() - 1;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(A.rows());
  A.row(last) = g.mass.transpose(), rhs[last] = 1.0;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (!lu.isInvertible()) return {};
  return lu.solve(rhs);
}

SpeedGrid assemble_speed_grid(const SpeedGridProblem& p, double U, std::size_t K, const CollisionRule& rule, SpeedGridParts parts) {
  const double h = U / double(K);
  const bool full = parts == SpeedGridParts::all;
  const std::size_t nb = K + 3;  // N_j(u) = spline(u/h − j + 3), j = 0 … K + 2
  const auto n = Eigen::Index(nb);
  Eigen::MatrixXd coll = Eigen::MatrixXd::Zero(n, Eigen::Index(4 * K)), drift = coll, gram = coll, gram_u = coll;
  Eigen::MatrixXd coll1 = full ? coll : Eigen::MatrixXd::Zero(n, 0);
  std::vector<IntervalMoments> moments(K);
  parallel_each(K, [&](std::size_t i) {
    const auto cols = Eigen::Index(4 * i);
    auto c1 = full ? coll1.middleCols(cols, 4) : coll1.middleCols(0, 0);
    if (full)
      interval<true>(p, h, i, rule, coll.middleCols(cols, 4), c1, drift.middleCols(cols, 4), gram.middleCols(cols, 4), gram_u.middleCols(cols, 4), moments[i]);
    else
      interval<false>(p, h, i, rule, coll.middleCols(cols, 4), c1, drift.middleCols(cols, 4), gram.middleCols(cols, 4), gram_u.middleCols(cols, 4), moments[i]);
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
      g.collisions.col(J) += coll.col(col), g.drift.col(J) += drift.col(col);
      g.gram.col(J) += gram.col(col), g.gram_u.col(J) += gram_u.col(col);
      if (full) g.collisions_p1.col(J) += coll1.col(col);
      for (int m = 0; m < 8; ++m)
        if (integrals[m]->size() != 0) (*integrals[m])[J] += moments[i].m[c][m];
    }
  return g;
}

SpeedMoments speed_moments(const SpeedGrid& g, const SpeedGridProblem& p, const Eigen::VectorXd& P) {
  const double norm = g.mass.dot(P), u2 = g.u2.dot(P) / norm, u4 = g.u4.dot(P) / norm, u6 = g.u6.dot(P) / norm;
  // Cumulants at the density's own temperature: c² = u² m₂/(2θ), ⟨c²⟩ = 3/2, a_p = ⟨S_p(c²)⟩/⟨S_p²⟩_M (physics.md §6;
  // S₂, S₃ of sonine_polynomials.hpp expanded in the moments, ⟨S₂²⟩_M = 15/8, ⟨S₃²⟩_M = 35/16).
  const double theta = p.m2 * u2 / 3.0, s = p.m2 / (2.0 * theta), x2 = u4 * s * s, x3 = u6 * s * s * s;
  if (g.gain.size() == 0)  // SpeedGridParts::density: the gas's side and the drag were not assembled
    return {theta, 0.6 * x2 / (1.5 * 1.5) - 1.0, (-x3 / 6.0 + 1.75 * x2 - 35.0 / 8.0 * 1.5 + 35.0 / 16.0) / (35.0 / 16.0), nan, nan, nan};
  return {theta, 0.6 * x2 / (1.5 * 1.5) - 1.0, (-x3 / 6.0 + 1.75 * x2 - 35.0 / 8.0 * 1.5 + 35.0 / 16.0) / (35.0 / 16.0),
          g.gain.dot(P) / norm, -g.drag.dot(P) / (norm * u2), g.gain4.dot(P) / norm};
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
