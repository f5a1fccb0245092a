#pragma once
// The parts of a scene's figure that compare/gnuplot_figure.cpp assembles into one gnuplot script: the axes'
// helpers (figure_axes.cpp), the curves and the legend (figure_curves.cpp), the guides (figure_guides.cpp) and the
// residual panel under a judged curve (figure_residuals.cpp).
#include <cmath>
#include <string>
#include <utility>
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

// The legend, drawn once in the figure's right margin: each species once in its colour, then the line and symbol
// styles (theory level, paper level, DSMC, tolerance band) once in black.
struct Legend {
  std::vector<std::pair<int, std::string>> species;  // species number (-1: a curve over species), its text
  std::vector<std::string> styles;                   // keyentry plot elements

  void add_species(int k, const std::string& text);  // a second quantity's text for the same species joins with " / "
  void add_style(const std::string& entry);
  std::vector<std::string> entries() const;          // the keyentry plot elements, species first
};

// One quantity's panel and the residual panel under it.
struct Panel {
  std::string y, ylabel;
  bool logy = false;
  std::vector<std::string> plots, labels;  // plot elements; `set label` commands (the guides' names)
  std::vector<double> yvalues;             // the values its y range holds; empty: autoscaled
  ResidualPanel residual;
};

// Species in row order within one x value: long-form tables cycle through them.
std::vector<int> species_cycle(const model::Table& t);
// x = "species": one curve over species at the last sample time (v1 Fig. 8).
void species_curves(Panel& pn, const model::Table& theory, const model::Table* dsmc, Legend& legend, const std::string& level);
// Theory, its companions drawn beside it, and DSMC, one colour per species.
void species_rows(Panel& pn, const model::Scene& s, const model::Table& theory, const model::Table* dsmc, const std::vector<int>& drawn,
                  Legend& legend);
// The values a panel's y range holds: the judged level's and DSMC's, and the curves drawn beside them (paper level,
// MSD increments, Maxwell–Boltzmann) and DSMC's error bars (a linear axis) where they stay within a decade (a log
// axis) or half the range's width of them; beyond, they leave the frame instead of squashing the data.
std::vector<double> y_values(const Panel& pn, const model::Table& theory, const model::Table* dsmc, const std::vector<int>& drawn, bool maxwell);
// Guide slopes ([plot] slopes), anchored on the last drawn species' curve (t² at its first point, the others at its
// last) and drawn only over the x range where they stay within the data's x and y ranges, so that they never stretch
// the axes; each named at one end.
void guides(Panel& pn, const model::Scene& s, const model::Table& theory, const std::vector<int>& drawn);

}  // namespace granmix::compare::figure
