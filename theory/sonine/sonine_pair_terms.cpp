#include "theory/sonine/sonine_pair_terms.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "theory/sonine/sonine_moment_cooling.hpp"
#include "theory/sonine/sonine_quadrature.hpp"

namespace granmix::theory {

namespace {

class ClosedFormTerms final : public SoninePairTerms {
 public:
  explicit ClosedFormTerms(const model::Restitution& law) : law_(law) {}
  SonineMoments self(std::size_t i, double w, double lambda_i) const override {
    return sonine_self(w, 1.0, 1.0, law_.eps(i, i), lambda_i);
  }
  void cross_row(std::size_t i, const double* w, const double* mu, const SonineLambdas& l, const SonineRow& out) const override {
    const std::size_t N = law_.size();
    thread_local std::vector<double> eps;
    eps.resize(N);
    for (std::size_t j = 0; j < N; ++j) eps[j] = law_.eps(i, j);
    sonine_cross_row(N, w, eps.data(), mu, l.lambda[i], l.sqrt_lambda, l.inv_sqrt_lambda, out);
  }
  bool concurrent() const override { return true; }
  SonineTracerSums tracer(std::size_t k, std::size_t i, double weight, double mk, double mi, double Tk, double Ti, std::size_t modes,
                          bool partner_sonine) const override {
    const double eps = law_.eps(k, i), beta = mi / (mi + mk) * (1.0 + eps);
    const unsigned sources = partner_sonine ? sonine_cpq_sources : 1;
    // The β polynomials of the pair, kept up to cached_species (β, the order and the sources fixed per pair within
    // an integration): most of a pair's cost at order 4 otherwise (v1 Fig. 8: 44% of the kinetic level's time).
    const std::size_t N = law_.size();
    if (N > cached_species) return finish(sonine_pair_integrals_from(sonine_cpq_beta_polynomials(beta, modes, sources), weight, beta, Tk / mk,
                                                                      Ti / mi, modes, sources),
                                          eps, mk, mi, Tk, Ti, partner_sonine);
    if (polys_.empty()) polys_.resize(N * N);
    BetaPolynomials& cached = polys_[k * N + i];
    if (cached.beta != beta || cached.modes != modes || cached.sources != sources)
      cached = {beta, modes, sources, sonine_cpq_beta_polynomials(beta, modes, sources)};
    return finish(sonine_pair_integrals_from(cached.polys, weight, beta, Tk / mk, Ti / mi, modes, sources), eps, mk, mi, Tk, Ti, partner_sonine);
  }
  SonineMomentRates moments(std::size_t k, std::size_t i, double weight, double mk, double mi, double Tk, double Ti, int order) const override {
    // The moment table's β polynomials per ordered pair (β and the order fixed within an integration), made on first use.
    const double beta = mi / (mi + mk) * (1.0 + law_.eps(k, i));
    const std::size_t N = law_.size();
    std::call_once(moment_polys_made_, [&] { moment_polys_.resize(N * N); });  // moments() runs on threads (concurrent)
    BetaPolynomials& cached = moment_polys_[k * N + i];
    if (cached.beta != beta || cached.modes != std::size_t(order)) cached = {beta, std::size_t(order), 0, sonine_moment_beta_polynomials(beta, order)};
    return sonine_moment_pair_from(cached.polys, weight, beta, Tk / mk, Ti / mi, order);
  }
  void moments_row(std::size_t k, std::size_t N, const double* weight, const double* m, const double* T, int order,
                   SonineMomentRates* out) const override {
    // Four partners per vector (sonine_moment_pairs4_from), their β polynomials interleaved and kept per species k
    // (β and the order fixed within an integration); lanes past the last partner repeat it and are dropped.
    const std::size_t lanes = (N + 3) / 4 * 4;
    std::call_once(moment_rows_made_, [&] { moment_rows_.resize(N); });  // rows of distinct k run on threads (concurrent)
    thread_local std::vector<double> beta, Ak, Ai, w;
    for (std::vector<double>* v : {&beta, &Ak, &Ai, &w}) v->resize(lanes);
    for (std::size_t l = 0; l < lanes; ++l) {
      const std::size_t i = std::min(l, N - 1);
      beta[l] = m[i] / (m[i] + m[k]) * (1.0 + law_.eps(k, i)), Ak[l] = T[k] / m[k], Ai[l] = T[i] / m[i], w[l] = weight[i];
    }
    MomentRow& row = moment_rows_[k];
    if (row.order != order || row.beta != beta) {
      row.order = order, row.beta = beta, row.groups = sonine_moment_beta_polynomials(beta[0], order).size();
      row.polys4.assign(lanes * row.groups, 0.0);
      for (std::size_t l = 0; l < lanes; ++l) {
        const std::vector<double> p = sonine_moment_beta_polynomials(beta[l], order);
        for (std::size_t j = 0; j < row.groups; ++j) row.polys4[(l / 4 * row.groups + j) * 4 + l % 4] = p[j];
      }
    }
    for (std::size_t b = 0; b < N; b += 4)
      sonine_moment_pairs4_from(row.polys4.data() + b * row.groups, row.groups, &w[b], &beta[b], &Ak[b], &Ai[b], order, out + b,
                                std::min<std::size_t>(4, N - b));
  }

 private:
  static SonineTracerSums finish(const std::array<SonineCollisionIntegrals, sonine_cpq_sources>& C, double eps, double mk, double mi, double Tk,
                                 double Ti, bool partner_sonine) {
    SonineTracerSums s;
    s.C = C[0];
    if (partner_sonine) s.C_partner = {C[1], C[2]};
    // v1 (A2) as ξ_ki = ν_ki[(1−ε) − (1+ε) m_k(T_i−T_k)/((m_i+m_k)T_k)], ν_ki = (2/3)C₀₀: exactly 0 for ε = 1, T_i = T_k.
    s.xi = (2.0 / 3.0) * s.C(0, 0) * ((1.0 - eps) - (1.0 + eps) * mk * (Ti - Tk) / ((mi + mk) * Tk));
    return s;
  }

  static constexpr std::size_t cached_species = 300;  // as SonineDecay's pair cache
  struct BetaPolynomials {
    double beta = -1.0;
    std::size_t modes = 0;  // the C_pq's modes, or the moment table's order
    unsigned sources = 0;
    std::vector<double> polys;
  };
  const model::Restitution& law_;
  mutable std::vector<BetaPolynomials> polys_;         // per ordered pair (k, i), made on first use
  mutable std::vector<BetaPolynomials> moment_polys_;  // the same for the moment table
  mutable std::once_flag moment_polys_made_;
  struct MomentRow {  // moments_row's polynomials of species k's pairs, four partners interleaved
    int order = 0;
    std::vector<double> beta, polys4;
    std::size_t groups = 0;
  };
  mutable std::vector<MomentRow> moment_rows_;  // per species k, made on first use
  mutable std::once_flag moment_rows_made_;
};

class ImpactSpeedTerms final : public SoninePairTerms {
 public:
  explicit ImpactSpeedTerms(const model::Restitution& law) : law_(law), cache_(law.size() * (law.size() + 1) / 2) {}
  SonineMoments self(std::size_t i, double w, double lambda_i) const override {
    const double th = 0.5 / lambda_i;
    return sonine_moments(sonine_pair_quadrature(th, th, 0.5, eps_nodes(i, i, th + th)), w, th, true);
  }
  void cross_row(std::size_t i, const double* w, const double* mu, const SonineLambdas& l, const SonineRow& out) const override {
    const double th_i = 0.5 / l.lambda[i];
    for (std::size_t j = 0; j < law_.size(); ++j) {
      const double th_j = 0.5 / l.lambda[j];
      const SonineMoments m = j == i ? SonineMoments{} : sonine_moments(sonine_pair_quadrature(th_i, th_j, mu[j], eps_nodes(i, j, th_i + th_j)), w[j], th_i, false);
      out.zeta0[j] = m.zeta0, out.zeta_self[j] = m.zeta_self, out.zeta_cross[j] = m.zeta_cross;
      out.Lambda0[j] = m.Lambda0, out.Lambda_self[j] = m.Lambda_self, out.Lambda_cross[j] = m.Lambda_cross;
    }
  }
  bool concurrent() const override { return false; }
  SonineTracerSums tracer(std::size_t k, std::size_t i, double weight, double mk, double mi, double Tk, double Ti, std::size_t modes,
                          bool) const override {  // the partner's a₂, a₃ terms exist in closed form only (left zero)
    const double Ak = Tk / mk, Ai = Ti / mi;
    const PairSonineIntegrals q = sonine_pair_quadrature(Ak, Ai, mi / (mi + mk), eps_nodes(k, i, Ak + Ai), modes);
    SonineTracerSums s{{}, -weight * q.energy[0] / (3.0 * Ak)};
    s.C.add(q.C, weight);
    return s;
  }
  SonineMomentRates moments(std::size_t k, std::size_t i, double weight, double mk, double mi, double Tk, double Ti, int order) const override {
    const double Ak = Tk / mk, Ai = Ti / mi;
    SonineMomentRates H = sonine_moment_quadrature(Ak, Ai, mi / (mi + mk), eps_nodes(k, i, Ak + Ai), order);
    for (double& x : H) x *= weight;
    return H;
  }

 private:
  // ε at the quadrature's impact speeds for the unordered pair {k, i} (ε_ki = ε_ik) at V = θ_k + θ_i, kept
  // for the next call at the same V to rounding (1e-14 relative: the two closures compute V as T/m and as
  // 1/(2λ)); evaluating the exact contact table is most of the cost of a pair.
  const double* eps_nodes(std::size_t k, std::size_t i, double V) const {
    const std::size_t a = std::min(k, i), b = std::max(k, i), N = law_.size();
    Nodes& c = cache_[a * (2 * N - a + 1) / 2 + (b - a)];
    if (c.eps.empty() || std::abs(V - c.V) > 1e-14 * V) {
      c.eps.resize(sonine_quadrature_nodes());
      sonine_quadrature_speeds(V, c.eps.data());
      for (double& u : c.eps) u = law_.eps_at(k, i, u);
      c.V = V;
    }
    return c.eps.data();
  }
  struct Nodes {
    double V = 0.0;
    std::vector<double> eps;
  };
  const model::Restitution& law_;
  mutable std::vector<Nodes> cache_;
};

}  // namespace

void SoninePairTerms::moments_row(std::size_t k, std::size_t N, const double* weight, const double* m, const double* T, int order,
                                  SonineMomentRates* out) const {
  for (std::size_t i = 0; i < N; ++i) out[i] = moments(k, i, weight[i], m[k], m[i], T[k], T[i], order);
}

std::shared_ptr<const SoninePairTerms> make_sonine_pair_terms(const model::Restitution& law) {
  if (law.is_viscoelastic()) return std::make_shared<ImpactSpeedTerms>(law);
  return std::make_shared<ClosedFormTerms>(law);
}

}  // namespace granmix::theory
