#include "theory/sonine/sonine2_diffusion.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "theory/sonine/sonine_cpq_table.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"
#include "theory/sonine/term_table.hpp"

namespace granmix::theory {

namespace {

constexpr std::size_t MM = max_sonine_modes;

// N_p = (2/√π)Γ(p + 5/2)/p! = N_{p−1}(p + 3/2)/p, N₀ = 3/2; and since x L_p^(α)′ = p L_p − (p + α)L_{p−1},
// S_p + 2x S_p′ = (2p + 1)S_p − (2p + 3)S_{p−1}: M_pp = (2p + 1)N_p, M_{p,p−1} = −(2p + 3)N_{p−1}, else 0.
struct ModeMatrices {
  std::array<double, MM> norm{};
  std::array<double, MM * MM> scaling{};
  ModeMatrices() {
    norm[0] = 1.5;
    for (std::size_t p = 1; p < MM; ++p) norm[p] = norm[p - 1] * (double(p) + 1.5) / double(p);
    for (std::size_t p = 0; p < MM; ++p) {
      scaling[p * MM + p] = (2.0 * double(p) + 1.0) * norm[p];
      if (p > 0) scaling[p * MM + p - 1] = -(2.0 * double(p) + 3.0) * norm[p - 1];
    }
  }
};

const ModeMatrices& mode_matrices() {
  static const ModeMatrices m;
  return m;
}

// The table's rows with p, q < M, made once per M (entry = source·MM² + p·MM + q: the Maxwellian source first).
const TermTable& cpq_table(std::size_t modes) {
  static const auto per_modes = [] {
    std::vector<TermTable> t;
    for (std::size_t M = 0; M <= MM; ++M) {
      std::vector<TermTable::Term> rows;
      for (const SonineCpqTerm& r : sonine_cpq_terms)
        if (std::size_t(r.p) < M && std::size_t(r.q) < M) rows.push_back({unsigned((r.source * MM + r.p) * MM + r.q), r.ia, r.ib, r.coefficient});
      t.emplace_back(rows);
    }
    return t;
  }();
  return per_modes[modes];
}

using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, int(MM), int(MM)>;

}  // namespace

std::vector<double> sonine_cpq_beta_polynomials(double beta, std::size_t modes, unsigned sources) {
  if (modes < 1 || modes > MM) throw std::invalid_argument("sonine2_pair_integrals: modes must be 1 to 5");
  const TermTable& t = cpq_table(modes);
  return t.beta_polynomials(beta, t.groups_below(unsigned(sources * MM * MM)));
}

std::array<SonineCollisionIntegrals, sonine_cpq_sources> sonine_pair_integrals_from(const std::vector<double>& polys, double weight, double beta,
                                                                                   double Ak, double Ai, std::size_t modes, unsigned sources) {
  const double V = Ak + Ai, bP = beta * weight * std::sqrt(2.0 * std::numbers::pi * V);
  std::array<double, sonine_cpq_sources * MM * MM> sum{};
  cpq_table(modes).evaluate(polys, Ak / V, sum.data());
  std::array<SonineCollisionIntegrals, sonine_cpq_sources> C;
  for (unsigned src = 0; src < sonine_cpq_sources; ++src) {
    C[src].modes = modes;
    if (src < sources)
      for (std::size_t e = 0; e < MM * MM; ++e) C[src].c[e] = sum[src * MM * MM + e] * bP;
  }
  return C;
}

namespace {

// C_pq of one pair per source (0: Maxwellian partner; 1, 2: the coefficients of the partner's a₂, a₃), sources < n.
std::array<SonineCollisionIntegrals, sonine_cpq_sources> pair_integrals(double weight, double mu, double eps, double Ak, double Ai,
                                                                        std::size_t modes, unsigned n) {
  const double beta = mu * (1.0 + eps);
  return sonine_pair_integrals_from(sonine_cpq_beta_polynomials(beta, modes, n), weight, beta, Ak, Ai, modes, n);
}

}  // namespace

double sonine_mode_norm(std::size_t p) { return mode_matrices().norm.at(p); }
double sonine_scaling_matrix(std::size_t p, std::size_t q) { return mode_matrices().scaling.at(p * MM + q); }

// The closed forms (sonine_cpq_table.hpp): C_pq = β P Σ coefficient a^ia β^ib, a = A_k/V, V = A_k + A_i,
// A = T/m, P = n_i σ_ki² χ_ki √(2πV). For p, q < 2: C₀₀ = 2βP (= (3/2)ν_ki, docs/physics-beyond.md §1), C₀₁ = −aβP,
// C₁₀ = −βP(3a² − 9aβ + 10a + 4β² − 5β)/a, C₁₁ = βP(30 − 33β + 12β² + 22a − 9aβ − 3a²)/2.
// Checks (tests/theory/test_sonine2_diffusion.cpp, test_sonine_modes.cpp): an independent quadrature over both
// Maxwellians and σ̂; elastic equal temperatures: C symmetric after the norms (self-adjoint operator);
// elastic Lorentz gas (a = 1, β = 2): D[2]/D[1] = 13/12.
SonineCollisionIntegrals sonine2_pair_integrals(double weight, double mu, double eps, double Ak, double Ai, std::size_t modes) {
  return pair_integrals(weight, mu, eps, Ak, Ai, modes, 1)[0];
}

std::array<SonineCollisionIntegrals, sonine_cpq_sources> sonine_pair_integrals_by_source(double weight, double mu, double eps, double Ak,
                                                                                        double Ai, std::size_t modes) {
  return pair_integrals(weight, mu, eps, Ak, Ai, modes, sonine_cpq_sources);
}

SonineTracerSums sonine_pair_sums(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, std::size_t i, double Tk,
                                  double Ti, std::size_t modes, bool partner_sonine) {
  const model::Mixture& mix = rates.mixture();
  const double s = mix.sigma(k, i);
  return terms.tracer(k, i, mix[i].density * s * s * rates.chi(k, i), mix[k].mass, mix[i].mass, Tk, Ti, modes, partner_sonine);
}

SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T,
                                     std::size_t modes) {
  SonineTracerSums sum;
  sum.C.modes = modes;
  for (std::size_t i = 0; i < rates.size(); ++i) {
    const SonineTracerSums p = sonine_pair_sums(rates, terms, k, i, T[k], T[i], modes);
    sum.C.add(p.C);
    sum.xi += p.xi;
  }
  return sum;
}

SonineTracerSums sonine2_tracer_sums(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes) {
  return sonine2_tracer_sums(rates, *make_sonine_pair_terms(rates.law()), k, T, modes);
}

SonineCollisionIntegrals sonine2_collision_integrals(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes) {
  return sonine2_tracer_sums(rates, k, T, modes).C;
}

double sonine_factor(const SonineCollisionIntegrals& C, double zeta) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t M = C.modes;
  const double first = C(0, 0) - 0.75 * zeta;  // ∝ 1/D[1]
  if (!(first > 0.0)) return nan;
  if (M == 1) return 1.0;
  Small A(M, M), AN(M, M);
  for (std::size_t p = 0; p < M; ++p)
    for (std::size_t q = 0; q < M; ++q) {
      A(p, q) = C(p, q) - 0.5 * zeta * sonine_scaling_matrix(p, q);
      AN(p, q) = A(p, q) / sonine_mode_norm(q);
    }
  // The modes relax (the quasi-steady state the diffusive D is) only if every eigenvalue of A N⁻¹ has a
  // positive real part.
  const Eigen::EigenSolver<Small> es(AN, false);
  if (es.info() != Eigen::Success) return nan;
  for (Eigen::Index j = 0; j < es.eigenvalues().size(); ++j)
    if (!(es.eigenvalues()[j].real() > 0.0)) return nan;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, int(MM), 1> e0 = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, int(MM), 1>::Zero(M);
  e0[0] = 1.0;
  const double inv00 = A.partialPivLu().solve(e0)[0];  // (A⁻¹)₀₀ ∝ D[M]
  if (!(inv00 > 0.0) || !std::isfinite(inv00)) return nan;
  return inv00 * first;
}

double sonine_factor(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes) {
  // ζ = ξ_k: the tagged species' temperature T_k sets the scaling of its tracer problem, and T_k
  // decays at ξ_k (equal to the common ζ once settled).
  const SonineTracerSums s = sonine2_tracer_sums(rates, k, T, modes);
  return sonine_factor(s.C, s.xi);
}

double kinetic_velocity_decay_rate(const CollisionRates& rates, const SoninePairTerms& terms, std::size_t k, const double* T,
                                   std::size_t modes) {
  const SonineTracerSums s = sonine2_tracer_sums(rates, terms, k, T, modes);
  const double factor = sonine_factor(s.C, s.xi);
  // τ_v,k⁻¹ = ν_k − ξ_k/2 (docs/physics-beyond.md §1; (2/3)C₀₀ − ξ_k/2 of these sums to 1e-12, tested) taken from the
  // rates' own v1 (A1)/(A3), the paper level's: one implementation of τ_v for both levels, so that an error
  // in it moves the judged curves too. No diffusive solution: the first-Sonine ν_k.
  const double inv_tau = rates.inv_tau_v_species(k, T);
  return 0.5 * s.xi + inv_tau / (std::isfinite(factor) ? factor : 1.0);
}

double kinetic_velocity_decay_rate(const CollisionRates& rates, std::size_t k, const double* T, std::size_t modes) {
  return kinetic_velocity_decay_rate(rates, *make_sonine_pair_terms(rates.law()), k, T, modes);
}

SonineDecay::SonineDecay(const CollisionRates& rates, std::size_t modes, std::shared_ptr<const SoninePairTerms> terms, bool shaped)
    : rates_(rates),
      modes_(modes),
      terms_(terms ? std::move(terms) : make_sonine_pair_terms(rates.law())),
      partner_sonine_(shaped && !rates.law().is_viscoelastic() && rates.size() <= pair_cache_species) {
  if (modes < 2 || modes > MM) throw std::invalid_argument("SonineDecay: modes must be 2 to 5");
}

void SonineDecay::rates(const double* T, const double*, double* nu) const {
  for (std::size_t k = 0; k < rates_.size(); ++k) nu[k] = kinetic_velocity_decay_rate(rates_, *terms_, k, T, modes_);
}

void SonineDecay::update(const double* T) const {
  const std::size_t N = rates_.size();
  const bool known = T_.size() == N;
  if (known && std::equal(T, T + N, T_.begin())) return;
  sums_.resize(N), diffusive_.resize(N);
  if (N > pair_cache_species) {
    for (std::size_t k = 0; k < N; ++k) sums_[k] = sonine2_tracer_sums(rates_, *terms_, k, T, modes_);
  } else {
    pairs_.resize(N * N);
    for (std::size_t k = 0; k < N; ++k)
      for (std::size_t i = 0; i < N; ++i)
        if (!known || T[k] != T_[k] || T[i] != T_[i])
          pairs_[k * N + i] = sonine_pair_sums(rates_, *terms_, k, i, T[k], T[i], modes_, partner_sonine_);
    for (std::size_t k = 0; k < N; ++k) {  // as sonine2_tracer_sums: from zero, partners in order
      SonineTracerSums& sum = sums_[k];
      sum = SonineTracerSums{};
      sum.C.modes = modes_;
      for (std::size_t i = 0; i < N; ++i) sum.C.add(pairs_[k * N + i].C), sum.xi += pairs_[k * N + i].xi;
    }
  }
  for (std::size_t k = 0; k < N; ++k) diffusive_[k] = std::isfinite(sonine_factor(sums_[k].C, sums_[k].xi));
  T_.assign(T, T + N);
}

void SonineDecay::correlation_rates(const CollisionRates&, const double* T, const double* xi, const double* Q, double* dQ, double*,
                                    const double* a2, const double* a3) const {
  const std::size_t N = rates_.size(), M = modes_;
  update(T);
  // With the cooling closure's a₂ (and a₃) and partner terms: the non-Maxwellian problem (see the header).
  const bool shaped = a2 && partner_sonine_;
  for (std::size_t k = 0; k < N; ++k) {
    const SonineTracerSums& s = sums_[k];
    const double v2 = 2.0 * T[k] / rates_.mixture()[k].mass;
    if (!diffusive_[k]) {  // no diffusive solution: first-Sonine ν_k, the other modes decoupled
      const double nu1 = 0.5 * s.xi + rates_.inv_tau_v_species(k, T);
      dQ[k] = 3.0 * T[k] / rates_.mixture()[k].mass - nu1 * Q[k];
      for (std::size_t p = 1; p < M; ++p) dQ[p * N + k] = -nu1 * Q[p * N + k];
      continue;
    }
    SonineCollisionIntegrals C = s.C;
    std::array<double, MM> source{};  // ⟨c² S_p(c²)⟩ over f_k beyond p = 0: N_p(δ_pq − δ_p,q−1) per a_kq (L_q^(1/2) = L_q^(3/2) − L_{q−1}^(3/2))
    double zeta = s.xi;  // the scaling rate of the same closure as C_pq: Maxwellian sums, or the level's ζ_k with the a's
    if (shaped) {
      for (std::size_t i = 0; i < N; ++i) {
        const SonineTracerSums& pair = pairs_[k * N + i];
        C.add(pair.C_partner[0], a2[i]);
        if (a3) C.add(pair.C_partner[1], a3[i]);
      }
      const double a[MM + 1] = {0.0, 0.0, a2[k], a3 ? a3[k] : 0.0};  // a_kq, q ≤ MM
      for (std::size_t p = 1; p < M; ++p) source[p] = sonine_mode_norm(p) * (a[p] - a[p + 1]);
      zeta = xi[k];
    }
    std::array<double, MM> b{};
    for (std::size_t q = 0; q < M; ++q) b[q] = Q[q * N + k] / sonine_mode_norm(q);
    for (std::size_t p = 0; p < M; ++p) {
      double d = (p == 0 ? 3.0 * T[k] / rates_.mixture()[k].mass : v2 * source[p]) - 0.5 * zeta * Q[p * N + k];
      for (std::size_t q = 0; q < M; ++q) d -= (C(p, q) - 0.5 * zeta * sonine_scaling_matrix(p, q)) * b[q];
      dQ[p * N + k] = d;
    }
  }
}

}  // namespace granmix::theory
