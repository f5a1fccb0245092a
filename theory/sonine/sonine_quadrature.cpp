#include "theory/sonine/sonine_quadrature.hpp"

#include <gsl/gsl_integration.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "theory/sonine/sonine_polynomials.hpp"

namespace granmix::theory {

namespace {

// The rules of M modes: Hermite max(5, 2M), Laguerre max(2, M) points (see the header), M = 1 … 5.
struct ModeRules {
  std::array<GaussRule, max_sonine_modes + 1> hermite, laguerre;
  ModeRules() {
    for (std::size_t M = 1; M <= max_sonine_modes; ++M)
      hermite[M] = golub_welsch(std::max<std::size_t>(5, 2 * M), false), laguerre[M] = golub_welsch(std::max<std::size_t>(2, M), true);
  }
};
const ModeRules& mode_rules() {
  static const ModeRules r;
  return r;
}

}  // namespace

GaussRule golub_welsch(std::size_t n, bool laguerre) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  for (std::size_t j = 0; j < n; ++j) {
    if (laguerre) J(Eigen::Index(j), Eigen::Index(j)) = 2.0 * double(j) + 1.0;
    if (j + 1 < n) J(Eigen::Index(j), Eigen::Index(j + 1)) = J(Eigen::Index(j + 1), Eigen::Index(j)) = laguerre ? double(j + 1) : std::sqrt(double(j + 1));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(J);
  if (es.info() != Eigen::Success) throw NumericalError("Golub–Welsch: eigen-decomposition failed");
  GaussRule r;
  for (std::size_t j = 0; j < n; ++j) {
    const double v0 = es.eigenvectors()(0, Eigen::Index(j));
    r.x.push_back(es.eigenvalues()[Eigen::Index(j)]), r.weight.push_back(v0 * v0);
  }
  return r;
}

namespace {

// A fixed set of rule sizes, each rule built on its first use (thread-safe: one std::call_once per size), so sizes
// that only a test asks for cost nothing elsewhere.
class RulesBySize {
 public:
  RulesBySize(std::vector<std::size_t> sizes, GaussRule (*make)(std::size_t), std::string name)
      : sizes_(std::move(sizes)), make_(make), name_(std::move(name)), rules_(sizes_.size()), once_(sizes_.size()) {}
  const GaussRule& operator()(std::size_t n) {
    for (std::size_t j = 0; j < sizes_.size(); ++j)
      if (sizes_[j] == n) {
        std::call_once(once_[j], [&] { rules_[j] = make_(n); });
        return rules_[j];
      }
    std::string allowed;
    for (std::size_t j = 0; j < sizes_.size(); ++j)
      allowed += (j == 0 ? "" : j + 1 == sizes_.size() ? " or " : ", ") + std::to_string(sizes_[j]);
    throw std::invalid_argument(name_ + ": no rule of " + std::to_string(n) + " nodes (" + allowed + ")");
  }

 private:
  std::vector<std::size_t> sizes_;
  GaussRule (*make_)(std::size_t);
  std::string name_;
  std::vector<GaussRule> rules_;
  std::vector<std::once_flag> once_;
};

// The Gauss rule of the weight x e^(−x²) on [0, ∞) (u = √(2V) x): its recurrence by the Stieltjes procedure on a
// discretisation of the weight (Gauss–Legendre, 512 points on [0, 10], where the weight is below 1e-42 beyond), then
// Golub–Welsch. Exact to degree 2n − 1 up to that discretisation (~1e-15).
GaussRule make_half_range_rule(std::size_t n) {
  constexpr std::size_t fine = 512;  // a tabulated GSL order (its computed orders lose ~1e-10)
  gsl_integration_glfixed_table* t = gsl_integration_glfixed_table_alloc(fine);
  if (t == nullptr) throw NumericalError("gsl_integration_glfixed_table_alloc failed");
  std::vector<double> x(fine), w(fine);
  for (std::size_t j = 0; j < fine; ++j) {
    double h = 0.0;
    if (gsl_integration_glfixed_point(0.0, 10.0, j, &x[j], &h, t) != 0) {
      gsl_integration_glfixed_table_free(t);
      throw NumericalError("gsl_integration_glfixed_point failed");
    }
    w[j] = h * x[j] * std::exp(-x[j] * x[j]);
  }
  gsl_integration_glfixed_table_free(t);
  // Stieltjes: p_{k+1} = (x − α_k) p_k − β_k p_{k−1}, on the discrete measure.
  std::vector<double> alpha(n), beta(n), p(fine, 1.0), q(fine, 0.0);
  double norm = 0.0;
  for (std::size_t j = 0; j < fine; ++j) norm += w[j];
  const double mass = norm;
  for (std::size_t k = 0; k < n; ++k) {
    double a = 0.0;
    for (std::size_t j = 0; j < fine; ++j) a += w[j] * x[j] * p[j] * p[j];
    alpha[k] = a / norm;
    for (std::size_t j = 0; j < fine; ++j) {
      const double next = (x[j] - alpha[k]) * p[j] - (k ? beta[k] : 0.0) * q[j];
      q[j] = p[j], p[j] = next;
    }
    double next_norm = 0.0;
    for (std::size_t j = 0; j < fine; ++j) next_norm += w[j] * p[j] * p[j];
    if (k + 1 < n) beta[k + 1] = next_norm / norm;
    norm = next_norm;
  }
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  for (std::size_t k = 0; k < n; ++k) {
    J(Eigen::Index(k), Eigen::Index(k)) = alpha[k];
    if (k + 1 < n) J(Eigen::Index(k), Eigen::Index(k + 1)) = J(Eigen::Index(k + 1), Eigen::Index(k)) = std::sqrt(beta[k + 1]);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(J);
  if (es.info() != Eigen::Success) throw NumericalError("half-range Gauss rule: eigen-decomposition failed");
  GaussRule r;
  for (std::size_t j = 0; j < n; ++j) {
    const double v0 = es.eigenvectors()(0, Eigen::Index(j));
    r.x.push_back(es.eigenvalues()[Eigen::Index(j)]), r.weight.push_back(mass * v0 * v0);
  }
  return r;
}

}  // namespace

const GaussRule& half_range_rule(std::size_t n) {
  static RulesBySize rules({std::begin(half_range_rule_sizes), std::end(half_range_rule_sizes)}, make_half_range_rule,
                           "half-range Gauss rule");
  return rules(n);
}

std::size_t sonine_quadrature_nodes() { return impact_speed_points; }

void sonine_quadrature_speeds(double V, double* u, std::size_t nodes) {
  const GaussRule& rule = half_range_rule(nodes);
  const double u_scale = std::sqrt(2.0 * V);
  for (std::size_t n = 0; n < rule.x.size(); ++n) u[n] = u_scale * rule.x[n];
}

PairSonineIntegrals sonine_pair_quadrature(double theta_k, double theta_i, double mu, const std::function<double(double)>& eps,
                                           std::size_t modes) {
  std::vector<double> e(sonine_quadrature_nodes());
  sonine_quadrature_speeds(theta_k + theta_i, e.data());
  for (double& x : e) x = eps(x);
  return sonine_pair_quadrature(theta_k, theta_i, mu, e.data(), modes);
}

PairSonineIntegrals sonine_pair_quadrature(double theta_k, double theta_i, double mu, const double* eps_nodes, std::size_t modes) {
  if (modes < 1 || modes > max_sonine_modes) throw std::invalid_argument("sonine_pair_quadrature: modes must be 1 to 5");
  const GaussRule& rule = half_range_rule(impact_speed_points);
  const GaussRule &hermite = mode_rules().hermite[modes], &laguerre = mode_rules().laguerre[modes];
  const double V = theta_k + theta_i, alpha = theta_k / V, sW = std::sqrt(theta_k * theta_i / V);
  const double u_scale = std::sqrt(2.0 * V), flux = 4.0 * std::numbers::pi * std::sqrt(2.0 * V / std::numbers::pi);
  const double inv2k = 0.5 / theta_k, inv2i = 0.5 / theta_i;
  PairSonineIntegrals out;
  out.C.modes = modes;
  std::array<double, max_sonine_modes> S{}, S1{};
  for (std::size_t n = 0; n < rule.x.size(); ++n) {
    const double u = u_scale * rule.x[n], beta = mu * (1.0 + eps_nodes[n]), bu = beta * u;
    std::array<double, 3> e2{}, e4{};
    SonineCollisionIntegrals c;
    for (std::size_t h = 0; h < hermite.x.size(); ++h) {
      const double W = sW * hermite.x[h], zk = W + alpha * u, zk1 = zk - bu, zi = W - (1.0 - alpha) * u;
      const double S2i = sonine_axial_S2(zi * zi * inv2i);  // E[S₂(c_i²) | v_iz]
      for (std::size_t l = 0; l < laguerre.x.size(); ++l) {
        const double g = hermite.weight[h] * laguerre.weight[l], R = 2.0 * theta_k * laguerre.x[l];
        const double v2 = R + zk * zk, v21 = R + zk1 * zk1;  // v_k², v_k′²
        const double x = v2 * inv2k, x1 = v21 * inv2k, cc = (R + zk * zk1) * inv2k;  // c², c′², c·c′
        const double d2 = v21 - v2, d4 = v21 * v21 - v2 * v2, s2k = sonine_S2(x);
        e2[0] += g * d2, e2[1] += g * s2k * d2, e2[2] += g * S2i * d2;
        e4[0] += g * d4, e4[1] += g * s2k * d4, e4[2] += g * S2i * d4;
        sonine_vector_basis(x, modes, S.data()), sonine_vector_basis(x1, modes, S1.data());
        for (std::size_t p = 0; p < modes; ++p) {
          const double loss = x * S[p] - cc * S1[p];  // c·[c S_p(c²) − c′ S_p(c′²)]
          for (std::size_t q = 0; q < modes; ++q) c(p, q) += g * S[q] * loss;
        }
      }
    }
    const double m = flux * rule.weight[n];
    for (std::size_t j = 0; j < 3; ++j) out.energy[j] += m * e2[j], out.fourth[j] += m * e4[j];
    out.C.add(c, m);
  }
  out.C.modes = modes;
  return out;
}

SonineMomentRates sonine_moment_quadrature(double theta_k, double theta_i, double mu, const double* eps_nodes, int order, std::size_t nodes) {
  const GaussRule& rule = half_range_rule(nodes);
  // Order 3: Hermite 8 × Laguerre 4 (degree 12 in W, 6 in r); order 4: 10 × 5 (S₄ times the change of v⁸: 16 and 8).
  const std::size_t rules = order > 3 ? 5 : 4;
  const GaussRule &hermite = mode_rules().hermite[rules], &laguerre = mode_rules().laguerre[rules];
  const double V = theta_k + theta_i, alpha = theta_k / V, sW = std::sqrt(theta_k * theta_i / V);
  const double u_scale = std::sqrt(2.0 * V), flux = 4.0 * std::numbers::pi * std::sqrt(2.0 * V / std::numbers::pi);
  const double inv2k = 0.5 / theta_k, inv2i = 0.5 / theta_i;
  constexpr std::size_t NS = sonine_moment_sources, PM = sonine_moment_max;
  const std::size_t P = order > 3 ? PM : 3, A = P - 1;  // moments p = 1 … P, Sonine coefficients a₂ … a_P
  SonineMomentRates out{};
  for (std::size_t n = 0; n < rule.x.size(); ++n) {
    const double u = u_scale * rule.x[n], bu = mu * (1.0 + eps_nodes[n]) * u;
    SonineMomentRates e{};
    for (std::size_t h = 0; h < hermite.x.size(); ++h) {
      const double W = sW * hermite.x[h], zk = W + alpha * u, zk1 = zk - bu, zi = W - (1.0 - alpha) * u;
      const double y = zi * zi * inv2i;
      const double partner[3] = {sonine_axial_S2(y), sonine_axial_S3(y), sonine_axial_S4(y)};  // E[S_q(c_i²) | v_iz]
      for (std::size_t l = 0; l < laguerre.x.size(); ++l) {
        const double g = hermite.weight[h] * laguerre.weight[l], r = laguerre.x[l];  // r = |v_k⊥|²/(2θ_k)
        const double x = r + zk * zk * inv2k, x1 = r + zk1 * zk1 * inv2k;          // c², c′²
        const double own[3] = {sonine_S2(x), sonine_S3(x), sonine_S4(x)};
        double xp = x, x1p = x1;  // x^p, x1^p
        for (std::size_t p = 0; p < P; ++p, xp *= x, x1p *= x1) {
          const double d = g * (x1p - xp);
          e[p * NS] += d;
          for (std::size_t q = 0; q < A; ++q) e[p * NS + 1 + q] += own[q] * d, e[p * NS + PM + q] += partner[q] * d;
        }
      }
    }
    const double m = flux * rule.weight[n];
    for (std::size_t j = 0; j < out.size(); ++j) out[j] += m * e[j];
  }
  // Below order 4 the ⟨c⁸⟩ row and the a₄ sources are not computed: NaN, so that no order-4 closure reads them.
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::size_t p = j / NS, src = j % NS;  // source 1 + q: own a_(q+2); PM + q: the partner's
    if (p >= P || (src != 0 && (src - 1) % (PM - 1) >= A)) out[j] = std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

SonineMoments sonine_moments(const PairSonineIntegrals& q, double w, double theta_k, bool self) {
  const double z = -w / (3.0 * theta_k);
  SonineMoments m;
  m.zeta0 = z * q.energy[0];
  m.Lambda0 = w * q.fourth[0];
  if (self) {
    m.zeta_self = 0.5 * z * (q.energy[1] + q.energy[2]);
    m.Lambda_self = 0.5 * w * (q.fourth[1] + q.fourth[2]);
  } else {
    m.zeta_self = 0.5 * z * q.energy[1], m.zeta_cross = 0.5 * z * q.energy[2];
    m.Lambda_self = 0.5 * w * q.fourth[1], m.Lambda_cross = 0.5 * w * q.fourth[2];
  }
  return m;
}

}  // namespace granmix::theory
