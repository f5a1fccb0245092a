#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "figure_parts.hpp"

namespace granmix::compare::figure {

namespace {

// First row of the last block of equal first-column values (the last time of a long-form table).
std::size_t last_block_start(const model::Table& t) {
  std::size_t r = t.rows.size();
  while (r > 0 && t.rows[r - 1][0] == t.rows.back()[0]) --r;
  return r;
}

// The error-bar columns of a DSMC curve: ±err, except that on a log axis a bar reaching zero or below
// (a histogram bin with a handful of counts) stops at a tenth of the value instead of stretching the
// axis over ten decades.
std::string error_bar(const std::string& y, bool logy) {
  const std::string v = "column('" + y + "')", e = "column('" + y + "_err')";
  if (!logy) return "(" + e + ")";
  return "(" + v + " - " + e + " > " + v + "/10 ? " + v + " - " + e + " : " + v + "/10):(" + v + " + " + e + ")";
}

// A legend entry in black: a line style explained once for every species.
std::string black_line(int dt, const std::string& text) {
  return fmt::format("keyentry with lines lc rgb 'black' lw 2 dt {} title {} noenhanced", dt, quote(text));
}

// What the row of species 0 holds for quantity y (model/observable_catalogue.cpp).
std::string row0_label(const std::string& y) {
  if (y == "T") return "mean ⟨T⟩";
  if (y == "gamma") return "γ = T_1/T_2";
  if (y == "gamma_ratio") return "γ(n^*)/γ(0)";
  if (y == "msd") return "total MSD";
  return "mixture";
}

std::string species_label(const model::Scene& s, int k, const std::string& y) {
  if (k == 0) return row0_label(y);
  if (k < 1 || std::size_t(k) > s.mixture.size()) return fmt::format("species {}", k);
  const model::Species& sp = s.mixture[std::size_t(k - 1)];
  return fmt::format("species {}: m = {:.3g}, σ = {:.3g}", k, sp.mass, sp.diameter);
}

}  // namespace

void Legend::add_species(int k, const std::string& text) {
  const auto it = std::find_if(species.begin(), species.end(), [&](const auto& e) { return e.first == k; });
  if (it == species.end()) species.emplace_back(k, text);
  else if (it->second.find(text) == std::string::npos) it->second += " / " + text;
}

void Legend::add_style(const std::string& entry) {
  if (std::find(styles.begin(), styles.end(), entry) == styles.end()) styles.push_back(entry);
}

std::vector<std::string> Legend::entries() const {
  std::vector<std::string> out;
  for (const auto& [k, text] : species)
    out.push_back(fmt::format("keyentry with lines ls {} dt 1 title {}", k < 0 ? 1 : species_style(k), quote(text)));
  out.insert(out.end(), styles.begin(), styles.end());
  return out;
}

std::vector<int> species_cycle(const model::Table& t) {
  std::vector<int> s;
  const int sc = t.column("species");
  if (sc < 0 || t.rows.empty()) return s;
  for (const auto& row : t.rows) {
    const int k = int(row[sc]);
    if (!s.empty() && k == s.front()) break;
    s.push_back(k);
  }
  return s;
}

void species_curves(Panel& pn, const model::Table& theory, const model::Table* dsmc, Legend& legend, const std::string& level) {
  const std::string& y = pn.y;
  pn.plots.push_back(fmt::format("'theory.tsv' every ::{} using (column('species')):(column('{}')) with linespoints ls 1 pt 6 ps 0.5 notitle",
                                 last_block_start(theory), y));
  legend.species.emplace_back(-1, fmt::format("theory: {}, t = {:g}", level, theory.rows.back()[0]));
  if (theory.column(y + "_paper") >= 0) {  // the paper level dashed beside the judged level, as the time plots draw it
    pn.plots.push_back(fmt::format("'theory.tsv' every ::{} using (column('species')):(column('{}_paper')) with lines ls 1 dt 2 notitle",
                                   last_block_start(theory), y));
    legend.add_style(black_line(2, "paper level"));
  }
  if (dsmc && dsmc->column(y + "_err") >= 0) {
    pn.plots.push_back(fmt::format("'dsmc.tsv' every ::{} using (column('species')):(column('{}')):{} with yerrorbars ls 2 pt 7 ps 0.6 notitle",
                                   last_block_start(*dsmc), y, error_bar(y, pn.logy)));
    legend.add_style("keyentry with yerrorbars ls 2 pt 7 ps 0.6 title 'DSMC ± 1σ'");
  }
}

void species_rows(Panel& pn, const model::Scene& s, const model::Table& theory, const model::Table* dsmc, const std::vector<int>& drawn,
                  Legend& legend) {
  const model::PlotSettings& p = s.plot;
  const std::string& y = pn.y;
  const std::vector<int> cycle = species_cycle(theory), dcycle = dsmc ? species_cycle(*dsmc) : std::vector<int>{};
  legend.add_style(black_line(1, "theory: " + s.theory.level));
  for (const int k : drawn) {
    const std::size_t o = std::size_t(std::find(cycle.begin(), cycle.end(), k) - cycle.begin());
    const int ls = species_style(k);
    legend.add_species(k, species_label(s, k, y));
    // Solid (dt 1): the black style 9 of γ and totals is dashed by default, and the paper level beside it is dashed too.
    pn.plots.push_back(fmt::format("'theory.tsv' every {}::{} using (column('{}')):(column('{}')) with lines ls {} dt 1 notitle", cycle.size(), o, p.x, y, ls));
    // The paper level's curve beside the judged level's (kinetic scenes), and what the DSMC of a
    // D_k/D_1 sweep measures (MSD increments), so the points are read against the right line.
    for (const auto& [suffix, dt, what] : {std::tuple{"_paper", 2, "paper level"}, std::tuple{"_increment", 3, "MSD increments"}})
      if (theory.column(y + suffix) >= 0) {
        pn.plots.push_back(fmt::format("'theory.tsv' every {}::{} using (column('{}')):(column('{}{}')) with lines ls {} dt {} notitle", cycle.size(), o,
                                       p.x, y, suffix, ls, dt));
        legend.add_style(black_line(dt, what));
      }
    // Dash-dot: the paper level beside it is dashed (MG Figs. 3, 7 draw all three).
    if (p.maxwell && theory.column(y + "_maxwell") >= 0) {
      pn.plots.push_back(fmt::format("'theory.tsv' every {}::{} using (column('{}')):(column('{}_maxwell')) with lines ls {} dt 4 notitle", cycle.size(), o,
                                     p.x, y, ls));
      legend.add_style(black_line(4, "Maxwell–Boltzmann"));
    }
    const auto d = std::find(dcycle.begin(), dcycle.end(), k);
    if (dsmc && dsmc->column(y + "_err") >= 0 && dsmc->column(p.x) >= 0 && d != dcycle.end()) {
      pn.plots.push_back(fmt::format("'dsmc.tsv' every {}::{} using (column('{}')):(column('{}')):{} with yerrorbars ls {} dt 1 lw 1.2 pt 7 ps 0.6 notitle",
                                     dcycle.size(), d - dcycle.begin(), p.x, y, error_bar(y, pn.logy), ls));
      legend.add_style("keyentry with yerrorbars lc rgb 'black' lw 1.2 pt 7 ps 0.6 title 'DSMC ± 1σ'");
    }
  }
}

std::vector<double> y_values(const Panel& pn, const model::Table& theory, const model::Table* dsmc, const std::vector<int>& drawn, bool maxwell) {
  std::vector<double> v;
  auto add = [&](const model::Table& t, const std::string& column, double lo, double hi) {
    for (const double x : column_values(t, column, drawn))
      if ((!pn.logy || x > 0.0) && x >= lo && x <= hi) v.push_back(x);
  };
  add(theory, pn.y, -INFINITY, INFINITY);
  if (dsmc) add(*dsmc, pn.y, -INFINITY, INFINITY);
  if (v.empty()) return v;
  const auto [a, b] = std::minmax_element(v.begin(), v.end());
  const double lo = pn.logy ? *a / 10.0 : *a - 0.5 * (*b - *a), hi = pn.logy ? *b * 10.0 : *b + 0.5 * (*b - *a);
  for (const std::string& beside : {pn.y + "_paper", pn.y + "_increment", maxwell ? pn.y + "_maxwell" : std::string()})
    if (!beside.empty()) add(theory, beside, lo, hi);
  // DSMC's error bars, on a linear axis (on a log axis a bar reaching zero stops at a tenth of the value).
  const int yc = dsmc ? dsmc->column(pn.y) : -1, ec = dsmc ? dsmc->column(pn.y + "_err") : -1, sc = dsmc ? dsmc->column("species") : -1;
  if (!pn.logy && yc >= 0 && ec >= 0 && sc >= 0)
    for (const auto& row : dsmc->rows)
      if (std::find(drawn.begin(), drawn.end(), int(row[sc])) != drawn.end())
        for (const double x : {row[yc] - row[ec], row[yc] + row[ec]})
          if (std::isfinite(x) && x >= lo && x <= hi) v.push_back(x);
  return v;
}

}  // namespace granmix::compare::figure
