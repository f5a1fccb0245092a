#pragma once
// The two halves of `granmix bench gaps` (why the papers' theory and the exact DSMC
// differ): the light species of v1 Fig. 2 (gaps_light.cpp), the heavy rare species of v1 Fig. 8
// (gaps_heavy.cpp) and the kinetic level's temperatures against the DSMC's cumulants (gaps_cumulant.cpp),
// plus helpers they use.
#include <cmath>
#include <string>
#include <vector>

#include "model/table.hpp"
#include "study.hpp"
#include "tagged_moments.hpp"
#include "theory/rates/collision_rates.hpp"

namespace granmix::bench {

// Times uniform in ln t from `from` to `to`, `per_decade` intervals per decade (both ends included).
inline std::vector<double> log_grid(double from, double to, int per_decade) {
  const int n = static_cast<int>(std::lround(std::log10(to / from) * per_decade));
  std::vector<double> t;
  for (int j = 0; j <= n; ++j) t.push_back(from * std::pow(10.0, double(j) / per_decade));
  return t;
}

// First-Sonine momentum rate ν_k = τ_v,k⁻¹ + ξ_k/2 (docs/physics-beyond.md §1) and ξ_k at temperatures T.
struct Rates {
  std::vector<double> nu, xi;
};
inline Rates rates_at(const theory::CollisionRates& rates, const std::vector<double>& T) {
  Rates r;
  r.xi.resize(T.size()), r.nu.resize(T.size());
  rates.xi_all(T.data(), r.xi.data());
  rates.inv_tau_v_all(T.data(), r.nu.data());
  for (std::size_t k = 0; k < T.size(); ++k) r.nu[k] += 0.5 * r.xi[k];
  return r;
}

// Pooled means of one moment along the time grid for species k (one replica left out, or none).
inline std::vector<double> series(const TaggedRun& run, std::size_t k, TaggedRun::Moment q, std::size_t excluded = TaggedRun::npos) {
  std::vector<double> s;
  for (std::size_t j = 0; j < run.times.size(); ++j) s.push_back(run.mean(j, k, q, excluded));
  return s;
}

// c = 2a₂ = 2[(3/5)⟨v⁴⟩/⟨v²⟩² − 1] from per-particle means (docs/physics.md §6).
inline double cumulant_of(double v2, double v4) { return 2.0 * (0.6 * v4 / (v2 * v2) - 1.0); }

// Index of the grid time closest to t.
inline std::size_t index_of(const std::vector<double>& times, double t) {
  std::size_t best = 0;
  for (std::size_t j = 1; j < times.size(); ++j)
    if (std::abs(std::log(times[j] / t)) < std::abs(std::log(times[best] / t))) best = j;
  return best;
}

struct GapsPart {
  model::Table table;
  std::vector<std::string> summary, json;  // json: one object per decomposed case (--json)
};

// bo1-fig02: per species T_k, c_k, Q_k, ν_eff against ν_k, D/D[1], MSD variants (series 0 light, 1 heavy).
GapsPart light_gaps(const StudyOptions& o);
// bo1-fig08 (θ = 3) at several N: per (N, t, species) temperatures, MSD ratios and their causes;
// `replicas` gets per-replica values at the last time.
GapsPart heavy_gaps(const StudyOptions& o, model::Table& replicas);
// v1 Figs. 2, 9, 10 (from o.scenes_folder; none without it): per (scene, t, species) the DSMC's T_k and c_k,
// the kinetic level's, and T_k from the first-Sonine rates driven by the measured c_k(t).
GapsPart cumulant_gaps(const StudyOptions& o);

}  // namespace granmix::bench
