// The figure of a scene (compare/gnuplot_figure.hpp): one panel per observable with labelled axes, a residual panel
// under each judged curve, a legend outside the data, guides within the data and a script that stands alone.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "compare/gnuplot_figure.hpp"
#include "model/model_error.hpp"
#include "run_cli.hpp"
#include "theory/scene_theory.hpp"

using namespace granmix;

namespace {

std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

bool have_gnuplot() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

// A binary's partial MSD from the ballistic t² to a logarithmic growth, ln(1 + t²), 41 log-spaced times from 1e-2 to 1e6
// (the shape of v1 Fig. 2), with DSMC 1% above theory and deviations judged as compare would write them.
struct Synthetic {
  model::Table theory{{"t", "species", "msd", "msd_paper"}, {}}, dsmc{{"t", "species", "msd", "msd_err"}, {}};
  std::vector<compare::Deviation> deviations;
};

Synthetic ballistic_to_log(const model::Scene& s) {
  Synthetic out;
  for (int i = 0; i <= 40; ++i) {
    const double t = std::pow(10.0, -2.0 + 0.2 * i);
    for (int k = 0; k <= 2; ++k) {
      const double scale = k == 2 ? 0.02 : 1.0, msd = scale * std::log1p(t * t);
      out.theory.rows.push_back({t, double(k), msd, 1.02 * msd});
      out.dsmc.rows.push_back({t, double(k), 1.01 * msd, 0.005 * msd});
      for (const auto& q : s.compare)
        if (model::covers(q, k))
          out.deviations.push_back({t, k, compare::label(q), msd, 1.01 * msd, 0.005 * msd, 0.01, 2.0, true, true, 0.0, 0.001, true});
    }
  }
  return out;
}

}  // namespace

TEST_CASE("figure of a user scene: a panel per observable with a residual panel each, labelled log axes, no path of the build", "[compare][dsmc]") {
  const auto d = test::fresh_dir("figure-ternary");
  const std::string scene = std::string(GRANMIX_SOURCE_DIR) + "/examples/ternary.toml";
  const auto r = test::run_granmix("compare " + scene + " --out " + d.string());
  INFO(r.output);
  REQUIRE(r.code == 0);
  const std::filesystem::path folder = d / "example-ternary";
  const std::string gp = file_text(folder / "example-ternary.gp");
  // ternary.toml asks for temperatures and msd: a main panel each, each with its residual panel below.
  CHECK(occurrences(gp, "\n# T\n") == 1);
  CHECK(occurrences(gp, "\n# msd\n") == 1);
  CHECK(occurrences(gp, "set ylabel \"temperature T_k  [T_u]\"") == 1);
  CHECK(occurrences(gp, "set ylabel \"MSD ⟨R_k^2⟩  [σ_u^2]\"") == 1);
  CHECK(occurrences(gp, "set ylabel \"DSMC/theory − 1\"") == 2);
  CHECK(gp.find("set xlabel \"time t  [t_u]\"") != std::string::npos);
  CHECK(gp.find("set logscale x") != std::string::npos);  // times 10 to 1000
  CHECK(gp.find("using 1:2:3 with filledcurves") != std::string::npos);  // the tolerance band
  CHECK(gp.find("'deviations.tsv'") != std::string::npos);  // read, not recomputed
  // The legend: each species named once, in the right margin.
  CHECK(occurrences(gp, "title \"species 3: m = 20, σ = 2\"") == 1);
  CHECK(gp.find("set key at screen") != std::string::npos);
  CHECK(gp.find("pngcairo") != std::string::npos);
  CHECK(gp.find("pdfcairo") != std::string::npos);
  // Self-contained: no `load`, no path into the source or the build tree.
  CHECK(gp.find("\nload ") == std::string::npos);
  CHECK(gp.find(GRANMIX_SOURCE_DIR) == std::string::npos);
  CHECK(gp.find(std::filesystem::path(GRANMIX_EXE).parent_path().string()) == std::string::npos);
  if (!have_gnuplot()) {
    WARN("gnuplot is not installed: the rendering of the figure is not checked");
    return;
  }
  // The script alone, in a folder of its own with the three tables, draws both files.
  const auto copy = test::fresh_dir("figure-ternary-copy");
  for (const char* f : {"example-ternary.gp", "theory.tsv", "dsmc.tsv", "deviations.tsv"}) std::filesystem::copy(folder / f, copy / f);
  REQUIRE(std::system(("cd '" + copy.string() + "' && gnuplot example-ternary.gp > gnuplot.log 2>&1").c_str()) == 0);
  CHECK(file_text(copy / "gnuplot.log").empty());  // no warning either
  for (const char* f : {"example-ternary.png", "example-ternary.pdf"}) {
    REQUIRE(std::filesystem::exists(copy / f));
    CHECK(std::filesystem::file_size(copy / f) > 10000);
    CHECK(std::filesystem::file_size(folder / f) == std::filesystem::file_size(copy / f));
  }
}

TEST_CASE("figure of a paper scene: its [plot] settings kept, one panel and its residual panel, guides within the data", "[compare]") {
  const model::Scene s = theory::load_scene(test::scene_path("bo1-fig02.toml"));
  const Synthetic data = ballistic_to_log(s);
  const std::string gp = compare::figure_script(s, data.theory, &data.dsmc, data.deviations);
  // The paper's own axes: labels, log scales; one main panel (msd), not one per observable asked.
  CHECK(gp.find("set ylabel \"<R_k^2(t)>\"") != std::string::npos);
  CHECK(gp.find("set xlabel \"t\"") != std::string::npos);
  CHECK(gp.find("set logscale y") != std::string::npos);
  CHECK(occurrences(gp, "\n# msd\n") == 1);
  CHECK(occurrences(gp, "\n# T\n") == 0);
  // The residual panel: the judged species' rows of deviations.tsv, in their bands.
  CHECK(gp.find("set ylabel \"DSMC/theory − 1\"") != std::string::npos);
  CHECK(gp.find("strcol('quantity') eq 'msd[2]' && column('species') == 2") != std::string::npos);
  CHECK(gp.find("strcol('quantity') eq 'msd[0,1]' && column('species') == 0") != std::string::npos);
  // Guides (slopes "2" and "log") sampled only where they stay within the data: x in [1e-2, 1e6] and the curve's
  // values in [min, max] of the msd drawn.
  double ymin = INFINITY, ymax = 0.0;
  for (const auto& row : data.theory.rows) ymin = std::min(ymin, row[2]), ymax = std::max(ymax, row[2]);
  const std::regex guide(R"(\[x=([-0-9.e+]+):([-0-9.e+]+)\] ([^ ]+) with lines)");
  std::size_t guides = 0;
  for (auto it = std::sregex_iterator(gp.begin(), gp.end(), guide); it != std::sregex_iterator(); ++it, ++guides) {
    const double lo = std::stod((*it)[1]), hi = std::stod((*it)[2]);
    INFO((*it)[0].str());
    CHECK(lo >= 1e-2 * (1 - 1e-6));
    CHECK(hi <= 1e6 * (1 + 1e-6));
    CHECK(lo < hi);
    if ((*it)[3].str().find("**(2)") != std::string::npos) {  // t² from the first point of species 2: ends at the data's largest value
      const double at_hi = 0.02 * std::log1p(1e-4) * std::pow(hi / 1e-2, 2);
      CHECK(at_hi <= ymax * (1 + 1e-6));
      CHECK(hi < 1e3);  // far inside the time range: the guide no longer runs to 10^10
    }
  }
  CHECK(guides == 2);
}

TEST_CASE("figure without gnuplot: the data and the script are written and the run succeeds", "[compare][dsmc]") {
  const auto d = test::fresh_dir("figure-no-gnuplot");
  const std::string scene = std::string(GRANMIX_SOURCE_DIR) + "/examples/ternary.toml";
  // A PATH without gnuplot: granmix is named by its full path.
  const std::string cmd = "PATH=/nonexistent " + std::string(GRANMIX_EXE) + " compare " + scene + " --out " + d.string() + " > /dev/null 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::filesystem::path folder = d / "example-ternary";
  CHECK(std::filesystem::exists(folder / "example-ternary.gp"));
  CHECK(!std::filesystem::exists(folder / "example-ternary.png"));
  CHECK(file_text(folder / "report.json").find("gnuplot not found") != std::string::npos);
}
