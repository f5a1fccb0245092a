#pragma once
// Frozen model errors (docs/judging.md, "Frozen model errors"): the computed model error of every point of every
// compared quantity of a scene in compare/scenes/, written to a reviewed, committed table compare/model-errors/<scene>.tsv
// by `granmix model-errors --write`. compare and validate judge those scenes against the table, not against the live
// computation, so a bug in the judged level moves its curve but not its own bound (a bound taken from the distance to a
// companion of another closure would otherwise widen with the bug); `granmix model-errors` (a ctest) fails when the
// live computation drifts from the table by more than a stated fraction.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::compare {

// Relative drifts are measured against max(frozen, this): model errors below 10⁻⁴ lie below any DSMC resolution here.
inline constexpr double model_error_floor = 1e-4;
// The drift `granmix model-errors` accepts by default: a bound moved by 5% of itself needs a review.
inline constexpr double default_model_error_drift = 0.05;

struct FrozenPoint {
  double x;
  int species;
  double model_error;
};

class FrozenModelErrors {
 public:
  std::string scene_sha256;
  std::map<std::string, std::vector<FrozenPoint>> points;  // per quantity label, in the table's order
  // The frozen model error at (quantity, species, x), the location matched to rounding as deviations.cpp matches rows.
  std::optional<double> at(const std::string& quantity, int species, double x) const;
};

// The computed model errors of a scene's compared quantities at every theory row they cover (the live computation).
FrozenModelErrors compute_model_errors(const model::Scene& scene, const model::Table& theory);
// The table's text (provenance comment lines, then quantity x species model_error) and its reading back.
std::string format_model_errors(const model::Scene& scene, const FrozenModelErrors& e);
FrozenModelErrors parse_model_errors(const std::string& text, const std::string& path);

// Where a scene's frozen table lives: compare/model-errors/<name>.tsv beside compare/scenes/ (empty for other scenes).
std::filesystem::path frozen_table_path(const model::Scene& scene);
// The frozen table of a scene of compare/scenes/ that has computed model errors: nullopt where the scene has none or
// is not a paper scene; a missing file or one of another version of the scene throws InputError naming the command
// that regenerates it.
std::optional<FrozenModelErrors> load_frozen_model_errors(const model::Scene& scene);

// The largest relative drift of `live` from `frozen` (|live − frozen| / max(frozen, floor)) and where it is, as text.
std::pair<double, std::string> largest_drift(const FrozenModelErrors& frozen, const FrozenModelErrors& live);

}  // namespace granmix::compare
