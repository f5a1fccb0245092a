#include "theory/rates/collision_rates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "theory/numerics/vector_clones.hpp"

namespace granmix::theory {

namespace {

const double rate_constant = 4.0 / 3.0 * std::sqrt(2.0 * std::numbers::pi);

// One pair's weights (collision_rates.hpp): a_ki = σ_ki² χ_ki √V μ_ki, a_ik (the same with μ_ik) and
// p_ki = σ_ki² χ_ki √V μ_ki μ_ik (T_i − T_k), from the inverse masses x = 1/m (μ_ki = m_i/(m_i+m_k)
// = x_k/(x_k+x_i)). Exchanging k and i gives a_ik, a_ki and −p_ki to the last bit (each operation
// is commutative in the pair), so the pass over unordered pairs, which evaluates it once, and the
// single-row sums agree.
struct PairWeights {
  double a_ki, a_ik, p_ki;
};
inline PairWeights pair_weights(double sk, double si, double chi, double xk, double xi, double Tk, double Ti) {
  const double s = 0.5 * (sk + si), q = 1.0 / (xk + xi);  // σ_ki = (σ_k + σ_i)/2
  const double w = s * s * chi * std::sqrt(Tk * xk + Ti * xi) * q;
  return {w * xk, w * xi, w * q * (xk * xi) * (Ti - Tk)};
}

// The per-species inputs of a pass and its sums (RowSums of every k: S_D, S_W, U_W; with uniform
// moments only S = S_D and U = U_W).
struct PassInput {
  std::size_t N;
  const double *T, *x, *n, *sigma;
  const double* const* chi;  // row k: χ_ki, i = 0 … N−1
  const double *W2, *D;  // per_pair: the moments of every link (packed upper triangle)
  double *S_D, *S_W, *U_W;
};

// Row k starts with the contributions of the rows before it and adds its own terms i = k … N−1 in
// order, so each sum runs over i = 0 … N−1 exactly as CollisionRates::row_sums (same numbers).
template <bool per_pair>
[[gnu::always_inline]] inline void pair_pass(std::size_t N, const double* __restrict T, const double* __restrict x,
                                             const double* __restrict n, const double* __restrict sigma,
                                             const double* const* chi, const double* __restrict W2,
                                             const double* __restrict D, double* __restrict S_D, double* __restrict S_W,
                                             double* __restrict U_W) {
  for (std::size_t k = 0; k < N; ++k) {
    S_D[k] = 0.0, U_W[k] = 0.0;
    if (per_pair) S_W[k] = 0.0;
  }
  constexpr std::size_t B = 256;
  double row_SD[B], row_SW[B], row_UW[B];
  std::size_t l = 0;  // index of the link (k, k)
  for (std::size_t k = 0; k < N; ++k) {
    const double Tk = T[k], xk = x[k], nk = n[k], sk = sigma[k];
    const double* __restrict chi_k = chi[k];
    double sD = S_D[k], sW = per_pair ? S_W[k] : 0.0, uW = U_W[k];
    {  // i = k
      const PairWeights P = pair_weights(sk, sk, chi_k[k], xk, xk, Tk, Tk);
      const double na = nk * P.a_ki, np = nk * P.p_ki;
      if (per_pair)
        sD += na * D[l], sW += na * W2[l], uW += np * W2[l];
      else
        sD += na, uW += np;
      ++l;
    }
    // Blocks of partners: the terms are independent in i (they vectorise: sqrt, division); the row
    // sums then add them in order from a buffer on the stack.
    for (std::size_t i0 = k + 1; i0 < N; i0 += B) {
      const std::size_t m = std::min(B, N - i0);
      for (std::size_t j = 0; j < m; ++j) {
        const std::size_t i = i0 + j;
        const PairWeights P = pair_weights(sk, sigma[i], chi_k[i], xk, x[i], Tk, T[i]);
        const double na = n[i] * P.a_ki, np = n[i] * P.p_ki, na_i = nk * P.a_ik, np_i = nk * P.p_ki;
        if (per_pair) {
          const double w2 = W2[l + j], d = D[l + j];
          row_SD[j] = na * d, row_SW[j] = na * w2, row_UW[j] = np * w2;
          S_D[i] += na_i * d, S_W[i] += na_i * w2, U_W[i] -= np_i * w2;  // p_ik = −p_ki
        } else {
          row_SD[j] = na, row_UW[j] = np;
          S_D[i] += na_i, U_W[i] -= np_i;
        }
      }
      for (std::size_t j = 0; j < m; ++j) {
        sD += row_SD[j], uW += row_UW[j];
        if (per_pair) sW += row_SW[j];
      }
      l += m;
    }
    S_D[k] = sD, U_W[k] = uW;
    if (per_pair) S_W[k] = sW;
  }
}

// The pass is most of the theory's time with many species: compiled also for AVX2 and AVX-512,
// chosen at run time. FMA contraction is off for this file (CMakeLists.txt), so every version gives
// the same numbers (IEEE +, ×, ÷ and √ round exactly once, in the same order).
GRANMIX_VECTOR_CLONES void pass_uniform(const PassInput& in) {
  pair_pass<false>(in.N, in.T, in.x, in.n, in.sigma, in.chi, in.W2, in.D, in.S_D, in.S_W, in.U_W);
}
GRANMIX_VECTOR_CLONES void pass_per_pair(const PassInput& in) {
  pair_pass<true>(in.N, in.T, in.x, in.n, in.sigma, in.chi, in.W2, in.D, in.S_D, in.S_W, in.U_W);
}

// Adds pair term n_i a_ki and n_i p_ki to a row's sums.
inline void add_pair(double& S_D, double& S_W, double& U_W, double na, double np, bool per_pair, const CollisionMoments& W) {
  if (per_pair)
    S_D += na * W.D, S_W += na * W.W2, U_W += np * W.W2;
  else
    S_D += na, U_W += np;
}

}  // namespace

std::vector<double> CollisionRates::key() const {
  std::vector<double> key;
  const std::size_t N = size();
  for (std::size_t k = 0; k < N; ++k) {
    key.insert(key.end(), {mix_[k].mass, mix_[k].diameter, mix_[k].density});
    for (std::size_t i = 0; i < N; ++i) key.insert(key.end(), {law_.eps(k, i), chi_[k][i]});
  }
  return key;
}

CollisionRates::CollisionRates(model::Mixture mix, model::Restitution law, std::vector<std::vector<double>> chi,
                               MomentMethod method)
    : mix_(std::move(mix)), law_(std::move(law)), chi_(std::move(chi)), method_(method) {
  const std::size_t N = mix_.size();
  if (law_.size() != N) throw std::invalid_argument("collision rates: restitution must have one row per species");
  // The rates are sums over all N² pairs (v1 Eqs. 20, 23), one pass per call: refuse what would not
  // fit rather than fail in the allocator or run for hours.
  const double links = 0.5 * double(N) * double(N + 1), chi_bytes = 8.0 * double(N) * double(N);
  auto check_size = [&](double bytes) {
    if (bytes > max_pair_data_bytes)
      throw std::invalid_argument(fmt::format(
          "theory: {} species need {:.1f} GB of pair data (χ: N² × 8 bytes{}); the limit is {:.0f} GB, about {} species "
          "with one ε for all pairs", N, bytes / 1e9, bytes > chi_bytes ? ", moments: N(N+1)/2 × 16 bytes" : "",
          max_pair_data_bytes / 1e9, std::size_t(std::sqrt(max_pair_data_bytes / 8.0))));
  };
  check_size(chi_bytes);
  bool uniform = !law_.is_viscoelastic();
  for (std::size_t k = 0; k < N && uniform; ++k)
    for (std::size_t i = k; i < N && uniform; ++i) uniform = law_.eps(k, i) == law_.eps(0, 0);
  if (!uniform) check_size(chi_bytes + 16.0 * links);
  if (chi_.size() != N) throw std::invalid_argument("collision rates: χ must have one row per species");
  for (std::size_t k = 0; k < N; ++k) {
    if (chi_[k].size() != N) throw std::invalid_argument("collision rates: χ must have one column per species");
    // The pass over unordered pairs reads χ_ki for both directions (the pair correlation at contact).
    for (std::size_t i = 0; i < k; ++i)
      if (chi_[k][i] != chi_[i][k])
        throw std::invalid_argument(fmt::format("collision rates: χ must be symmetric (χ_{}{} = {} but χ_{}{} = {})", k, i,
                                                chi_[k][i], i, k, chi_[i][k]));
  }
  if (method_ == MomentMethod::automatic)
    method_ = (law_.is_viscoelastic() && law_.form() != model::ViscoelasticForm::series) ? MomentMethod::quadrature
                                                                                         : MomentMethod::series;
  for (std::size_t k = 0; k < N; ++k) {
    inv_m_.push_back(1.0 / mix_[k].mass);
    density_.push_back(mix_[k].density);
    diameter_.push_back(mix_[k].diameter);
  }
  // The pass reads χ by rows; equal contact values (the dilute gas) all read one row of N values,
  // which stays in cache instead of streaming N² of them per call.
  bool same_chi = true;
  for (std::size_t k = 0; k < N && same_chi; ++k)
    for (std::size_t i = k; i < N && same_chi; ++i) same_chi = chi_[k][i] == chi_[0][0];
  if (same_chi && N > 0) chi_uniform_row_.assign(N, chi_[0][0]);
  for (std::size_t k = 0; k < N; ++k) chi_rows_.push_back(same_chi ? chi_uniform_row_.data() : chi_[k].data());
  uniform_moments_ = uniform && N > 0;
  if (uniform_moments_) W_ = constant_moments(law_.eps(0, 0));
  if (!uniform && !law_.is_viscoelastic()) {
    W2_.reserve(std::size_t(links)), D_.reserve(std::size_t(links));
    for (std::size_t k = 0; k < N; ++k)
      for (std::size_t i = k; i < N; ++i) {
        const CollisionMoments W = constant_moments(law_.eps(k, i));
        W2_.push_back(W.W2), D_.push_back(W.D);
      }
  }
}

CollisionMoments CollisionRates::moments(std::size_t k, std::size_t i, double V) const {
  if (!law_.is_viscoelastic()) return constant_moments(law_.eps(k, i));
  const double a = viscoelastic_scale(law_.akappa(k, i), V);
  return method_ == MomentMethod::series ? series_moments(a) : quadrature_moments(a, law_.form());
}

CollisionRates::RowSums CollisionRates::pair_sums(std::size_t k, std::size_t i, double Tk, double Ti) const {
  const PairWeights P = pair_weights(diameter_[k], diameter_[i], chi_[k][i], inv_m_[k], inv_m_[i], Tk, Ti);
  const CollisionMoments W = uniform_moments_ ? W_ : moments(k, i, Tk * inv_m_[k] + Ti * inv_m_[i]);
  RowSums r;
  add_pair(r.S_D, r.S_W, r.U_W, density_[i] * P.a_ki, density_[i] * P.p_ki, !uniform_moments_, W);
  if (uniform_moments_) r.S_W = r.S_D;
  return r;
}

CollisionRates::RowSums CollisionRates::row_sums(std::size_t k, const double* T) const {
  RowSums r;
  for (std::size_t i = 0; i < mix_.size(); ++i) {
    const RowSums p = pair_sums(k, i, T[k], T[i]);
    r.S_D += p.S_D, r.S_W += p.S_W, r.U_W += p.U_W;
  }
  return r;
}

void CollisionRates::finish(const RowSums& r, double Tk, double* xi, double* inv_tau) const {
  const double D = uniform_moments_ ? W_.D : 1.0, W2 = uniform_moments_ ? W_.W2 : 1.0, u = r.U_W * (1.0 / Tk);
  if (xi) *xi = rate_constant * (D * r.S_D - W2 * u);
  if (inv_tau) *inv_tau = rate_constant * 0.5 * (W2 * (r.S_W + u));
}

double CollisionRates::xi(std::size_t k, std::size_t i, double Tk, double Ti) const {
  double out = 0.0;
  finish(pair_sums(k, i, Tk, Ti), Tk, &out, nullptr);
  return out;
}

double CollisionRates::inv_tau_v(std::size_t k, std::size_t i, double Tk, double Ti) const {
  double out = 0.0;
  finish(pair_sums(k, i, Tk, Ti), Tk, nullptr, &out);
  return out;
}

double CollisionRates::xi_species(std::size_t k, const double* T) const {
  double out = 0.0;
  finish(row_sums(k, T), T[k], &out, nullptr);
  return out;
}

double CollisionRates::inv_tau_v_species(std::size_t k, const double* T) const {
  double out = 0.0;
  finish(row_sums(k, T), T[k], nullptr, &out);
  return out;
}

void CollisionRates::symmetric_sums(const double* T, double* xi, double* inv_tau) const {
  const std::size_t N = mix_.size();
  std::vector<double> S_D(N), S_W(uniform_moments_ ? 0 : N), U_W(N), W2_at_T, D_at_T;
  PassInput in{N, T, inv_m_.data(), density_.data(), diameter_.data(), chi_rows_.data(), W2_.data(), D_.data(), S_D.data(), S_W.data(), U_W.data()};
  if (law_.is_viscoelastic()) {
    // The moments depend on the pair and on V = T_k/m_k + T_i/m_i only, which both directions
    // share: one evaluation (two quadratures) per unordered pair.
    W2_at_T.resize(N * (N + 1) / 2), D_at_T.resize(W2_at_T.size());
    for (std::size_t k = 0, l = 0; k < N; ++k)
      for (std::size_t i = k; i < N; ++i, ++l) {
        const CollisionMoments W = moments(k, i, T[k] * inv_m_[k] + T[i] * inv_m_[i]);
        W2_at_T[l] = W.W2, D_at_T[l] = W.D;
      }
    in.W2 = W2_at_T.data(), in.D = D_at_T.data();
  }
  if (uniform_moments_)
    pass_uniform(in);
  else
    pass_per_pair(in);
  for (std::size_t k = 0; k < N; ++k)
    finish({S_D[k], uniform_moments_ ? S_D[k] : S_W[k], U_W[k]}, T[k], xi ? xi + k : nullptr, inv_tau ? inv_tau + k : nullptr);
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
