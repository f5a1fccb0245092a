#include "collision_rates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granmix::theory {

CollisionRates::CollisionRates(model::Mixture mix, model::Restitution law, std::vector<std::vector<double>> chi,
                               MomentMethod method)
    : mix_(std::move(mix)), law_(std::move(law)), chi_(std::move(chi)), method_(method) {
  const std::size_t N = mix_.size();
  // The rates are sums over all N² pairs (v1 Eqs. 20, 23) with a table of pair constants: refuse
  // what would not fit rather than fail in the allocator or run for hours.
  const double links = 0.5 * double(N) * double(N + 1);
  if (links * link_bytes > max_pair_table_bytes)
    throw std::invalid_argument(fmt::format("theory: {} species need a pair table of {:.1f} GB (N(N+1)/2 × {} bytes); the limit is {:.0f} GB, "
                                            "about {} species", N, links * link_bytes / 1e9, link_bytes, max_pair_table_bytes / 1e9,
                                            std::size_t(std::sqrt(2.0 * max_pair_table_bytes / link_bytes))));
  if (law_.size() != N || chi_.size() != N)
    throw std::invalid_argument("collision rates: restitution and χ must have one row per species");
  if (method_ == MomentMethod::automatic)
    method_ = (law_.is_viscoelastic() && law_.form() != model::ViscoelasticForm::series) ? MomentMethod::quadrature
                                                                                         : MomentMethod::series;
  const double c = 4.0 / 3.0 * std::sqrt(2.0 * std::numbers::pi);
  for (std::size_t k = 0; k < N; ++k) inv_m_.push_back(1.0 / mix_[k].mass);
  for (std::vector<double>* v : {&links_.pref_ki, &links_.pref_ik, &links_.mu_ki, &links_.mu_ik, &links_.W2, &links_.D})
    v->reserve(std::size_t(links));
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t i = k; i < N; ++i) {
      const double s = mix_.sigma(k, i);
      const double mk = mix_[k].mass, mi = mix_[i].mass;
      const CollisionMoments W = law_.is_viscoelastic() ? CollisionMoments{} : constant_moments(law_.eps(k, i));
      links_.pref_ki.push_back(c * mix_[i].density * s * s * chi_[k][i]);
      links_.pref_ik.push_back(c * mix_[k].density * s * s * chi_[i][k]);
      links_.mu_ki.push_back(mi / (mi + mk));
      links_.mu_ik.push_back(mk / (mi + mk));
      links_.W2.push_back(W.W2);
      links_.D.push_back(W.D);
    }
}

CollisionRates::Pair CollisionRates::pair(std::size_t k, std::size_t i) const {
  const std::size_t j = link_index(std::min(k, i), std::max(k, i));
  if (k <= i) return {links_.pref_ki[j], links_.mu_ki[j], links_.mu_ik[j], inv_m_[k], inv_m_[i]};
  return {links_.pref_ik[j], links_.mu_ik[j], links_.mu_ki[j], inv_m_[k], inv_m_[i]};
}

CollisionMoments CollisionRates::moments(std::size_t k, std::size_t i, double V) const {
  if (!law_.is_viscoelastic()) return constant_moments(law_.eps(k, i));
  const double a = viscoelastic_scale(law_.akappa(k, i), V);
  return method_ == MomentMethod::series ? series_moments(a) : quadrature_moments(a, law_.form());
}

double CollisionRates::xi(std::size_t k, std::size_t i, double Tk, double Ti) const {
  const Pair p = pair(k, i);
  const double V = Tk * p.inv_mk + Ti * p.inv_mi;
  return xi_formula(p.prefactor, p.mu, p.mu_k, std::sqrt(V), Tk, Ti, moments(k, i, V));
}

double CollisionRates::inv_tau_v(std::size_t k, std::size_t i, double Tk, double Ti) const {
  const Pair p = pair(k, i);
  const double V = Tk * p.inv_mk + Ti * p.inv_mi;
  return inv_tau_formula(p.prefactor, p.mu, p.mu_k, std::sqrt(V), Tk, Ti, moments(k, i, V));
}

double CollisionRates::xi_species(std::size_t k, const double* T) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < mix_.size(); ++i) sum += xi(k, i, T[k], T[i]);
  return sum;
}

double CollisionRates::inv_tau_v_species(std::size_t k, const double* T) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < mix_.size(); ++i) sum += inv_tau_v(k, i, T[k], T[i]);
  return sum;
}

namespace {

// The loop of CollisionRates::symmetric_sums for the requested outputs (compile-time flags). Row k
// starts with the contributions of the rows before it and adds its own terms i = k … N−1 in order,
// so each sum runs over i = 0 … N−1 exactly as a per-species loop would (same numbers).
// W2, D: the moments of every link (packed like Links).
template <bool with_xi, bool with_tau, class Links, class XiF, class TauF>
void pair_pass(std::size_t N, const double* __restrict T, const double* __restrict inv_m, const Links& L,
               const double* __restrict W2, const double* __restrict D, double* __restrict xi,
               double* __restrict inv_tau, XiF xi_f, TauF tau_f) {
  for (std::size_t k = 0; k < N; ++k) {
    if (with_xi) xi[k] = 0.0;
    if (with_tau) inv_tau[k] = 0.0;
  }
  const double *pref_ki = L.pref_ki.data(), *pref_ik = L.pref_ik.data(), *mu_ki = L.mu_ki.data(), *mu_ik = L.mu_ik.data();
  constexpr std::size_t B = 256;
  double row_terms_xi[B], row_terms_tau[B];
  std::size_t l = 0;  // index of the link (k, k)
  for (std::size_t k = 0; k < N; ++k) {
    const double Tk = T[k], ik = inv_m[k];
    double row_xi = 0.0, row_tau = 0.0;
    {  // i = k
      const double sqrtV = std::sqrt(Tk * ik + Tk * ik);
      const CollisionMoments W{W2[l], D[l]};
      if (with_xi) row_xi = xi[k] + xi_f(pref_ki[l], mu_ki[l], mu_ik[l], sqrtV, Tk, Tk, W);
      if (with_tau) row_tau = inv_tau[k] + tau_f(pref_ki[l], mu_ki[l], mu_ik[l], sqrtV, Tk, Tk, W);
      ++l;
    }
    // Blocks of partners: the terms are independent in i (they vectorise: sqrt, division); the row
    // sums then add them in order from a buffer on the stack.
    for (std::size_t i0 = k + 1; i0 < N; i0 += B) {
      const std::size_t n = std::min(B, N - i0);
      for (std::size_t j = 0; j < n; ++j) {
        const std::size_t i = i0 + j, p = l + j;
        const double Ti = T[i], sqrtV = std::sqrt(Tk * ik + Ti * inv_m[i]);
        const CollisionMoments W{W2[p], D[p]};
        if (with_xi) {
          row_terms_xi[j] = xi_f(pref_ki[p], mu_ki[p], mu_ik[p], sqrtV, Tk, Ti, W);
          xi[i] += xi_f(pref_ik[p], mu_ik[p], mu_ki[p], sqrtV, Ti, Tk, W);
        }
        if (with_tau) {
          row_terms_tau[j] = tau_f(pref_ki[p], mu_ki[p], mu_ik[p], sqrtV, Tk, Ti, W);
          inv_tau[i] += tau_f(pref_ik[p], mu_ik[p], mu_ki[p], sqrtV, Ti, Tk, W);
        }
      }
      for (std::size_t j = 0; j < n; ++j) {
        if (with_xi) row_xi += row_terms_xi[j];
        if (with_tau) row_tau += row_terms_tau[j];
      }
      l += n;
    }
    if (with_xi) xi[k] = row_xi;
    if (with_tau) inv_tau[k] = row_tau;
  }
}

}  // namespace

void CollisionRates::symmetric_sums(const double* T, double* xi, double* inv_tau) const {
  const std::size_t N = mix_.size();
  const double *W2 = links_.W2.data(), *D = links_.D.data();
  std::vector<double> W2_at_T, D_at_T;
  if (law_.is_viscoelastic()) {
    // The moments depend on the pair and on V = T_k/m_k + T_i/m_i only, which both directions
    // share: one evaluation (two quadratures) per unordered pair instead of one per ordered pair
    // and per output (a quarter of the quadratures for ξ and τ_v⁻¹ together).
    W2_at_T.resize(links_.W2.size()), D_at_T.resize(links_.D.size());
    for (std::size_t k = 0, l = 0; k < N; ++k)
      for (std::size_t i = k; i < N; ++i, ++l) {
        const CollisionMoments W = moments(k, i, T[k] * inv_m_[k] + T[i] * inv_m_[i]);
        W2_at_T[l] = W.W2, D_at_T[l] = W.D;
      }
    W2 = W2_at_T.data(), D = D_at_T.data();
  }
  const auto xi_f = [](auto... a) { return xi_formula(a...); };  // lambdas: inlined into the pass
  const auto tau_f = [](auto... a) { return inv_tau_formula(a...); };
  if (xi && inv_tau)
    pair_pass<true, true>(N, T, inv_m_.data(), links_, W2, D, xi, inv_tau, xi_f, tau_f);
  else if (xi)
    pair_pass<true, false>(N, T, inv_m_.data(), links_, W2, D, xi, nullptr, xi_f, tau_f);
  else
    pair_pass<false, true>(N, T, inv_m_.data(), links_, W2, D, nullptr, inv_tau, xi_f, tau_f);
}

void CollisionRates::xi_all(const double* T, double* out) const { symmetric_sums(T, out, nullptr); }

void CollisionRates::inv_tau_v_all(const double* T, double* out) const { symmetric_sums(T, nullptr, out); }

void CollisionRates::xi_and_inv_tau_v_all(const double* T, double* xi, double* inv_tau) const {
  symmetric_sums(T, xi, inv_tau);
}

double CollisionRates::diffusion(std::size_t k, const double* T) const {
  return T[k] / (inv_tau_v_species(k, T) * mix_[k].mass);
}

}  // namespace granmix::theory
