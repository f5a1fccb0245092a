#include "theory/sonine/sonine_moment_cooling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "theory/numerics/equilibrated_solve.hpp"
#include "theory/numerics/parallel_each.hpp"
#include "theory/sonine/sonine_moment_table.hpp"
#include "theory/sonine/term_table.hpp"

namespace granmix::theory {

namespace {

constexpr int PM = sonine_moment_max, NS = sonine_moment_sources;

// Whether order `order` carries entry (p, source): p ≤ order and no a_q beyond it (sources 1…PM−1 own a₂…a_PM, then
// the partner's).
constexpr bool carried(int order, int p, int source) {
  const int q = source == 0 ? 0 : source <= PM - 1 ? source + 1 : source - (PM - 1) + 1;  // the Sonine coefficient's index
  return p <= order && q <= order;
}

// The table, entry (p − 1)·NS + source: all of it (order 4), or the rows order 3 carries (order 2 reads a part of
// those) — 75 of its 176 (entry, power of a) groups, so a right-hand side of v1 Fig. 8's order-3 closure evaluates
// less than half of them.
constexpr int table_order(int order) { return order > 3 ? PM : 3; }
const TermTable& moment_table(int order) {
  const auto make = [](int order) {
    std::vector<TermTable::Term> rows;
    for (const SonineMomentTerm& r : sonine_moment_terms)
      if (carried(order, r.p, r.source)) rows.push_back({unsigned((r.p - 1) * NS + r.source), r.ia, r.ib, r.coefficient});
    return TermTable(rows);
  };
  static const TermTable all = make(PM), third = make(3);
  return table_order(order) == PM ? all : third;
}

// H(p; source) of one ordered pair, its table's sums (entry e at sums[e · stride]) times β P: the rates of ⟨c^(2p)⟩_k
// per unit Sonine coefficient; the entries its table does not carry NaN.
void scale_moments(const double* sums, std::size_t stride, double bP, int order, std::array<double, PM * NS>& H) {
  static constexpr auto mask = [](int order) {  // the entries a table carries
    std::array<bool, PM * NS> m{};
    for (int e = 0; e < PM * NS; ++e) m[std::size_t(e)] = carried(order, e / NS + 1, e % NS);
    return m;
  };
  static constexpr std::array<bool, PM * NS> all = mask(PM), third = mask(3);
  const std::array<bool, PM * NS>& kept = table_order(order) == PM ? all : third;
  for (std::size_t e = 0; e < H.size(); ++e) H[e] = kept[e] ? sums[e * stride] * bP : std::numeric_limits<double>::quiet_NaN();
}

// The table's a = A_k/V and the factor β P = β w √(2π V) of a pair.
struct PairScale {
  double a, bP;
};
PairScale pair_scale(double weight, double beta, double Ak, double Ai) {
  const double V = Ak + Ai;
  return {Ak / V, beta * weight * std::sqrt(2.0 * std::numbers::pi * V)};
}

}  // namespace

std::vector<double> sonine_moment_beta_polynomials(double beta, int order) { return moment_table(order).beta_polynomials(beta); }

std::array<double, PM * NS> sonine_moment_pair_from(const std::vector<double>& polys, double weight, double beta, double Ak, double Ai, int order) {
  const PairScale p = pair_scale(weight, beta, Ak, Ai);
  std::array<double, PM * NS> sums{}, H;
  moment_table(order).evaluate(polys, p.a, sums.data());
  scale_moments(sums.data(), 1, p.bP, order, H);
  return H;
}

void sonine_moment_pairs4_from(const double* polys4, std::size_t groups, const double* weight, const double* beta, const double* Ak,
                               const double* Ai, int order, SonineMomentRates* out, std::size_t lanes) {
  double a[4], bP[4], sums[PM * NS * 4] = {};
  for (int l = 0; l < 4; ++l) {
    const PairScale p = pair_scale(weight[l], beta[l], Ak[l], Ai[l]);
    a[l] = p.a, bP[l] = p.bP;
  }
  moment_table(order).evaluate4(polys4, groups, a, sums);
  for (std::size_t l = 0; l < lanes; ++l) scale_moments(sums + l, 4, bP[l], order, out[l]);
}

std::array<double, PM * NS> sonine_moment_pair(double weight, double mu, double eps, double Ak, double Ai, int order) {
  const double beta = mu * (1.0 + eps);
  return sonine_moment_pair_from(sonine_moment_beta_polynomials(beta, order), weight, beta, Ak, Ai, order);
}

namespace {

// Over f_M (1 + Σ_q a_q S_q): ⟨c^(2p)⟩ = M_p (1 + Σ_q (−1)^q C(p, q) a_q), M_p = Γ(p + 3/2)/Γ(3/2) (the Laguerre
// moments ∫x^(1/2+p) e^(−x) L_q^(1/2) = Γ(p + 3/2)(−1)^q C(p, q)): ⟨c⁴⟩ = M₂(1 + a₂), ⟨c⁶⟩ = M₃(1 + 3a₂ − a₃),
// ⟨c⁸⟩ = M₄(1 + 6a₂ − 4a₃ + a₄).
constexpr double M[PM + 1] = {1.0, 1.5, 15.0 / 4.0, 105.0 / 8.0, 945.0 / 16.0};
constexpr double moment_weight(int p, int q) {  // (−1)^q C(p, q)
  double c = 1.0;
  for (int j = 0; j < q; ++j) c = c * double(p - j) / double(j + 1);
  return q % 2 == 0 ? c : -c;
}

}  // namespace

SonineMomentCooling::SonineMomentCooling(const CollisionRates& rates, int order, std::vector<double> z0,
                                         std::shared_ptr<const SoninePairTerms> terms)
    : rates_(rates), order_(order), N_(rates.size()), z0_(std::move(z0)), terms_(terms ? std::move(terms) : make_sonine_pair_terms(rates.law())) {
  if (order < 2 || order > PM) throw std::invalid_argument("Sonine moment cooling: order must be 2, 3 or 4");
  if (z0_.empty()) z0_.assign(state_size(), 0.0);
  if (z0_.size() != state_size()) throw std::invalid_argument("Sonine moment cooling: initial state needs (order − 1) values per species");
}

void SonineMomentCooling::assemble(const double* T) const {
  // The pair terms depend on T only: CVODE's difference-quotient Jacobian perturbs one unknown at a time, and for
  // the a's, MSDs and VACF modes (most columns) T is bitwise the same as at the last call.
  if (assembled_ && std::equal(T, T + N_, assembled_T_.begin())) return;
  assembled_T_.assign(T, T + N_), assembled_ = true;
  const model::Mixture& mix = rates_.mixture();
  constexpr std::size_t A = PM - 1;  // Sonine coefficients a₂ … a_PM per species
  R0_.assign(N_ * PM, 0.0), self_.assign(N_ * PM * A, 0.0), partner_.resize(N_ * N_ * PM * A);
  // Each species' rows on one thread (its sums in the same order for any thread count), summed on the stack and
  // stored once: neighbouring species' sums share cache lines, which two threads adding into them in turn pass back
  // and forth (v1 Fig. 8's kinetic level on 2 threads: 1.79 s, against 2.07 s adding in place; the numbers bit for bit).
  masses_.resize(N_);
  for (std::size_t i = 0; i < N_; ++i) masses_[i] = mix[i].mass;
  parallel_each(N_, [&](std::size_t k) {
    std::array<double, PM> r0{};
    std::array<double, PM * A> self{};
    thread_local std::vector<double> weight;
    thread_local std::vector<SonineMomentRates> row;
    weight.resize(N_), row.resize(N_);
    for (std::size_t i = 0; i < N_; ++i) {
      const double sigma = mix.sigma(k, i);
      weight[i] = mix[i].density * sigma * sigma * rates_.chi(k, i);
    }
    terms_->moments_row(k, N_, weight.data(), masses_.data(), T, order_, row.data());
    for (std::size_t i = 0; i < N_; ++i) {
      const SonineMomentRates& H = row[i];
      for (int p = 0; p < PM; ++p) {
        r0[std::size_t(p)] += H[std::size_t(p * NS)];
        for (std::size_t j = 0; j < A; ++j) {
          self[std::size_t(p) * A + j] += H[std::size_t(p * NS) + 1 + j];
          partner_[((k * N_ + i) * PM + std::size_t(p)) * A + j] = H[std::size_t(p * NS) + 1 + A + j];
        }
      }
    }
    std::copy(r0.begin(), r0.end(), R0_.begin() + std::ptrdiff_t(k * PM));
    std::copy(self.begin(), self.end(), self_.begin() + std::ptrdiff_t(k * PM * A));
  }, N_ >= parallel_moment_species && terms_->concurrent());
}

void SonineMomentCooling::initial_state(const double*, double rtol, double* z, double* atol) const {
  // a₂, a₃ are O(0.01–0.3) and start at 0 from a Maxwellian: an absolute tolerance rtol, as for ln T.
  for (std::size_t j = 0; j < state_size(); ++j) z[j] = z0_[j], atol[j] = rtol;
}

void SonineMomentCooling::rates(const double* T, const double* z, double* xi, double* dz_dt) const {
  assemble(T);
  constexpr std::size_t A = PM - 1;
  const std::size_t used = std::size_t(order_ - 1);  // a₂ … a_order (the pair terms of higher ones are not read)
  // a_q of species k (q ≥ 2): z holds c = 2a₂, then a₃, a₄ per species.
  auto a = [&](int q, std::size_t k) { return q == 2 ? 0.5 * z[k] : z[std::size_t(q - 2) * N_ + k]; };
  for (std::size_t k = 0; k < N_; ++k) {
    std::array<double, PM> R1{};  // the rates' parts linear in the a's
    for (std::size_t p = 0; p < std::size_t(order_); ++p) {
      const double* s = &self_[(k * PM + p) * A];
      double sum = 0.0;
      for (std::size_t j = 0; j < used; ++j) sum += s[j] * a(int(j) + 2, k);
      for (std::size_t i = 0; i < N_; ++i) {
        const double* w = &partner_[((k * N_ + i) * PM + p) * A];
        double partners = 0.0;
        for (std::size_t j = 0; j < used; ++j) partners += w[j] * a(int(j) + 2, i);
        sum += partners;
      }
      R1[p] = sum;
    }
    const double* R0 = &R0_[k * PM];
    const double zeta0 = -R0[0] / M[1], zeta1 = -R1[0] / M[1];
    xi[k] = zeta0 + zeta1;
    if (!dz_dt) continue;
    // d⟨c^(2p)⟩/dt = R_p + p ζ ⟨c^(2p)⟩ (ζ₁'s product with the a's dropped), then the a's from the moments:
    // (−1)^p da_p = d⟨c^(2p)⟩/M_p − Σ_(q<p) (−1)^q C(p, q) da_q.
    double da[PM + 1] = {};
    for (int p = 2; p <= order_; ++p) {
      double shape = 1.0;
      for (int q = 2; q <= p; ++q) shape += moment_weight(p, q) * a(q, k);
      const double dM = R0[p - 1] + R1[std::size_t(p - 1)] + double(p) * (zeta0 * M[p] * shape + zeta1 * M[p]);
      double rest = dM / M[p];
      for (int q = 2; q < p; ++q) rest -= moment_weight(p, q) * da[q];
      da[p] = moment_weight(p, p) * rest;
    }
    dz_dt[k] = 2.0 * da[2];
    for (int p = 3; p <= order_; ++p) dz_dt[std::size_t(p - 2) * N_ + k] = da[p];
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
                                                "Sonine moments at order " + std::to_string(order_) + ": the steady a's at T_max/T_min = " +
                                                    fmt::format("{:.4g}", *std::max_element(T, T + N_) / *std::min_element(T, T + N_)) +
                                                    " (no steady shape there: the linear closure breaks down)");
  return std::vector<double>(x.data(), x.data() + n);
}

}  // namespace granmix::theory
