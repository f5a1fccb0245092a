#pragma once
// The parts of a scene's figure that compare/gnuplot_figure.cpp assembles into one gnuplot script: the axes'
// helpers (figure_axes.cpp) and the residual panel under a judged curve (figure_residuals.cpp).
#include <cmath>
#include <string>
#include <vector>

#include "deviations.hpp"
#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::compare::figure {

// A species' line style in plots/style.gp: 1-8 by species number (cycling), 9 (black) for row 0 (total, mean, γ).
int species_style(int k);
// Whether positive data span more than two decades (max/min > 100): such an axis is drawn logarithmic.
bool spans_decades(const std::vector<double>& values);
// The finite values of a column over the rows of the given species (all rows when `species` is empty).
std::vector<double> column_values(const model::Table& t, const std::string& column, const std::vector<int>& species);
// A gnuplot string in double quotes (enhanced text markup kept).
std::string quote(const std::string& s);

struct ResidualPanel {
  std::string tables;              // `set table` commands filtering deviations.tsv into datablocks, run before drawing
  std::vector<std::string> plots;  // the panel's plot elements; empty: the quantity is not judged
  double range = NAN;              // the y axis spans ±range; points beyond are drawn as arrows on its edge
  std::string ylabel;              // DSMC/theory − 1, or (DSMC − theory)/|theory| where a theory value is negative
  std::vector<int> species;        // the species with residuals (their colours)
  bool failed = false;             // a judged point outside its tolerance
  bool unjudged = false;           // a point outside the judged window (drawn open)
};

// The residual panel under the curves of quantity `y` ([plot] x on the x axis): rel = (DSMC − theory)/|theory| of
// every row of deviations.tsv for `y`, with ±σ/|theory| bars, in the band ±(model_error + z·σ/|theory|) (or
// absolute/|theory|, when larger) inside which a judged point passes (compare/deviations.hpp). `index` names the
// panel's datablocks.
ResidualPanel residual_panel(const model::Scene& s, const std::string& y, const std::vector<Deviation>& d,
                             const model::Table& theory, int index);

}  // namespace granmix::compare::figure
