#pragma once
// Speed classes: the particles of each species kept ordered by speed class, so that a selector's
// majorant can use the bound of a particle's class instead of the species' maximum speed, keeping
// the low-rank structure. Class c of species k holds indices [begin(u), end(u)), u = k·C + c, with speeds up to
// bound(u): geometric bounds top·r^(C−1−c) below the top class, whose bound is the species' maximum
// speed (raised when exceeded, like the paper's vmax). An ordered pair (a, b) proposed at a rate
// ∝ bound(class(a)) gives the unordered pair σ²(bound_a + bound_b) ≥ σ²(|v_a| + |v_b|) ≥ σ²|g|: the
// majorant stays exact, only tighter. With C = 1 this is the paper's per-species vmax.
//
// Particles only move up (when a collision takes them past their class bound); refresh() re-sorts.
// Moving a particle between classes swaps particle records (velocity and displacement), so indices do
// not keep their particle: runs that follow individual particles (TAMSD tracers) use C = 1.
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "particles.hpp"

namespace granmix::dsmc {

class SpeedClasses {
 public:
  SpeedClasses(Particles& p, std::size_t classes);
  std::size_t classes() const { return C_; }
  std::size_t units() const { return bound_.size(); }
  std::size_t species_of(std::size_t u) const { return u / C_; }
  std::size_t begin(std::size_t u) const { return off_[u]; }
  std::size_t count(std::size_t u) const { return off_[u + 1] - off_[u]; }
  double bound(std::size_t u) const { return bound_[u]; }
  // The unit (k·C + c) holding index a of species k.
  std::size_t unit_of(std::size_t a, std::size_t k) const {
    std::size_t u = k * C_ + C_ - 1;
    while (a < off_[u]) --u;
    return u;
  }
  // Σ_c N_u bound_u over the classes of species k: the species' weight in a two-level selection
  // (species from a tree over M leaves, then its class by pick()), so the tree keeps M leaves, not M·C.
  // Kept with the class weights N_u bound_u, renewed when a count or bound changes (callgrind: computing
  // them per proposal would be a fifth of its instructions).
  double weight(std::size_t k) const { return species_weight_[k]; }
  // The class of species k with probability N_u bound_u / weight(k), for x uniform in [0, weight(k)).
  // The top class is never empty while weight(k) > 0 (it holds the fastest particle and only gains
  // between refreshes), so it takes x that rounding pushed past the last sum.
  std::size_t pick(std::size_t k, double x) const {
    const std::size_t top = k * C_ + C_ - 1;
    for (std::size_t u = k * C_; u < top; ++u) {
      if (x < weight_[u]) return u;
      x -= weight_[u];
    }
    return top;
  }
  // Particle a of species k changed speed: if it exceeds its class bound, move it up to the class of
  // its speed (raising the top bound if it exceeds that). `other` is an index the caller holds; it is
  // kept pointing at the same particle through the swaps. Returns true when a count or bound of
  // species k changed (its weight must then be recomputed).
  bool moved(Particles& p, std::size_t a, std::size_t k, std::size_t& other) {
    const double s = std::sqrt(norm2(p.v[a]));
    const std::size_t from = unit_of(a, k), top = k * C_ + C_ - 1;
    bool changed = false;
    if (s > bound_[top]) bound_[top] = s, changed = true;
    // Only upwards: a particle that slowed down still satisfies its class bound, and leaving it
    // there saves the swaps (random memory accesses) on half the collisions; refresh() re-sorts all
    // particles every N collisions, about two per particle.
    if (s <= bound_[from]) {
      if (changed) update_weights(k);
      return changed;
    }
    std::size_t to = from;
    while (s > bound_[to]) ++to;
    for (std::size_t u = from; u < to; ++u) {  // to the end of class u, which then shrinks by one
      const std::size_t last = off_[u + 1] - 1;
      swap(p, a, last, other);
      a = last, --off_[u + 1];
    }
    update_weights(k);
    return true;
  }
  // New bounds from the current maximum speed of each species and every particle put in its class
  // (an in-place counting sort per species, O(N)); the selector then recomputes all its weights.
  void refresh(Particles& p);

 private:
  void update_weights(std::size_t k) {
    double w = 0.0;
    for (std::size_t u = k * C_; u < k * C_ + C_; ++u) w += weight_[u] = double(count(u)) * bound_[u];
    species_weight_[k] = w;
  }
  static void swap(Particles& p, std::size_t x, std::size_t y, std::size_t& other) {
    if (x == y) return;
    std::swap(p.v[x], p.v[y]);
    if (p.track_displacement) std::swap(p.flight[x], p.flight[y]);
    if (other == x) other = y;
    else if (other == y) other = x;
  }
  std::size_t C_;
  std::vector<std::size_t> off_;  // M·C + 1 offsets
  std::vector<double> bound_;     // M·C bounds
  std::vector<double> weight_;    // M·C class weights N_u bound_u
  std::vector<double> species_weight_;  // M sums of the class weights
};

}  // namespace granmix::dsmc
