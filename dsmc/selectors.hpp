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

#include "alias_table.hpp"
#include "pair_table.hpp"
#include "particles.hpp"
#include "rng.hpp"
#include "speed_classes.hpp"
#include "sum_tree.hpp"

namespace granmix::dsmc {

struct Proposal {
  std::size_t a, b, i, k;
  double scale;  // accept iff u * scale < |g|
};

// Selectors draw the first particle of a pair from a speed class (dsmc/speed_classes.hpp) and use
// class bounds for the majorant: bound(class a) + bound(class b) >= |v_a| + |v_b| >= |g|. With one
// class per species this is the paper's N_i vmax_i N_k σ_ik² majorant. After a collision the
// event loop reports each particle's new speed through moved(); it returns true when the selector's
// state (weights, bounds, particle order) changed.

// A table over (class of i, species k) of majorants with the exact χ_ik of every pair: for few species.
class DirectSelector {
 public:
  DirectSelector(const PairTable& pairs, Particles& p, std::size_t classes = 1)
      : pairs_(pairs), cls_(p, classes), tree_(std::vector<double>(cls_.units() * pairs.M, 0.0)) {
    refresh_weights(p);
  }
  double total_rate() const { return std::numbers::pi / pairs_.volume * tree_.total(); }
  Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t M = pairs_.M, cell = tree_.sample(rng.uniform()), u = cell / M, k = cell % M, i = cls_.species_of(u);
    const std::size_t a = cls_.begin(u) + rng.below(cls_.count(u)), b = p.begin(k) + rng.below(p.count(k));
    return {a, b, i, k, cls_.bound(u) + cls_.bound(cls_.unit_of(b, k))};
  }
  const SpeedClasses& classes() const { return cls_; }
  bool moved(std::size_t a, std::size_t i, std::size_t& other, Particles& p) {
    bool changed = false;
    cls_.moved(p, a, i, other, [&](std::size_t u) { update_unit(u, p), changed = true; });
    return changed;
  }
  void refresh(Particles& p) {
    cls_.refresh(p);
    refresh_weights(p);
  }

 private:
  void refresh_weights(const Particles& p) {
    for (std::size_t u = 0; u < cls_.units(); ++u) update_unit(u, p);
  }
  void update_unit(std::size_t u, const Particles& p) {
    const std::size_t i = cls_.species_of(u);
    for (std::size_t k = 0; k < pairs_.M; ++k)
      tree_.set(u * pairs_.M + k, double(cls_.count(u)) * cls_.bound(u) * double(p.count(k)) * pairs_.sigma2(i, k) * pairs_.chi(i, k));
  }
  const PairTable& pairs_;
  SpeedClasses cls_;
  SumTree tree_;
};

// The low-rank method of the source paper (v1 Eqs. 12–14): σ_ik² = (σ_i² + 2σ_iσ_k + σ_k²)/4 makes
// the majorant N_i vmax_i N_k σ_ik² a sum of three rank-1 terms. Summed over k, the majorant of a
// class u of species i is W_u = N_u bound_u (σ_i² S_0 + 2σ_i S_1 + S_2) with S_r = Σ_k N_k σ_k^r, so u
// is drawn from one sum tree over W_u (O(log MC) per proposal and per update), then the term r with
// probability ∝ (σ_i² S_0, 2σ_i S_1, S_2), then k from the fixed weights N_k σ_k^r by an alias table
// (O(1)). (Drawing r first and i, k from three trees gives the same pair law with three descents.)
// Enskog χ_ik is not low-rank: the majorant uses χ_max and the acceptance carries χ_ik/χ_max
// (exact, at the price of more rejections).
class LowRankSelector {
 public:
  LowRankSelector(const PairTable& pairs, Particles& p, std::size_t classes = 1)
      : pairs_(pairs), k_{AliasTable(v_weights(0, p)), AliasTable(v_weights(1, p)), AliasTable(v_weights(2, p))}, cls_(p, classes),
        tree_(std::vector<double>(cls_.units(), 0.0)) {
    for (std::size_t u = 0; u < cls_.units(); ++u) update_unit(u);
  }
  double total_rate() const { return std::numbers::pi * pairs_.chi_max / (4.0 * pairs_.volume) * tree_.total(); }
  Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t u = tree_.sample(rng.uniform()), i = cls_.species_of(u);
    const double s = pairs_.sigma[i], t0 = s * s * S_[0], t1 = 2.0 * s * S_[1];
    const double x = rng.uniform() * (t0 + t1 + S_[2]);
    const std::size_t k = k_[x < t0 ? 0 : (x < t0 + t1 ? 1 : 2)].sample(rng.uniform());
    const double chi_ratio = pairs_.dilute() ? 1.0 : pairs_.chi_max / pairs_.chi(i, k);
    const std::size_t a = cls_.begin(u) + rng.below(cls_.count(u)), b = p.begin(k) + rng.below(p.count(k));
    return {a, b, i, k, chi_ratio * (cls_.bound(u) + cls_.bound(cls_.unit_of(b, k)))};
  }
  const SpeedClasses& classes() const { return cls_; }
  bool moved(std::size_t a, std::size_t i, std::size_t& other, Particles& p) {
    bool changed = false;
    cls_.moved(p, a, i, other, [&](std::size_t u) { update_unit(u), changed = true; });
    return changed;
  }
  void refresh(Particles& p) {
    cls_.refresh(p);
    for (std::size_t u = 0; u < cls_.units(); ++u) update_unit(u);
  }

 private:
  // N_k σ_k^r, and their sums S_r.
  std::vector<double> v_weights(int r, const Particles& p) {
    std::vector<double> w(pairs_.M);
    S_[r] = 0.0;
    for (std::size_t k = 0; k < pairs_.M; ++k) S_[r] += w[k] = double(p.count(k)) * std::pow(pairs_.sigma[k], r);
    return w;
  }
  void update_unit(std::size_t u) {
    const double s = pairs_.sigma[cls_.species_of(u)];
    tree_.set(u, double(cls_.count(u)) * cls_.bound(u) * (s * s * S_[0] + 2.0 * s * S_[1] + S_[2]));
  }
  const PairTable& pairs_;
  double S_[3] = {0, 0, 0};
  AliasTable k_[3];
  SpeedClasses cls_;
  SumTree tree_;
};

// Bird's method, the comparison of the v2 paper: one global bound σ_max² χ_max 2 vmax for every
// pair, particles drawn uniformly from the whole system.
class BirdSelector {
 public:
  BirdSelector(const PairTable& pairs, Particles& p, std::size_t = 1) : pairs_(pairs) { refresh(p); }
  double total_rate() const {
    const double N = double(n_);
    return std::numbers::pi / pairs_.volume * N * N * pairs_.sigma2_max * pairs_.chi_max * vmax_;
  }
  Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t a = rng.below(n_), b = rng.below(n_);
    const std::size_t i = species_of(a, p), k = species_of(b, p);
    const double scale = pairs_.sigma2_max * pairs_.chi_max / (pairs_.sigma2(i, k) * pairs_.chi(i, k)) * 2.0 * vmax_;
    return {a, b, i, k, scale};
  }
  bool moved(std::size_t a, std::size_t, std::size_t&, Particles& p) {
    const double speed = std::sqrt(norm2(p.v[a]));
    if (speed <= vmax_) return false;
    vmax_ = speed;
    return true;
  }
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
