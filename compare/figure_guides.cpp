#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "figure_parts.hpp"

namespace granmix::compare::figure {

void guides(Panel& pn, const model::Scene& s, const model::Table& theory, const std::vector<int>& drawn) {
  if (drawn.empty() || s.plot.slopes.empty()) return;
  const int xc = theory.column(s.plot.x), yc = theory.column(pn.y), sc = theory.column("species");
  std::vector<std::vector<double>> curve;
  for (const auto& row : theory.rows)
    if (int(row[sc]) == drawn.back() && std::isfinite(row[yc]) && std::isfinite(row[xc])) curve.push_back(row);
  const std::vector<double> xs = column_values(theory, s.plot.x, drawn), ys = column_values(theory, pn.y, drawn);
  if (curve.empty() || xs.empty() || ys.empty()) return;
  const auto [xmin, xmax] = std::minmax_element(xs.begin(), xs.end());
  const auto [ymin, ymax] = std::minmax_element(ys.begin(), ys.end());
  const double x0 = curve.front()[xc], y0 = curve.front()[yc], x1 = curve.back()[xc], y1 = curve.back()[yc];
  for (const std::string& sl : s.plot.slopes) {
    // g(x) = ya (x/xa)^power, or y1 ln x / ln x1; [lo, hi]: where g lies within [ymin, ymax].
    double lo = *xmin, hi = *xmax;
    std::string expr, name;
    if (sl == "log") {
      if (!(x1 > 1.0 && y1 > 0.0)) continue;
      const double l1 = std::log(x1);
      // From a tenth of its end value on a log axis: towards t = 1 ln t falls to zero, a vertical drop.
      const double floor = pn.logy ? std::max(*ymin, y1 / 10.0) : *ymin;
      lo = std::max({lo, 1.0, std::exp(floor * l1 / y1)}), hi = std::min(hi, std::exp(*ymax * l1 / y1));
      expr = fmt::format("{:.8g}*log(x)/{:.8g}", y1, l1), name = "∝ ln t";
    } else {
      const double power = sl == "2" ? 2.0 : sl == "1" ? 1.0 : 1.0 / 6.0;
      const double xa = sl == "2" ? x0 : x1, ya = sl == "2" ? y0 : y1;
      if (!(xa > 0.0 && ya > 0.0)) continue;
      if (*ymin > 0.0) lo = std::max(lo, xa * std::pow(*ymin / ya, 1.0 / power));
      hi = std::min(hi, xa * std::pow(*ymax / ya, 1.0 / power));
      expr = fmt::format("{:.8g}*(x/{:.8g})**({})", ya, xa, sl == "1/6" ? "1.0/6" : sl);
      name = sl == "2" ? "∝ t^2" : sl == "1" ? "∝ t" : "∝ t^{1/6}";
    }
    if (!(lo < hi)) continue;
    pn.plots.push_back(fmt::format("[x={:.8g}:{:.8g}] {} with lines lc rgb 'black' lw 1.5 dt 3 notitle", lo, hi, expr));
    // The guide's name beside its end: the upper end of a rising line, the lower end of ln t's (drawn from the last point).
    const double xl = sl == "2" ? hi : lo;
    const double yl = sl == "log" ? y1 * std::log(xl) / std::log(x1)
                                  : (sl == "2" ? y0 : y1) * std::pow(xl / (sl == "2" ? x0 : x1), sl == "2" ? 2.0 : sl == "1" ? 1.0 : 1.0 / 6.0);
    pn.labels.push_back(fmt::format("set label {} at first {:.8g}, first {:.8g} {} offset {} front", quote(name), xl, yl,
                                    sl == "2" ? "right" : "left", sl == "2" ? "-0.5,0.6" : "0.5,-0.6"));
  }
}

}  // namespace granmix::compare::figure
