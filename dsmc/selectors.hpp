#pragma once
// Pair selectors of the exact event-driven DSMC (design.md §5). Each proposes an ordered pair of
// particles (a, b) of species (i, k) from a majorant process of total rate total_rate(), and a
// scale such that accepting with probability |g|/scale gives every unordered pair {a, b} its true
// collision rate π σ_ik² χ_ik |g| / V (physics.md §1).
//
// Normalisation (v1 Eq. 12 as printed drops N_i N_k; derived here): proposing the ordered pair (a,b)
// with rate π σ_ik² χ̂ vmax_i / V, the unordered pair is proposed at π σ_ik² χ̂ (vmax_i + vmax_k)/V,
// which bounds its true rate because |g| <= vmax_i + vmax_k. Summed over ordered pairs (self pairs
// included and rejected): Γ = (π/V) Σ_ik N_i vmax_i N_k σ_ik² χ̂_ik.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "pair_table.hpp"
#include "particles.hpp"
#include "rng.hpp"
#include "sum_tree.hpp"

namespace granmix::dsmc {

struct Proposal {
  std::size_t a, b, i, k;
  double scale;  // accept iff u * scale < |g|
};

// M×M table of majorants with the exact χ_ik of every pair: for few species.
class DirectSelector {
 public:
  DirectSelector(const PairTable& pairs, const Particles& p) : pairs_(pairs), vmax_(p.species()), tree_(weights(p)) {}
  double total_rate() const { return std::numbers::pi / pairs_.volume * tree_.total(); }
  Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t M = pairs_.M, cell = tree_.sample(rng.uniform()), i = cell / M, k = cell % M;
    return {p.begin(i) + rng.below(p.count(i)), p.begin(k) + rng.below(p.count(k)), i, k, vmax_[i] + vmax_[k]};
  }
  void raise_speed(std::size_t i, double speed, const Particles& p) {
    if (speed <= vmax_[i]) return;
    vmax_[i] = speed;
    update_row(i, p);
  }
  void refresh(const Particles& p) {
    for (std::size_t i = 0; i < pairs_.M; ++i) vmax_[i] = speed_max(p, i), update_row(i, p);
  }

 private:
  std::vector<double> weights(const Particles& p) {
    const std::size_t M = pairs_.M;
    for (std::size_t i = 0; i < M; ++i) vmax_[i] = speed_max(p, i);
    std::vector<double> w(M * M);
    for (std::size_t i = 0; i < M; ++i)
      for (std::size_t k = 0; k < M; ++k) w[i * M + k] = weight(i, k, p);
    return w;
  }
  double weight(std::size_t i, std::size_t k, const Particles& p) const {
    const std::size_t M = pairs_.M;
    return double(p.count(i)) * vmax_[i] * double(p.count(k)) * pairs_.sigma2[i * M + k] * pairs_.chi[i * M + k];
  }
  void update_row(std::size_t i, const Particles& p) {
    for (std::size_t k = 0; k < pairs_.M; ++k) tree_.set(i * pairs_.M + k, weight(i, k, p));
  }
  const PairTable& pairs_;
  std::vector<double> vmax_;
  SumTree tree_;
};

// The low-rank method of the source paper (v1 Eqs. 12–14): σ_ik² = (σ_i² + 2σ_iσ_k + σ_k²)/4 makes
// N_i vmax_i N_k σ_ik² a sum of three rank-1 terms u_i^(r) v_k^(r); i is drawn from a sum tree over
// u^(r) (which changes with vmax_i), k from a sum tree over the fixed v^(r). O(log M) per proposal
// and per speed update. Enskog χ_ik is not low-rank: the majorant uses χ_max and the acceptance
// carries χ_ik/χ_max (exact, at the price of more rejections).
class LowRankSelector {
 public:
  LowRankSelector(const PairTable& pairs, const Particles& p) : pairs_(pairs), vmax_(p.species()) {
    const std::size_t M = pairs_.M;
    for (std::size_t i = 0; i < M; ++i) vmax_[i] = speed_max(p, i);
    std::array<std::vector<double>, 3> u, v;
    for (int r = 0; r < 3; ++r) u[r].resize(M), v[r].resize(M);
    for (std::size_t i = 0; i < M; ++i) {
      const double n = double(p.count(i)), s = pairs_.sigma[i];
      v[0][i] = n, v[1][i] = n * s, v[2][i] = n * s * s;
      for (int r = 0; r < 3; ++r) u[r][i] = u_weight(r, i, p);
    }
    for (int r = 0; r < 3; ++r) u_.emplace_back(u[r]), v_.emplace_back(v[r]);
  }
  double total_rate() const { return std::numbers::pi * pairs_.chi_max / (4.0 * pairs_.volume) * sum(); }
  Proposal propose(Rng& rng, const Particles& p) const {
    // Term r with probability U_r V_r / Σ; then i ∝ u_i^(r), k ∝ v_k^(r).
    const double x = rng.uniform() * sum();
    const double t0 = u_[0].total() * v_[0].total(), t1 = u_[1].total() * v_[1].total();
    const int r = x < t0 ? 0 : (x < t0 + t1 ? 1 : 2);
    const std::size_t i = u_[r].sample(rng.uniform()), k = v_[r].sample(rng.uniform());
    const double chi_ratio = pairs_.chi_max / pairs_.chi[i * pairs_.M + k];
    return {p.begin(i) + rng.below(p.count(i)), p.begin(k) + rng.below(p.count(k)), i, k, chi_ratio * (vmax_[i] + vmax_[k])};
  }
  void raise_speed(std::size_t i, double speed, const Particles& p) {
    if (speed <= vmax_[i]) return;
    vmax_[i] = speed;
    for (int r = 0; r < 3; ++r) u_[r].set(i, u_weight(r, i, p));
  }
  void refresh(const Particles& p) {
    for (std::size_t i = 0; i < pairs_.M; ++i) {
      vmax_[i] = speed_max(p, i);
      for (int r = 0; r < 3; ++r) u_[r].set(i, u_weight(r, i, p));
    }
  }

 private:
  // u^(1) = N vmax σ², u^(2) = 2 N vmax σ, u^(3) = N vmax; paired with v = N, N σ, N σ².
  double u_weight(int r, std::size_t i, const Particles& p) const {
    const double s = pairs_.sigma[i], base = double(p.count(i)) * vmax_[i];
    return r == 0 ? base * s * s : (r == 1 ? 2.0 * base * s : base);
  }
  double sum() const {
    return u_[0].total() * v_[0].total() + u_[1].total() * v_[1].total() + u_[2].total() * v_[2].total();
  }
  const PairTable& pairs_;
  std::vector<double> vmax_;
  std::vector<SumTree> u_, v_;
};

// Bird's method, the comparison of the v2 paper: one global bound σ_max² χ_max 2 vmax for every
// pair, particles drawn uniformly from the whole system.
class BirdSelector {
 public:
  BirdSelector(const PairTable& pairs, const Particles& p) : pairs_(pairs) { refresh(p); }
  double total_rate() const {
    const double N = double(n_);
    return std::numbers::pi / pairs_.volume * N * N * pairs_.sigma2_max * pairs_.chi_max * vmax_;
  }
  Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t a = rng.below(n_), b = rng.below(n_);
    const std::size_t i = species_of(a, p), k = species_of(b, p), ik = i * pairs_.M + k;
    const double scale = pairs_.sigma2_max * pairs_.chi_max / (pairs_.sigma2[ik] * pairs_.chi[ik]) * 2.0 * vmax_;
    return {a, b, i, k, scale};
  }
  void raise_speed(std::size_t, double speed, const Particles&) { vmax_ = std::max(vmax_, speed); }
  void refresh(const Particles& p) {
    n_ = p.size();
    vmax_ = 0.0;
    for (std::size_t k = 0; k < p.species(); ++k) vmax_ = std::max(vmax_, speed_max(p, k));
  }

 private:
  static std::size_t species_of(std::size_t a, const Particles& p) {
    return static_cast<std::size_t>(std::upper_bound(p.offset.begin(), p.offset.end(), a) - p.offset.begin()) - 1;
  }
  const PairTable& pairs_;
  std::size_t n_ = 0;
  double vmax_ = 0.0;
};

}  // namespace granmix::dsmc
