#include "gnuplot_figure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "figure_parts.hpp"
#include "figure_style.hpp"
#include "model/observable_catalogue.hpp"
#include "tsv_writer.hpp"

namespace granmix::compare {

namespace {

using figure::Legend;
using figure::Panel;
using figure::quote;
using figure::species_cycle;

// The quantities drawn, one panel each: [plot] y first, then every other quantity the scene asks for that theory.tsv
// holds (the catalogue's order). A paper scene keeps the paper's single panel.
std::vector<std::string> panel_quantities(const model::Scene& s, const model::Table& theory) {
  std::vector<std::string> out{s.plot.y};
  if (model::is_paper_scene(s.file)) return out;
  for (const model::ObservableDescriptor& d : model::observable_catalogue())
    if (d.plotted_on_y && d.asked(s.observables))
      for (const std::string& q : d.quantities)
        if (std::find(out.begin(), out.end(), q) == out.end() && !figure::column_values(theory, q, {}).empty()) out.push_back(q);
  return out;
}

// The species whose curves a panel draws: [plot] species, those with values (γ lives on row 0 only), and not
// species 1 of D_k/D_1 (identically 1).
std::vector<int> drawn_species(const model::Scene& s, const std::string& y, const model::Table& theory) {
  std::vector<int> out;
  for (const int k : species_cycle(theory)) {
    if (y == "D_ratio" && k == 1) continue;
    if (!s.plot.species.empty() && std::find(s.plot.species.begin(), s.plot.species.end(), std::size_t(k)) == s.plot.species.end()) continue;
    if (!figure::column_values(theory, y, {k}).empty()) out.push_back(k);
  }
  return out;
}

// An axis' range: the data's, padded by `pad` of its width (of its decades on a log axis). The x range is the same
// for every panel, main and residual alike.
std::string data_range(char axis, const std::vector<double>& v, bool log, double pad) {
  if (v.empty()) return fmt::format("set autoscale {}\n", axis);
  const auto [a, b] = std::minmax_element(v.begin(), v.end());
  if (*a == *b) return fmt::format("set autoscale {}\n", axis);
  if (log) {
    const double f = std::pow(*b / *a, pad);
    return fmt::format("set {}range [{:.8g}:{:.8g}]\n", axis, *a / f, *b * f);
  }
  const double d = pad * (*b - *a);
  return fmt::format("set {}range [{:.8g}:{:.8g}]\n", axis, *a - d, *b + d);
}

std::string log_axis(char axis, bool log) {
  return log ? fmt::format("set logscale {0}\nset format {0} '10^{{%T}}'\n", axis) : fmt::format("unset logscale {0}\nset format {0} '%g'\n", axis);
}

std::string plot_command(const std::vector<std::string>& plots) {
  std::string s = "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) s += (i ? ", \\\n     " : "") + plots[i];
  return s + "\n";
}

// Heights in rows of the figure: title, a main panel, a residual panel, the x axis' tics and label under a panel.
constexpr double title_rows = 0.6, main_rows = 3.0, residual_rows = 1.4, axis_rows = 1.0;
constexpr int width_px = 1000;  // the PNG's width; the PDF's is 7 in, the same proportions
constexpr double left = 0.10;   // the plots' left screen margin

// The plots' right screen margin: the legend beside it holds its longest entry (about 8.2 px a character at 12 pt,
// after 75 px of sample line).
double right_margin(const std::vector<std::string>& entries) {
  std::size_t longest = 0;
  for (const std::string& e : entries) {
    const auto a = e.find("title ");  // title "…" or title '…'
    if (a == std::string::npos || a + 7 > e.size()) continue;
    const auto b = e.find(e[a + 6], a + 7);
    std::size_t chars = 0;
    for (std::size_t i = a + 7; i < std::min(b, e.size()); ++i) chars += (e[i] & 0xC0) != 0x80;  // UTF-8: count code points
    longest = std::max(longest, chars);
  }
  return std::clamp(1.0 - (75.0 + 8.2 * double(longest) + 20.0) / width_px, 0.5, 0.8);
}

// Residual tics every step (1, 2 or 5 times a power of ten, at most 0.7 of the range) up to 0.75 of the range: the
// top tic's label stays clear of the main panel's lowest.
std::string residual_tics(double range) {
  const double p = std::pow(10.0, std::floor(std::log10(0.7 * range)));
  const double step = 5 * p <= 0.7 * range ? 5 * p : 2 * p <= 0.7 * range ? 2 * p : p;
  const double last = step * std::floor(0.75 * range / step);
  return fmt::format("set ytics {0:g}, {1:g}, {2:g}\nset yrange [{3:.4g}:{4:.4g}]\n", -last, step, last, -range, range);
}

}  // namespace

std::string figure_script(const model::Scene& s, const model::Table& theory, const model::Table* dsmc, const std::vector<Deviation>& deviations) {
  const model::PlotSettings& p = s.plot;
  Legend legend;
  std::vector<Panel> panels;
  const std::vector<std::string> quantities = panel_quantities(s, theory);
  std::vector<int> all_drawn;
  for (const std::string& y : quantities)
    for (const int k : drawn_species(s, y, theory))
      if (std::find(all_drawn.begin(), all_drawn.end(), k) == all_drawn.end()) all_drawn.push_back(k);
  const std::vector<double> xs = p.x == "species" ? figure::column_values(theory, "species", all_drawn) : figure::column_values(theory, p.x, all_drawn);
  const bool logx = p.logx.value_or(figure::spans_decades(xs));
  for (std::size_t i = 0; i < quantities.size(); ++i) {
    Panel pn;
    pn.y = quantities[i];
    const std::vector<int> drawn = drawn_species(s, pn.y, theory);
    const bool own = i == 0;  // [plot] y: its labels and axes as the scene sets them
    pn.ylabel = own && !p.ylabel.empty() ? p.ylabel : model::axis_label(pn.y, s.time_unit_mg);
    pn.logy = own && p.logy ? *p.logy : figure::spans_decades(figure::column_values(theory, pn.y, p.x == "species" ? std::vector<int>{} : drawn));
    if (p.x == "species") figure::species_curves(pn, theory, dsmc, legend, s.theory.level);
    else {
      figure::species_rows(pn, s, theory, dsmc, drawn, legend), figure::guides(pn, s, theory, drawn);
      pn.yvalues = figure::y_values(pn, theory, dsmc, drawn, p.maxwell);
    }
    if (!deviations.empty()) pn.residual = figure::residual_panel(s, pn.y, deviations, theory, int(i));
    if (pn.plots.empty()) continue;
    panels.push_back(std::move(pn));
  }
  bool band = false, failed = false, unjudged = false;
  for (const Panel& pn : panels)
    band = band || !pn.residual.plots.empty(), failed = failed || pn.residual.failed, unjudged = unjudged || pn.residual.unjudged;
  if (band) legend.add_style("keyentry with filledcurves lc rgb '#777777' fs transparent solid 0.3 noborder title 'tolerance band'");
  if (failed) legend.add_style("keyentry with points lc rgb 'black' lw 1.5 pt 2 ps 1.4 title 'outside its tolerance'");
  if (unjudged) legend.add_style("keyentry with points lc rgb 'black' pt 6 ps 0.6 title 'not judged'");
  if (panels.empty()) return "";

  double rows = title_rows;
  for (const Panel& pn : panels) rows += main_rows + (pn.residual.plots.empty() ? 0.0 : residual_rows) + axis_rows;
  const std::string xlabel = !p.xlabel.empty() ? p.xlabel : model::axis_label(p.x, s.time_unit_mg);
  const double right = right_margin(legend.entries());
  std::string body = fmt::format("set multiplot title {} noenhanced\n", quote(s.title));
  body += fmt::format("set lmargin at screen {}\nset rmargin at screen {}\n{}{}\n", left, right, log_axis('x', logx), data_range('x', xs, logx, 0.02));
  double top = 1.0 - title_rows / rows;
  const bool key_bottom = p.key.find("bottom") != std::string::npos;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const Panel& pn = panels[i];
    const bool under = !pn.residual.plots.empty();
    const double mid = top - main_rows / rows, bottom = mid - (under ? residual_rows / rows : 0.0);
    body += fmt::format("\n# {}\nset tmargin at screen {:.4f}\nset bmargin at screen {:.4f}\nset datafile columnheaders\n", pn.y, top, mid);
    body += log_axis('y', pn.logy) + data_range('y', pn.yvalues, pn.logy, 0.04) + fmt::format("set ylabel {} font ''\n", quote(pn.ylabel));
    body += under ? "set format x ''\nunset xlabel\n" : fmt::format("set xlabel {}\n", quote(xlabel));
    body += "unset label\n";
    for (const std::string& l : pn.labels) body += l + "\n";
    std::vector<std::string> plots = pn.plots;
    const bool key_here = key_bottom ? i + 1 == panels.size() : i == 0;
    if (key_here) {
      body += fmt::format("set key at screen {}, screen {:.4f} left {} Left reverse samplen 2.5 spacing 1.15 nobox\n", right + 0.02, key_bottom ? bottom : top,
                          key_bottom ? "bottom" : "top");
      const std::vector<std::string> entries = legend.entries();
      plots.insert(plots.end(), entries.begin(), entries.end());
    } else {
      body += "unset key\n";
    }
    body += plot_command(plots);
    if (under) {
      // Residuals: the datablocks filtered from deviations.tsv carry no header line.
      body += fmt::format("set tmargin at screen {:.4f}\nset bmargin at screen {:.4f}\nset datafile nocolumnheaders\nunset key\nunset label\n", mid, bottom);
      body += log_axis('y', false) + residual_tics(pn.residual.range) + fmt::format("gm_range = {:.4g}\n", pn.residual.range);
      body += fmt::format("set ylabel {} font gm_small\n", quote(pn.residual.ylabel));
      body += log_axis('x', logx) + fmt::format("set xlabel {}\n", quote(xlabel));
      body += plot_command(pn.residual.plots);
      body += "set ytics autofreq\n";
    }
    body += log_axis('x', logx);
    top = bottom - axis_rows / rows;
  }
  body += "unset multiplot\nunset output\n";

  std::string gp = "# Generated by granmix compare: " + s.title + " (" + s.source + ")\n";
  gp += "# Draws " + s.name + ".png and " + s.name + ".pdf from theory.tsv, dsmc.tsv and deviations.tsv in this folder: gnuplot " + s.name + ".gp\n";
  gp += "# The style (plots/style.gp of granmix):\n" + std::string(figure_style) + "\n";
  for (const Panel& pn : panels) gp += pn.residual.tables;
  // One body, two terminals (a multiplot cannot be replotted); the PDF's thinner lines and smaller symbols read as the PNG's.
  const int px = width_px, py = int(std::lround(rows * 112.0));
  gp += "do for [gm_out in \"png pdf\"] {\n";
  gp += fmt::format("if (gm_out eq \"png\") {{\n  set terminal pngcairo size {},{} enhanced font 'DejaVu Sans,12'\n  set output '{}.png'\n  gm_small = ',10'\n}} else {{\n", px, py, s.name);
  gp += fmt::format("  set terminal pdfcairo size 7in,{:.2f}in enhanced font 'DejaVu Sans,9.5' linewidth 0.8 pointscale 0.8\n  set output '{}.pdf'\n  gm_small = ',7.5'\n}}\n", 7.0 * py / px, s.name);
  gp += body + "}\n";
  return gp;
}

FigureResult write_figure(const std::filesystem::path& dir, const model::Scene& s, const model::Table& theory, const model::Table* dsmc,
                          const std::vector<Deviation>& deviations) {
  FigureResult out;
  const int xc = s.plot.x == "species" ? theory.column("species") : theory.column(s.plot.x), yc = theory.column(s.plot.y);
  if (xc < 0 || yc < 0) {
    out.message = "no figure: theory.tsv has no column '" + (xc < 0 ? s.plot.x : s.plot.y) + "' ([plot] x/y)";
    return out;
  }
  const std::string gp = figure_script(s, theory, dsmc, deviations);
  if (gp.empty()) {
    out.message = "no figure: theory.tsv has no finite value of '" + s.plot.y + "' for the species drawn ([plot] species)";
    return out;
  }
  write_atomically(dir / (s.name + ".gp"), gp);
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    out.message = "gnuplot not found: the data and " + s.name + ".gp are written; install gnuplot-nox (make deps) and run 'gnuplot " +
                  s.name + ".gp' in the scene folder";
    return out;
  }
  const std::string cmd = "cd '" + dir.string() + "' && gnuplot '" + s.name + ".gp' > gnuplot.log 2>&1";
  out.rendered = std::system(cmd.c_str()) == 0;
  if (out.rendered) std::filesystem::remove(dir / "gnuplot.log");
  out.message = out.rendered ? s.name + ".png, " + s.name + ".pdf" : "gnuplot failed: see gnuplot.log in the scene folder";
  return out;
}

}  // namespace granmix::compare
