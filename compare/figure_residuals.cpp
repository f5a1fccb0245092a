#include <fmt/format.h>

#include <algorithm>

#include "figure_parts.hpp"

namespace granmix::compare::figure {

namespace {

// deviations.tsv locates a row by the theory table's first column (t, the swept value, v*). A figure drawn against
// another column ([plot] x = "t_s", the rescaled time) maps each location through the theory table's own pairs;
// x = "species" draws the rows of the last location against their species.
struct Location {
  std::string definitions, x, filter;
};

Location location(const model::Table& theory, const std::string& x) {
  const std::string& at = theory.columns.front();
  if (x == at) return {"", "column(1)", ""};
  if (x == "species") {
    const double last = theory.rows.back()[0];
    return {"", "column('species')", fmt::format(" && abs(column(1) - {:.17g}) <= 1e-12*{:.17g}", last, std::max(1.0, std::abs(last)))};
  }
  const int sc = theory.column("species"), xc = theory.column(x);
  std::vector<std::string> from, to;
  for (const auto& row : theory.rows)
    if (xc >= 0 && int(row[sc]) == int(theory.rows.front()[sc])) from.push_back(fmt::format("{:.17g}", row[0])), to.push_back(fmt::format("{:.17g}", row[xc]));
  std::string d = fmt::format("array gm_from[{}] = [{}]\narray gm_to[{}] = [{}]\n", from.size(), fmt::join(from, ", "), to.size(), fmt::join(to, ", "));
  d += "gm_at(t, i) = i > |gm_from| ? NaN : abs(gm_from[i] - t) <= 1e-12*(abs(t) > 1 ? abs(t) : 1) ? gm_to[i] : gm_at(t, i + 1)\n";
  return {d, "gm_at(column(1), 1)", ""};
}

// The half-width of a point's tolerance band relative to |theory|: compare/deviations.cpp's pass rule
// |dsmc − theory| <= model_error·|theory| + z·err, or <= absolute, divided by |theory|. The figure reads the columns
// of deviations.tsv; this value only sizes the panel's y axis.
double band(const Deviation& x, const model::CompareQuantity& q) {
  const double err = std::max(x.dsmc_err, error_floor * std::max(std::abs(x.dsmc), std::abs(x.theory)));
  return std::max(x.model_error + q.z * err / std::abs(x.theory), q.absolute / std::abs(x.theory));
}

std::string band_expression(const model::CompareQuantity& q) {
  return fmt::format("gm_max(column('model_error') + {:g}*gm_max(column('dsmc_err'), {:g}*gm_max(abs(column('dsmc')), abs(column('theory'))))/abs(column('theory')), "
                     "{:g}/abs(column('theory')))",
                     q.z, error_floor, q.absolute);
}

// ±range holds the bands and points of nine in ten rows; when the largest is not far beyond, all of them.
double axis_range(std::vector<double> v) {
  if (v.empty()) return 0.01;
  std::sort(v.begin(), v.end());
  const double most = v[std::size_t(0.9 * double(v.size() - 1))], all = v.back();
  const double r = 1.1 * (all <= 1.5 * most ? all : most);
  return std::isfinite(r) && r > 0.0 ? r : 0.01;
}

}  // namespace

ResidualPanel residual_panel(const model::Scene& s, const std::string& y, const std::vector<Deviation>& d, const model::Table& theory,
                             int index) {
  ResidualPanel out;
  if (theory.rows.empty()) return out;
  const Location loc = location(theory, s.plot.x);
  std::vector<std::string> bands, points;
  std::vector<double> sizes;
  out.tables = loc.definitions + "gm_max(a, b) = a > b ? a : b\nset datafile columnheaders\n";
  int n = 0;
  for (const model::CompareQuantity& q : s.compare) {
    if (q.name != y) continue;
    const std::string lab = label(q);
    // One group per species, in the order deviations.tsv lists them; a species axis puts them all on one curve.
    std::vector<int> groups;
    for (const Deviation& x : d)
      if (x.quantity == lab && std::find(groups.begin(), groups.end(), s.plot.x == "species" ? -1 : x.species) == groups.end())
        groups.push_back(s.plot.x == "species" ? -1 : x.species);
    for (const int k : groups) {
      bool unjudged = false, failed = false;
      for (const Deviation& x : d) {
        if (x.quantity != lab || (k >= 0 && x.species != k)) continue;
        if (x.judged) sizes.push_back(std::max(std::abs(x.rel), band(x, q)));
        unjudged = unjudged || !x.judged, failed = failed || (x.judged && !x.pass);
      }
      const int style = k >= 0 ? species_style(k) : 2;  // a species axis: the DSMC colour of the curve above
      if (std::find(out.species.begin(), out.species.end(), k) == out.species.end()) out.species.push_back(k);
      const std::string rows = fmt::format("strcol('quantity') eq '{}'{}{}", lab, k >= 0 ? fmt::format(" && column('species') == {}", k) : "", loc.filter);
      const std::string res = fmt::format("$res{}_{}", index, n), bnd = fmt::format("$band{}_{}", index, n);
      ++n;
      out.tables += fmt::format("set table {}\nplot 'deviations.tsv' using ({}):(column('rel')):(column('dsmc_err')/abs(column('theory'))):(column('judged')):(column('pass')) "
                                "with table if ({})\n",
                                res, loc.x, rows);
      out.tables += fmt::format("set table {}\nplot 'deviations.tsv' using ({}):(-{}):({}) with table if ({} && column('judged') == 1)\nunset table\n", bnd,
                                loc.x, band_expression(q), band_expression(q), rows);
      bands.push_back(fmt::format("{} using 1:2:3 with filledcurves ls {} fs transparent solid 0.12 noborder notitle", bnd, style));
      points.push_back(fmt::format("{} using 1:($4 == 1 ? $2 : NaN):3 with yerrorbars ls {} dt 1 lw 1.2 pt 7 ps 0.6 notitle", res, style));
      if (unjudged) points.push_back(fmt::format("{} using 1:($4 == 0 ? $2 : NaN):3 with yerrorbars ls {} dt 1 lw 1 pt 6 ps 0.6 notitle", res, style));
      if (failed) points.push_back(fmt::format("{} using 1:($4 == 1 && $5 == 0 ? $2 : NaN) with points lc rgb 'black' lw 1.5 pt 2 ps 1.4 notitle", res));
      points.push_back(fmt::format("{0} using 1:($2 > gm_range ? 0.92*gm_range : NaN) with points ls {1} pt 9 ps 1.1 notitle, "
                                   "{0} using 1:($2 < -gm_range ? -0.92*gm_range : NaN) with points ls {1} pt 11 ps 1.1 notitle",
                                   res, style));
      out.unjudged = out.unjudged || unjudged, out.failed = out.failed || failed;
    }
  }
  if (n == 0) return {};
  out.range = axis_range(sizes);
  const bool positive = std::all_of(d.begin(), d.end(), [&](const Deviation& x) { return (x.quantity != y && x.quantity.rfind(y + "[", 0) != 0) || x.theory > 0.0; });
  out.ylabel = positive ? "DSMC/theory − 1" : "(DSMC − theory)/|theory|";
  out.plots = bands;
  out.plots.push_back("0 with lines lc rgb '#555555' lw 1 dt 1 notitle");
  out.plots.insert(out.plots.end(), points.begin(), points.end());
  return out;
}

}  // namespace granmix::compare::figure
