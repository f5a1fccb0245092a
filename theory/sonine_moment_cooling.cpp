#include "sonine_moment_cooling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "equilibrated_solve.hpp"
#include "sonine_moment_table.hpp"
#include "term_table.hpp"

namespace granmix::theory {

namespace {

constexpr int PM = sonine_moment_max, NS = sonine_moment_sources;

// The table, entry (p − 1)·NS + source.
const TermTable& moment_table() {
  static const TermTable t = [] {
    std::vector<TermTable::Term> rows;
    for (const SonineMomentTerm& r : sonine_moment_terms) rows.push_back({unsigned((r.p - 1) * NS + r.source), r.ia, r.ib, r.coefficient});
    return TermTable(rows);
  }();
  return t;
}

// H(p; source) of one ordered pair from its β polynomials, times β P: the rates of ⟨c^(2p)⟩_k per unit
// Sonine coefficient.
std::array<double, PM * NS> pair_moments(const std::vector<double>& polys, double a, double bP) {
  std::array<double, PM * NS> H{};
  moment_table().evaluate(polys, a, H.data());
  for (double& x : H) x *= bP;
  return H;
}

}  // namespace

std::vector<double> sonine_moment_beta_polynomials(double beta) { return moment_table().beta_polynomials(beta); }

std::array<double, PM * NS> sonine_moment_pair_from(const std::vector<double>& polys, double weight, double beta, double Ak, double Ai) {
  const double V = Ak + Ai;
  return pair_moments(polys, Ak / V, beta * weight * std::sqrt(2.0 * std::numbers::pi * V));
}

std::array<double, PM * NS> sonine_moment_pair(double weight, double mu, double eps, double Ak, double Ai) {
  const double beta = mu * (1.0 + eps);
  return sonine_moment_pair_from(sonine_moment_beta_polynomials(beta), weight, beta, Ak, Ai);
}

namespace {

// ⟨c⁴⟩ = M2 (1 + a₂), ⟨c⁶⟩ = M3 (1 + 3a₂ − a₃) over f_M (1 + a₂S₂ + a₃S₃): Γ(p + 3/2)/Γ(3/2) and ⟨c^(2p) S_q⟩.
constexpr double M1 = 1.5, M2 = 15.0 / 4.0, M3 = 105.0 / 8.0;

}  // namespace

SonineMomentCooling::SonineMomentCooling(const CollisionRates& rates, int order, std::vector<double> z0,
                                         std::shared_ptr<const SoninePairTerms> terms)
    : rates_(rates), order_(order), N_(rates.size()), z0_(std::move(z0)), terms_(terms ? std::move(terms) : make_sonine_pair_terms(rates.law())) {
  if (order < 2 || order > PM) throw std::invalid_argument("Sonine moment cooling: order must be 2 or 3");
  if (z0_.empty()) z0_.assign(state_size(), 0.0);
  if (z0_.size() != state_size()) throw std::invalid_argument("Sonine moment cooling: initial state needs (order − 1) values per species");
}

void SonineMomentCooling::assemble(const double* T) const {
  // The pair terms depend on T only: CVODE's difference-quotient Jacobian perturbs one unknown at a time, and for
  // the a's, MSDs and VACF modes (most columns) T is bitwise the same as at the last call.
  if (assembled_ && std::equal(T, T + N_, assembled_T_.begin())) return;
  assembled_T_.assign(T, T + N_), assembled_ = true;
  const model::Mixture& mix = rates_.mixture();
  R0_.assign(N_ * PM, 0.0), self_.assign(N_ * PM * 2, 0.0), partner_.resize(N_ * N_ * PM * 2);
  for (std::size_t k = 0; k < N_; ++k) {
    for (std::size_t i = 0; i < N_; ++i) {
      const double sigma = mix.sigma(k, i);
      const std::array<double, PM * NS> H =
          terms_->moments(k, i, mix[i].density * sigma * sigma * rates_.chi(k, i), mix[k].mass, mix[i].mass, T[k], T[i]);
      for (int p = 0; p < PM; ++p) {
        R0_[k * PM + std::size_t(p)] += H[std::size_t(p * NS)];
        for (std::size_t j = 0; j < 2; ++j) {
          self_[(k * PM + std::size_t(p)) * 2 + j] += H[std::size_t(p * NS) + 1 + j];
          partner_[((k * N_ + i) * PM + std::size_t(p)) * 2 + j] = H[std::size_t(p * NS) + 3 + j];
        }
      }
    }
  }
}

void SonineMomentCooling::initial_state(const double*, double rtol, double* z, double* atol) const {
  // a₂, a₃ are O(0.01–0.3) and start at 0 from a Maxwellian: an absolute tolerance rtol, as for ln T.
  for (std::size_t j = 0; j < state_size(); ++j) z[j] = z0_[j], atol[j] = rtol;
}

void SonineMomentCooling::rates(const double* T, const double* z, double* xi, double* dz_dt) const {
  assemble(T);
  const bool third = order_ == 3;
  auto a2 = [&](std::size_t k) { return 0.5 * z[k]; };
  auto a3 = [&](std::size_t k) { return third ? z[N_ + k] : 0.0; };
  for (std::size_t k = 0; k < N_; ++k) {
    std::array<double, PM> R1{};  // the rates' parts linear in the a's
    for (std::size_t p = 0; p < PM; ++p) {
      const double* s = &self_[(k * PM + p) * 2];
      double sum = s[0] * a2(k) + s[1] * a3(k);
      for (std::size_t i = 0; i < N_; ++i) {
        const double* w = &partner_[((k * N_ + i) * PM + p) * 2];
        sum += w[0] * a2(i) + w[1] * a3(i);
      }
      R1[p] = sum;
    }
    const double* R0 = &R0_[k * PM];
    const double zeta0 = -R0[0] / M1, zeta1 = -R1[0] / M1;
    xi[k] = zeta0 + zeta1;
    if (!dz_dt) continue;
    const double dM2 = R0[1] + R1[1] + 2.0 * (zeta0 * M2 * (1.0 + a2(k)) + zeta1 * M2);
    const double da2 = dM2 / M2;
    dz_dt[k] = 2.0 * da2;
    if (third) {
      const double dM3 = R0[2] + R1[2] + 3.0 * (zeta0 * M3 * (1.0 + 3.0 * a2(k) - a3(k)) + zeta1 * M3);
      dz_dt[N_ + k] = 3.0 * da2 - dM3 / M3;
    }
  }
}

bool SonineMomentCooling::cumulants(const double*, const double* z, double* c) const {
  std::copy(z, z + N_, c);
  return true;
}

bool SonineMomentCooling::third_sonine(const double* z, double* a3) const {
  if (order_ < 3) return false;
  std::copy(z + N_, z + 2 * N_, a3);
  return true;
}

std::vector<double> SonineMomentCooling::steady_state(const double* T) const {
  const std::size_t n = state_size();
  std::vector<double> z(n, 0.0), xi(N_), b(n), d(n);
  rates(T, z.data(), xi.data(), b.data());
  Eigen::MatrixXd A(n, n);
  for (std::size_t j = 0; j < n; ++j) {
    z[j] = 1.0;
    rates(T, z.data(), xi.data(), d.data());
    z[j] = 0.0;
    for (std::size_t i = 0; i < n; ++i) A(Eigen::Index(i), Eigen::Index(j)) = d[i] - b[i];
  }
  const Eigen::VectorXd x = solve_equilibrated(A, -Eigen::Map<const Eigen::VectorXd>(b.data(), Eigen::Index(n)),
                                                "Sonine moments at order " + std::to_string(order_) + ": the steady a's");
  return std::vector<double>(x.data(), x.data() + n);
}

}  // namespace granmix::theory
