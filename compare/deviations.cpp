#include "deviations.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "frozen_model_errors.hpp"
#include "model/errors.hpp"
#include "model/model_error.hpp"

namespace granmix::compare {

std::string label(const model::CompareQuantity& q) {
  if (q.species.empty()) return q.name;
  // Runs of consecutive species are written as ranges: msd[1,0], msd_ratio[13-43].
  std::string s = q.name + "[";
  for (std::size_t i = 0; i < q.species.size();) {
    std::size_t j = i;
    while (j + 1 < q.species.size() && q.species[j + 1] == q.species[j] + 1) ++j;
    if (i) s += ',';
    s += std::to_string(q.species[i]);
    if (j > i) {  // a pair as "1,2", a longer run as "13-43"
      s += j > i + 1 ? '-' : ',';
      s += std::to_string(q.species[j]);
    }
    i = j + 1;
  }
  s += ']';
  return s;
}

std::string tolerance_text(const model::CompareQuantity& q) {
  // Δp, Δm, Δs: the correction over the paper level, the Maxwellian value, the first-Sonine D; Δps: the larger.
  // Δe: the level's own computed model error (error_column).
  std::string delta = "Δ";
  for (const std::string& lower : q.correction_from) delta += lower.front();
  if (!q.error_column.empty()) delta += 'e';
  if (std::isfinite(q.model_error_max)) delta += fmt::format("≤{:g}", q.model_error_max);  // "Δcgb≤0.03": the cap on it
  const bool computed = !q.correction_from.empty() || !q.error_column.empty();
  const std::string rel = !computed ? fmt::format("{:g}", q.relative)
                        : q.relative > 0 ? fmt::format("{:g}+{}", q.relative, delta) : delta;
  return rel + fmt::format("+{:g}σ", q.z) + (q.absolute > 0 ? fmt::format(" or ±{:g}", q.absolute) : "");
}

nlohmann::ordered_json tolerance_json(const model::CompareQuantity& q) {
  nlohmann::ordered_json j = {{"relative", q.relative}, {"z", q.z}};
  // One lower level as a string, several as an array.
  if (q.correction_from.size() == 1) j["correction_from"] = q.correction_from.front();
  if (q.correction_from.size() > 1) j["correction_from"] = q.correction_from;
  if (!q.error_column.empty()) j["error_column"] = q.error_column;
  if (std::isfinite(q.model_error_max)) j["model_error_max"] = q.model_error_max;
  if (q.absolute > 0) j["absolute"] = q.absolute;
  return j;
}

std::vector<Deviation> deviations(const model::Table& theory, const model::Table& dsmc,
                                  const std::vector<model::CompareQuantity>& quantities, const FrozenModelErrors* frozen) {
  std::vector<Deviation> out;
  // Rows are located by the first column of the theory table: t, or the swept value, or v*.
  if (theory.columns.empty()) return out;
  const std::string& x = theory.columns.front();
  const int tt = 0, ts = theory.column("species"), dt = dsmc.column(x), ds = dsmc.column("species");
  if (ts < 0 || dt < 0 || ds < 0) return out;
  for (const auto& q : quantities) {
    const model::ModelError model_error(q, theory);  // the computed tolerance's parts (model/model_error.hpp)
    const int a = model_error.predicted(), b = dsmc.column(q.name), e = dsmc.column(q.name + "_err");
    const int paper = theory.column(model::predicted_name(q) + "_paper");
    if (a < 0 || b < 0 || e < 0) continue;
    for (const auto& row : theory.rows) {
      const double t = row[tt];
      const int species = int(row[ts]);
      if (!model::covers(q, species)) continue;
      // Same scene grid on both sides: the locations agree to rounding.
      const auto match = std::find_if(dsmc.rows.begin(), dsmc.rows.end(), [&](const std::vector<double>& r) {
        return int(r[ds]) == species && same_location(r[dt], t);
      });
      if (match == dsmc.rows.end() || !std::isfinite(row[a]) || !std::isfinite((*match)[b])) continue;
      Deviation d{t, species, label(q), row[a], (*match)[b], (*match)[e], 0.0, 0.0, model::judges(q, t), true};
      const double diff = d.dsmc - d.theory;
      d.rel = d.theory != 0.0 ? diff / std::abs(d.theory) : 0.0;
      // The error bar used for z, floored at rounding level: replicas that agree to the last digits do not make
      // a rounding difference 10¹⁰ standard errors. An unknown error (NaN: one replica) gives no z and no verdict.
      const double err = std::max(d.dsmc_err, error_floor * std::max(std::abs(d.dsmc), std::abs(d.theory)));
      d.model_error = model_error.at(row);
      if (frozen && (!q.correction_from.empty() || !q.error_column.empty())) {  // the reviewed bound, not the live one
        const std::optional<double> f = frozen->at(d.quantity, species, t);
        if (!f)
          throw InputError(fmt::format("frozen model errors: no point {} species {} at x = {:g} (allowed: a table of this theory: "
                                       "build/granmix model-errors --write, after review)",
                                       d.quantity, species, t));
        d.model_error = *f;
      }
      d.resolved = d.model_error <= q.model_error_max;
      if (std::isnan(d.dsmc_err)) {
        d.z = NAN, d.judged = false, d.pass = false;
      } else {
        d.z = err > 0.0 ? diff / err : (diff == 0.0 ? 0.0 : INFINITY);
        const double bound = d.model_error * std::abs(d.theory) + q.z * err;
        d.pass = d.resolved && (std::abs(diff) <= bound || std::abs(diff) <= q.absolute);
        d.bound_ratio = bound > 0.0 ? std::abs(diff) / bound : (diff == 0.0 ? 0.0 : INFINITY);
        if (q.absolute > 0.0) d.bound_ratio = std::min(d.bound_ratio, std::abs(diff) / q.absolute);
      }
      d.paper_rel = paper >= 0 ? (d.dsmc - row[paper]) / std::abs(row[paper]) : NAN;
      out.push_back(d);
    }
  }
  return out;
}

std::vector<QuantityResult> summarise(const std::vector<Deviation>& d, const std::vector<model::CompareQuantity>& quantities) {
  std::vector<QuantityResult> out;
  for (const auto& q : quantities) {
    QuantityResult r;
    r.spec = q;
    for (const auto& x : d) {
      if (x.quantity != label(q)) continue;
      ++r.points;
      if (std::isnan(x.dsmc_err)) r.not_judged = "no DSMC error bar (1 replica)";
      if (!x.judged) continue;
      ++r.judged;
      if (!x.pass) ++r.failed;
      r.bound_ratios.push_back(x.bound_ratio);
      if (!x.resolved) ++r.unresolved;
      r.max_rel = std::max(r.max_rel, std::abs(x.rel));
      r.max_z = std::max(r.max_z, std::abs(x.z));
      r.max_model_error = std::max(r.max_model_error, x.model_error);
      if (std::isfinite(x.paper_rel)) r.max_paper_rel = std::isfinite(r.max_paper_rel) ? std::max(r.max_paper_rel, std::abs(x.paper_rel)) : std::abs(x.paper_rel);
    }
    out.push_back(r);
  }
  return out;
}

std::string format_deviations(const std::string& provenance, const std::string& x, const std::vector<Deviation>& d) {
  std::string s = provenance + x + "\tspecies\tquantity\ttheory\tdsmc\tdsmc_err\trel\tz\tjudged\tpass\tpaper_rel\tmodel_error\tresolved\n";
  for (const auto& x : d)
    s += fmt::format("{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\t{}\n", x.t, x.species, x.quantity, x.theory, x.dsmc, x.dsmc_err, x.rel, x.z,
                     int(x.judged), int(x.pass), x.paper_rel, x.model_error, int(x.resolved));
  return s;
}

}  // namespace granmix::compare
