#pragma once
// What each observable owes, declared once (docs/architecture.md §8, "Add an observable"): the [observables] key that
// asks for it, the quantity columns it puts in theory.tsv and dsmc.tsv (the names [compare] judges and [plot] draws),
// the axis of its tables, and where its theory column, its DSMC estimator and its error estimator are computed. The
// lists of observables — the quantity names a scene may judge and plot, the "asks for no observable" message, the
// table `granmix observables` prints for docs/scenes.md — are derived from here.
#include <string>
#include <vector>

namespace granmix::model {

struct Observables;

struct ObservableDescriptor {
  std::string key;                      // [observables] key
  std::vector<std::string> quantities;  // its columns in theory.tsv and dsmc.tsv ([compare] name, [plot] y)
  std::string axis;                     // the tables' first column
  std::string summary;
  std::string theory, dsmc, error;      // where its theory column, DSMC estimator and DSMC error are computed
  bool plotted_on_y = true;             // false: an x axis ([plot] x), not a curve
  bool (*asked)(const Observables&);    // whether a scene's [observables] ask for it
  // One axis label per quantity (gnuplot enhanced text: _k subscript, ^2 superscript), with its units in brackets:
  // σ_u, T_u, t_u = σ_u(m_u/T_u)^{1/2} are the units of the scene's diameters, temperatures and times (docs/scenes.md).
  std::vector<std::string> labels;
};

const std::vector<ObservableDescriptor>& observable_catalogue();
// Every quantity name, in the catalogue's order; those [plot] y may take; the [observables] keys.
std::vector<std::string> observable_quantities();
std::vector<std::string> plotted_quantities();
std::vector<std::string> observable_keys();
// A figure's axis label for a column of theory.tsv: a quantity's from the catalogue, a location column's (t, lag, v,
// eps, density, n_star, species) from its own list; times in t_0 = λ_11/v_01(0) when `time_unit_mg`. The column name
// itself when unknown.
std::string axis_label(const std::string& column, bool time_unit_mg);
// `granmix observables`: one row per observable (key, quantities, axis, what it is, where each duty lives).
std::string observable_listing(bool markdown);

}  // namespace granmix::model
