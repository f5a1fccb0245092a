#pragma once
// The figure of a scene (docs/user-guide.md, "Figures"): <scene>.gp written beside theory.tsv, dsmc.tsv and
// deviations.tsv, self-contained (the style of plots/style.gp copied in), rendered to <scene>.png (pngcairo) and
// <scene>.pdf (pdfcairo) when gnuplot is installed. One panel per quantity (a paper scene: its [plot] y only), theory
// as lines, DSMC as symbols with error bars; under a judged curve its residual panel with the tolerance band; the
// legend in the right margin.
#include <filesystem>
#include <string>
#include <vector>

#include "deviations.hpp"
#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::compare {

struct FigureResult {
  bool rendered = false;
  std::string message;  // what was drawn, or how to get the figure
};

// The script's text; `deviations` are the rows of deviations.tsv (empty when the scene is not judged).
std::string figure_script(const model::Scene& scene, const model::Table& theory, const model::Table* dsmc,
                          const std::vector<Deviation>& deviations);

// Writes <scene>.gp into `dir` and runs gnuplot on it there.
FigureResult write_figure(const std::filesystem::path& dir, const model::Scene& scene, const model::Table& theory,
                          const model::Table* dsmc, const std::vector<Deviation>& deviations);

}  // namespace granmix::compare
