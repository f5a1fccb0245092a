// index.html of `granmix validate`: one page with the summary table, a section per scene
// with its figure, tolerances and whys, and relative links to the scene's files; all text escaped.
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <sstream>

#include "compare/html_report.hpp"
#include "run_cli.hpp"

using namespace granmix;

namespace {

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

}  // namespace

TEST_CASE("html_escape: the five characters that break markup or attributes", "[compare]") {
  CHECK(compare::html_escape("a<b>&\"c'") == "a&lt;b&gt;&amp;&quot;c&#39;");
  CHECK(compare::html_escape("σ = 0.02, ε ≤ 1") == "σ = 0.02, ε ≤ 1");  // UTF-8 passes through
}

TEST_CASE("granmix validate writes index.html: summary rows - pass and fail cells - figure - links - escaped text", "[compare][dsmc]") {
  const auto d = test::fresh_dir("html-report");
  std::filesystem::create_directories(d / "scenes");
  std::filesystem::copy(test::scene_path("mg-fig01.toml"), d / "scenes" / "mg-fig01.toml");
  // The same scene under another name, with markup in its title and impossible tolerances: it must fail.
  std::string text = read_text(test::scene_path("mg-fig01.toml"));
  const std::string name = "name = \"mg-fig01\"";
  REQUIRE(text.find(name) != std::string::npos);
  text.replace(text.find(name), name.size(), "name = \"strict\"");
  text = std::regex_replace(text, std::regex(R"(\brelative = [0-9.eE+-]+)"), "relative = 1e-9");
  text = std::regex_replace(text, std::regex(R"(\bz = [0-9.]+)"), "z = 0");
  const auto title = text.find("title = \"");
  REQUIRE(title != std::string::npos);
  text.insert(title + 9, "<i>a & b</i> ");
  test::write_file(d / "scenes" / "strict.toml", text);

  const auto r = test::run_granmix("validate --scenes " + (d / "scenes").string() + " --out " + (d / "out").string());
  INFO(r.output);
  CHECK(r.code == 1);  // strict fails
  REQUIRE(std::filesystem::exists(d / "out" / "index.html"));
  const std::string html = read_text(d / "out" / "index.html");
  INFO(html.substr(0, 4000));
  CHECK(html.find("<!DOCTYPE html>") == 0);
  CHECK(html.find("<script") == std::string::npos);
  // Summary table: one row per compared quantity of summary.tsv (mg-fig01 and strict judge the same quantities).
  std::istringstream tsv(read_text(d / "out" / "summary.tsv"));
  std::size_t rows = 0;
  for (std::string line; std::getline(tsv, line);) rows += !line.empty() && line[0] != '#';
  rows -= 1;  // the header line
  CHECK(count(html, "<td class=\"pass\">yes</td>") + count(html, "<td class=\"fail\">NO</td>") == rows);
  CHECK(count(html, "<td class=\"fail\">NO</td>") >= 1);
  CHECK(count(html, "<td class=\"pass\">yes</td>") >= rows / 2);
  // Per scene: an anchor, the paper source, the figure (when gnuplot drew it) and relative links to the files.
  for (const std::string s : {"mg-fig01", "strict"}) {
    CHECK(html.find("<h2 id=\"" + s + "\">") != std::string::npos);
    for (const std::string f : {"theory.tsv", "dsmc.tsv", "deviations.tsv", "report.json"})
      CHECK(html.find("href=\"" + s + "/" + f + "\"") != std::string::npos);
    if (std::filesystem::exists(d / "out" / s / (s + ".png"))) CHECK(html.find("<img src=\"" + s + "/" + s + ".png\"") != std::string::npos);
  }
  CHECK(html.find("Montanero &amp; Garzo 2002, Fig. 1(a)") != std::string::npos);
  // The tolerance cell states the judging rule: the computed parts add to the statistical one, and the cap.
  CHECK(html.find("<td>|Δ kinetic, cooling4| + 4σ, model error ≤ 0.005</td>") != std::string::npos);
  CHECK(html.find("why:") != std::string::npos);
  // The title's markup is shown as text, never interpreted.
  CHECK(html.find("&lt;i&gt;a &amp; b&lt;/i&gt;") != std::string::npos);
  CHECK(html.find("<i>a & b</i>") == std::string::npos);
}
