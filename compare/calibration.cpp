#include "calibration.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/poisson.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <fmt/format.h>

#include "commands.hpp"
#include "model/errors.hpp"

namespace granmix::compare {

namespace {

double quantile_of(std::vector<double> v, double q) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * double(v.size() - 1) + 0.5))];
}

// P(|t_ν| > z): a judged point's chance to fall outside z·σ when theory and DSMC agree (ν = R − 1, docs/judging.md §6).
double two_sided_tail(std::size_t replicas, double z) {
  if (replicas < 2) return 1.0;
  const boost::math::students_t t(double(replicas - 1));
  return 2.0 * boost::math::cdf(boost::math::complement(t, z));
}

}  // namespace

std::vector<CalibrationRow> calibrate(const std::vector<SeedRun>& runs) {
  std::vector<CalibrationRow> rows;
  std::map<std::string, std::size_t> at;
  std::map<std::string, std::vector<double>> ratios;
  for (const SeedRun& run : runs)
    for (const SceneOutcome& s : run.scenes)
      for (const QuantityResult& q : s.quantities) {
        const std::string key = s.scene + ":" + label(q.spec);
        auto [it, fresh] = at.emplace(key, rows.size());
        if (fresh) rows.push_back({.scene = s.scene, .quantity = label(q.spec), .replicas = s.replicas, .z = q.spec.z});
        CalibrationRow& r = rows[it->second];
        ++r.seeds, r.seeds_failed += !q.pass();
        r.points += q.judged, r.outside += q.failed;
        r.replicas = std::min(r.replicas, s.replicas);
        ratios[key].insert(ratios[key].end(), q.bound_ratios.begin(), q.bound_ratios.end());
      }
  for (CalibrationRow& r : rows) {
    const std::vector<double>& v = ratios[r.scene + ":" + r.quantity];
    r.chance = two_sided_tail(r.replicas, r.z);
    const double expected = std::max(r.chance * double(r.points), 1e-12);
    r.allowed = boost::math::quantile(boost::math::poisson(expected), 0.999);
    // A seed of n points fails by chance with probability at most 1 − (1 − p)^n, however its points correlate (Šidák's
    // inequality; docs/validation.md, "Held-out calibration"): its count over the seeds is binomial at worst.
    const double per_seed = r.seeds ? double(r.points) / double(r.seeds) : 0.0;
    r.seed_chance = -std::expm1(per_seed * std::log1p(-std::min(r.chance, 1.0 - 1e-16)));
    r.seeds_allowed = r.seeds ? boost::math::quantile(boost::math::binomial(double(r.seeds), std::max(r.seed_chance, 1e-12)), 0.999) : 0.0;
    r.ratio_median = quantile_of(v, 0.5), r.ratio_p90 = quantile_of(v, 0.9);
    r.ratio_max = v.empty() ? NAN : *std::max_element(v.begin(), v.end());
  }
  return rows;
}

std::string calibration_tsv(const std::vector<CalibrationRow>& rows) {
  std::string s = "scene\tquantity\treplicas\tz\tseeds\tseeds_failed\tpoints\toutside\tfraction_outside\tchance\tallowed\tratio_median\tratio_p90\tratio_max\tconsistent\tseed_chance\tseeds_allowed\n";
  for (const CalibrationRow& r : rows)
    s += fmt::format("{}\t{}\t{}\t{:g}\t{}\t{}\t{}\t{}\t{:.6g}\t{:.6g}\t{:g}\t{:.6g}\t{:.6g}\t{:.6g}\t{}\t{:.6g}\t{:g}\n", r.scene, r.quantity, r.replicas,
                     r.z, r.seeds, r.seeds_failed, r.points, r.outside, r.points ? double(r.outside) / double(r.points) : 0.0, r.chance,
                     r.allowed, r.ratio_median, r.ratio_p90, r.ratio_max, r.consistent() ? 1 : 0, r.seed_chance, r.seeds_allowed);
  return s;
}

nlohmann::ordered_json calibration_json(const std::vector<SeedRun>& runs, const std::vector<CalibrationRow>& rows) {
  nlohmann::ordered_json j;
  j["seeds"] = nlohmann::ordered_json::array();
  for (const SeedRun& run : runs) {
    std::size_t failed = 0;
    for (const SceneOutcome& s : run.scenes) failed += !s.pass;
    j["seeds"].push_back({{"seed", run.seed}, {"scenes", run.scenes.size()}, {"scenes_failed", failed}, {"errors", run.errors}});
  }
  j["quantities"] = nlohmann::ordered_json::array();
  for (const CalibrationRow& r : rows)
    j["quantities"].push_back({{"scene", r.scene}, {"quantity", r.quantity}, {"replicas", r.replicas}, {"z", r.z}, {"seeds", r.seeds},
                               {"seeds_failed", r.seeds_failed}, {"points", r.points}, {"outside", r.outside}, {"chance", r.chance},
                               {"allowed", r.allowed}, {"ratio_median", r.ratio_median}, {"ratio_p90", r.ratio_p90}, {"ratio_max", r.ratio_max},
                               {"consistent", r.consistent()}, {"seed_chance", r.seed_chance}, {"seeds_allowed", r.seeds_allowed}});
  return j;
}

std::string calibration_summary(const std::vector<SeedRun>& runs, const std::vector<CalibrationRow>& rows) {
  std::size_t points = 0, outside = 0, inconsistent = 0;
  std::string s;
  for (const CalibrationRow& r : rows) {
    points += r.points, outside += r.outside;
    if (r.consistent() && r.outside == 0) continue;
    inconsistent += !r.consistent();
    s += fmt::format("  {:<24} {:<20} failed in {} of {} seeds (chance allows {:g}); {} of {} points outside (independent points: {:g}), "
                     "|dev|/bound max {:.3g}: {}\n",
                     r.scene, r.quantity, r.seeds_failed, r.seeds, r.seeds_allowed, r.outside, r.points, r.allowed, r.ratio_max,
                     r.consistent() ? "consistent" : "TOO MANY");
  }
  return fmt::format("calibration: {} seeds, {} quantities, {} of {} judged points outside their bound; {} quantities fail more often than "
                     "chance allows\n",
                     runs.size(), rows.size(), outside, points, inconsistent) +
         s;
}

std::vector<std::uint64_t> parse_seed_range(const std::string& text) {
  std::smatch m;
  const std::string allowed = " (allowed: A-B or A, integers in [0, 2^53], A <= B, at most 1000 seeds)";
  if (!std::regex_match(text, m, std::regex("([0-9]{1,16})(?:-([0-9]{1,16}))?"))) throw InputError("--seeds: \"" + text + "\" is not a seed range" + allowed);
  const std::uint64_t a = std::stoull(m[1].str()), b = m[2].matched ? std::stoull(m[2].str()) : a;
  if (b < a || b > max_seed || b - a >= 1000) throw InputError("--seeds: " + text + " out of range" + allowed);
  std::vector<std::uint64_t> seeds;
  for (std::uint64_t s = a; s <= b; ++s) seeds.push_back(s);
  return seeds;
}

}  // namespace granmix::compare
