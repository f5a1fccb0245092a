#include "frozen_model_errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "deviations.hpp"
#include "model/errors.hpp"
#include "model/model_error.hpp"
#include "model/sha256.hpp"

namespace granmix::compare {

namespace {

bool computed(const model::CompareQuantity& q) { return !q.correction_from.empty() || !q.error_column.empty(); }

}  // namespace

std::optional<double> FrozenModelErrors::at(const std::string& quantity, int species, double x) const {
  const auto it = points.find(quantity);
  if (it == points.end()) return std::nullopt;
  for (const FrozenPoint& p : it->second)
    if (p.species == species && same_location(p.x, x)) return p.model_error;
  return std::nullopt;
}

FrozenModelErrors compute_model_errors(const model::Scene& scene, const model::Table& theory) {
  FrozenModelErrors e;
  e.scene_sha256 = model::sha256_hex(scene.text);
  const int ts = theory.column("species");
  if (theory.columns.empty() || ts < 0) return e;
  for (const model::CompareQuantity& q : scene.compare) {
    if (!computed(q)) continue;
    const model::ModelError m(q, theory);
    if (m.predicted() < 0) continue;
    std::vector<FrozenPoint>& out = e.points[label(q)];
    for (const auto& row : theory.rows)
      if (model::covers(q, int(row[std::size_t(ts)])) && std::isfinite(row[std::size_t(m.predicted())]))
        out.push_back({row[0], int(row[std::size_t(ts)]), m.at(row)});
  }
  return e;
}

std::string format_model_errors(const model::Scene& scene, const FrozenModelErrors& e) {
  std::string s = fmt::format("# frozen model errors of scene {} ({}), sha256 {}\n", scene.name, scene.file, e.scene_sha256);
  s += "# the bounds compare and validate judge with; regenerate after a reviewed change: build/granmix model-errors --write\n";
  s += "# (docs/judging.md, \"Frozen model errors\")\nquantity\tx\tspecies\tmodel_error\n";
  for (const auto& [quantity, points] : e.points)
    for (const FrozenPoint& p : points) s += fmt::format("{}\t{:.17g}\t{}\t{:.17g}\n", quantity, p.x, p.species, p.model_error);
  return s;
}

FrozenModelErrors parse_model_errors(const std::string& text, const std::string& path) {
  FrozenModelErrors e;
  std::istringstream in(text);
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.rfind("# frozen model errors", 0) == 0) {
      const auto at = line.rfind("sha256 ");
      if (at != std::string::npos) e.scene_sha256 = line.substr(at + 7);
    }
    if (line.empty() || line[0] == '#' || line.rfind("quantity\t", 0) == 0) continue;
    std::vector<std::string> f;
    for (std::size_t a = 0, b; a <= line.size(); a = b + 1) {
      b = std::min(line.find('\t', a), line.size());
      f.push_back(line.substr(a, b - a));
    }
    char* end = nullptr;
    FrozenPoint p{};
    bool ok = f.size() == 4;
    if (ok) p.x = std::strtod(f[1].c_str(), &end), ok = *end == '\0';
    if (ok) p.species = int(std::strtol(f[2].c_str(), &end, 10)), ok = *end == '\0';
    if (ok) p.model_error = std::strtod(f[3].c_str(), &end), ok = *end == '\0';  // strtod reads "nan" too
    if (!ok) throw InputError(path + ":" + std::to_string(n) + ": expected quantity, x, species, model_error (allowed: the file as granmix model-errors --write writes it)");
    e.points[f[0]].push_back(p);
  }
  return e;
}

std::filesystem::path frozen_table_path(const model::Scene& scene) {
  const std::filesystem::path file = std::filesystem::path(scene.file).lexically_normal();
  if (!model::is_paper_scene(scene.file) || file.parent_path().filename() != "scenes") return {};
  return file.parent_path().parent_path() / "model-errors" / (scene.name + ".tsv");
}

std::optional<FrozenModelErrors> load_frozen_model_errors(const model::Scene& scene) {
  const std::filesystem::path path = frozen_table_path(scene);
  if (path.empty() || std::none_of(scene.compare.begin(), scene.compare.end(), computed)) return std::nullopt;
  const std::string regenerate = " (allowed: the table of this version of the scene: build/granmix model-errors --write, after review)";
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": no frozen model errors for scene " + scene.name + regenerate);
  std::ostringstream text;
  text << in.rdbuf();
  FrozenModelErrors e = parse_model_errors(text.str(), path.string());
  if (e.scene_sha256 != model::sha256_hex(scene.text))
    throw InputError(path.string() + ": frozen model errors of another version of " + scene.file + " (sha256 " + e.scene_sha256 + ")" + regenerate);
  return e;
}

std::pair<double, std::string> largest_drift(const FrozenModelErrors& frozen, const FrozenModelErrors& live) {
  double worst = 0.0;
  std::string where = "none";
  for (const auto& [quantity, points] : live.points)
    for (const FrozenPoint& p : points) {
      const std::optional<double> f = frozen.at(quantity, p.species, p.x);
      const double drift = f ? std::abs(p.model_error - *f) / std::max(*f, model_error_floor) : INFINITY;
      if (!(drift <= worst)) {  // a NaN drift (NaN model error) counts as the largest
        worst = std::isnan(drift) ? INFINITY : drift;
        where = fmt::format("{} species {} at x = {:g}: live {:.4g}, frozen {}", quantity, p.species, p.x, p.model_error, f ? fmt::format("{:.4g}", *f) : "absent");
      }
    }
  for (const auto& [quantity, points] : frozen.points)
    if (!live.points.count(quantity)) return {INFINITY, quantity + ": frozen but no longer computed"};
  return {worst, where};
}

}  // namespace granmix::compare
