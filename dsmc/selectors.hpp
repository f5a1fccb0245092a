#pragma once
// Pair selectors of the exact event-driven DSMC (docs/architecture.md §5). Each proposes an ordered pair of
// particles (a, b) of species (i, k) from a majorant process of total rate total_rate(), and a
// scale and weight such that accepting with probability weight·|g|/scale gives every unordered pair
// {a, b} its true collision rate π σ_ik² χ_ik |g| / V (docs/physics.md §1).
//
// Normalisation (v1 Eq. 12 as printed drops N_i N_k; derived here): proposing the ordered pair (a,b)
// with rate π σ_ik² χ̂ vmax_i / V, the unordered pair is proposed at π σ_ik² χ̂ (vmax_i + vmax_k)/V,
// which bounds its true rate because |g| <= vmax_i + vmax_k. Summed over ordered pairs (self pairs
// included and rejected): Γ = (π/V) Σ_ik N_i vmax_i N_k σ_ik² χ̂_ik.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>
#include <utility>
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
  double scale, weight;  // accept iff u * scale < weight * |g|: weight carries σ_ik²χ_ik or χ_ik where the
                         // majorant uses a maximum (a multiply instead of a division per trial)
};

// Selectors draw the first particle of a pair from a speed class (dsmc/speed_classes.hpp) and use
// class bounds for the majorant: bound(class a) + bound(class b) >= |v_a| + |v_b| >= |g|. With one
// class per species this is the paper's N_i vmax_i N_k σ_ik² majorant. The class is drawn in two
// levels: the species i from a sum tree whose weights carry W_i = Σ_{u∈i} N_u bound_u, then the class
// u ∝ N_u bound_u by SpeedClasses::pick (the tree keeps M leaves instead of M·C: fewer levels and a
// quarter of the cache). After a collision the event loop reports each particle's new speed through
// moved(); it returns true when the selector's state (weights, bounds, particle order) changed.
// propose() is forced inline into the event loop: out of line it cost 2% more instructions per
// trial (callgrind, 691 species).

// Ordered pair (a, b) of the class u and species k: a uniform in u, b uniform in k (one random word;
// species hold fewer than 2^32 particles: ensemble.cpp refuses more).
inline std::pair<std::size_t, std::size_t> pick_pair(Rng& rng, const SpeedClasses& c, std::size_t u, const Particles& p, std::size_t k) {
  const auto [x, y] = rng.below_pair(static_cast<std::uint32_t>(c.count(u)), static_cast<std::uint32_t>(p.count(k)));
  return {c.begin(u) + x, p.begin(k) + y};
}

// A table over species pairs (i, k) of majorants W_i N_k σ_ik² χ_ik with the exact χ_ik: for few
// species. Cell i·2^s + k (2^s >= M) so that i and k come from a shift and a mask, not a division.
class DirectSelector {
 public:
  DirectSelector(const PairTable& pairs, Particles& p, std::size_t classes = 1)
      : pairs_(pairs), shift_(std::bit_width(pairs.M - 1)), cls_(p, classes), tree_(std::vector<double>(pairs.M << shift_, 0.0)) {
    refresh_weights(p);
  }
  double total_rate() const { return std::numbers::pi / pairs_.volume * tree_.total(); }
  [[gnu::always_inline]] Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t cell = tree_.sample(rng.uniform()), i = cell >> shift_, k = cell & ((std::size_t(1) << shift_) - 1);
    const std::size_t u = cls_.pick(i, rng.uniform() * cls_.weight(i));
    const auto [a, b] = pick_pair(rng, cls_, u, p, k);
    return {a, b, i, k, cls_.bound(u) + cls_.bound(cls_.unit_of(b, k)), 1.0};
  }
  const SpeedClasses& classes() const { return cls_; }
  bool moved(std::size_t a, std::size_t i, std::size_t& other, Particles& p) {
    if (!cls_.moved(p, a, i, other)) return false;
    update_species(i, p);
    return true;
  }
  void refresh(Particles& p) {
    cls_.refresh(p);
    refresh_weights(p);
  }

 private:
  void refresh_weights(const Particles& p) {
    std::vector<double> w(pairs_.M << shift_, 0.0);
    for (std::size_t i = 0; i < pairs_.M; ++i)
      for (std::size_t k = 0; k < pairs_.M; ++k) w[(i << shift_) + k] = cell_weight(i, k, cls_.weight(i), p);
    tree_ = SumTree(w);
  }
  void update_species(std::size_t i, const Particles& p) {
    const double wi = cls_.weight(i);
    for (std::size_t k = 0; k < pairs_.M; ++k) tree_.set((i << shift_) + k, cell_weight(i, k, wi, p));
  }
  double cell_weight(std::size_t i, std::size_t k, double wi, const Particles& p) const {
    return wi * double(p.count(k)) * pairs_.sigma2(i, k) * pairs_.chi(i, k);
  }
  const PairTable& pairs_;
  int shift_;
  SpeedClasses cls_;
  SumTree tree_;
};

// The low-rank method of the source paper (v1 Eqs. 12–14): σ_ik² = (σ_i² + 2σ_iσ_k + σ_k²)/4 makes
// the majorant N_i vmax_i N_k σ_ik² a sum of three rank-1 terms. Summed over k, the majorant of
// species i is W_i (σ_i² S_0 + 2σ_i S_1 + S_2) with S_r = Σ_k N_k σ_k^r, so i is drawn from one sum
// tree over these (O(log M) per proposal and per update), its class by pick(), then the term r with
// probability ∝ (σ_i² S_0, 2σ_i S_1, S_2), then k from the fixed weights N_k σ_k^r by an alias table
// (O(1)). (Drawing r first and i, k from three trees gives the same pair law with three descents.)
// Enskog χ_ik is not low-rank: the majorant uses χ_max and the acceptance carries χ_ik/χ_max
// (exact, at the price of more rejections).
class LowRankSelector {
 public:
  LowRankSelector(const PairTable& pairs, Particles& p, std::size_t classes = 1)
      : pairs_(pairs), k_{AliasTable(v_weights(0, p)), AliasTable(v_weights(1, p)), AliasTable(v_weights(2, p))}, cls_(p, classes),
        tree_(std::vector<double>(pairs.M, 0.0)) {
    refresh_weights();
  }
  double total_rate() const { return std::numbers::pi * pairs_.chi_max / (4.0 * pairs_.volume) * tree_.total(); }
  [[gnu::always_inline]] Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t i = tree_.sample(rng.uniform()), u = cls_.pick(i, rng.uniform() * cls_.weight(i));
    const double s = pairs_.sigma[i], t0 = s * s * S_[0], t1 = 2.0 * s * S_[1];
    const double x = rng.uniform() * (t0 + t1 + S_[2]);
    const std::size_t k = k_[x < t0 ? 0 : (x < t0 + t1 ? 1 : 2)].sample(rng.uniform());
    const auto [a, b] = pick_pair(rng, cls_, u, p, k);
    return {a, b, i, k, pairs_.chi_max * (cls_.bound(u) + cls_.bound(cls_.unit_of(b, k))), pairs_.chi(i, k)};
  }
  const SpeedClasses& classes() const { return cls_; }
  bool moved(std::size_t a, std::size_t i, std::size_t& other, Particles& p) {
    if (!cls_.moved(p, a, i, other)) return false;
    tree_.set(i, species_weight(i));
    return true;
  }
  void refresh(Particles& p) {
    cls_.refresh(p);
    refresh_weights();
  }

 private:
  // N_k σ_k^r, and their sums S_r.
  std::vector<double> v_weights(int r, const Particles& p) {
    std::vector<double> w(pairs_.M);
    S_[r] = 0.0;
    for (std::size_t k = 0; k < pairs_.M; ++k) S_[r] += w[k] = double(p.count(k)) * std::pow(pairs_.sigma[k], r);
    return w;
  }
  double species_weight(std::size_t i) const {
    const double s = pairs_.sigma[i];
    return cls_.weight(i) * (s * s * S_[0] + 2.0 * s * S_[1] + S_[2]);
  }
  void refresh_weights() {
    std::vector<double> w(pairs_.M);
    for (std::size_t i = 0; i < pairs_.M; ++i) w[i] = species_weight(i);
    tree_ = SumTree(w);
  }
  const PairTable& pairs_;
  double S_[3] = {0, 0, 0};
  AliasTable k_[3];
  SpeedClasses cls_;
  SumTree tree_;
};

// Bird's method as the v2 paper's authors run it (their DSMCup): every pair gets the largest cross
// section σ_max² χ_max, and each particle its own speed bound, here the bound of its speed class.
// The ordered pair (a, b): a with probability ∝ bound(class a) (species tree over W_i, then pick()),
// b uniform over all N particles (its species from an alias table over N_k, then uniform in it). The
// unordered pair is proposed at (π/V) σ_max² χ_max (bound_a + bound_b) >= its true rate
// (π/V) σ_ik² χ_ik |g|, and accepted with their ratio: exact, like direct and low-rank, only with
// more rejections (the cross section of the pair is not in the majorant). Total rate
// Γ = (π/V) σ_max² χ_max N Σ_i W_i.
class BirdSelector {
 public:
  BirdSelector(const PairTable& pairs, Particles& p, std::size_t classes = 1)
      : pairs_(pairs), k_(counts(p)), cls_(p, classes), tree_(std::vector<double>(pairs.M, 0.0)) {
    refresh_weights();
  }
  double total_rate() const { return std::numbers::pi / pairs_.volume * pairs_.sigma2_max * pairs_.chi_max * n_ * tree_.total(); }
  [[gnu::always_inline]] Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t i = tree_.sample(rng.uniform()), u = cls_.pick(i, rng.uniform() * cls_.weight(i)), k = k_.sample(rng.uniform());
    const auto [a, b] = pick_pair(rng, cls_, u, p, k);
    return {a, b, i, k, pairs_.sigma2_max * pairs_.chi_max * (cls_.bound(u) + cls_.bound(cls_.unit_of(b, k))),
            pairs_.sigma2(i, k) * pairs_.chi(i, k)};
  }
  const SpeedClasses& classes() const { return cls_; }
  bool moved(std::size_t a, std::size_t i, std::size_t& other, Particles& p) {
    if (!cls_.moved(p, a, i, other)) return false;
    tree_.set(i, cls_.weight(i));
    return true;
  }
  void refresh(Particles& p) {
    cls_.refresh(p);
    refresh_weights();
  }

 private:
  std::vector<double> counts(const Particles& p) {
    std::vector<double> n(p.species());
    for (std::size_t k = 0; k < p.species(); ++k) n[k] = double(p.count(k));
    n_ = double(p.size());
    return n;
  }
  void refresh_weights() {
    std::vector<double> w(pairs_.M);
    for (std::size_t i = 0; i < pairs_.M; ++i) w[i] = cls_.weight(i);
    tree_ = SumTree(w);
  }
  const PairTable& pairs_;
  double n_ = 0.0;
  AliasTable k_;
  SpeedClasses cls_;
  SumTree tree_;
};

// Bird's method with one global bound σ_max² χ_max 2 vmax for every pair, particles drawn uniformly
// from the whole system (`bird-global`): the textbook majorant,
// kept to show what the per-particle bound of BirdSelector gains.
class GlobalBirdSelector {
 public:
  GlobalBirdSelector(const PairTable& pairs, Particles& p, std::size_t = 1) : pairs_(pairs) { refresh(p); }
  double total_rate() const {
    const double N = double(n_);
    return std::numbers::pi / pairs_.volume * N * N * pairs_.sigma2_max * pairs_.chi_max * vmax_;
  }
  [[gnu::always_inline]] Proposal propose(Rng& rng, const Particles& p) const {
    const std::size_t a = rng.below(n_), b = rng.below(n_);
    const std::size_t i = species_of(a, p), k = species_of(b, p);
    return {a, b, i, k, pairs_.sigma2_max * pairs_.chi_max * 2.0 * vmax_, pairs_.sigma2(i, k) * pairs_.chi(i, k)};
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
