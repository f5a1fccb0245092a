#pragma once
// The figure of a scene (docs/architecture.md §3): <scene>.gp written beside theory.tsv and dsmc.tsv, using
// plots/style.gp; rendered to <scene>.png (pngcairo) and <scene>.pdf (pdfcairo) when gnuplot is
// installed. Theory as lines, DSMC as symbols with error bars, guide slopes dashed.
#include <filesystem>
#include <string>

#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::compare {

struct FigureResult {
  bool rendered = false;
  std::string message;  // what was drawn, or how to get the figure
};

FigureResult write_figure(const std::filesystem::path& dir, const model::Scene& scene, const model::Table& theory,
                          const model::Table* dsmc);

}  // namespace granmix::compare
