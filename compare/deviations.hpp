#pragma once
// Theory against DSMC, point by point (docs/architecture.md §3): for every compared quantity and every
// (t or x, species) row present in both tables, rel = (dsmc − theory)/|theory| and z = (dsmc − theory)/err.
// A judged point passes when |dsmc − theory| <= relative |theory| + z_tol err (model error plus
// statistical error), or <= absolute. Where theory.tsv also holds the paper level's value
// (`<column>_paper`), its gap to DSMC is reported beside (paper_rel), not judged.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/scene.hpp"
#include "model/table.hpp"

namespace granmix::compare {

// The DSMC error bar used for z and the verdict is at least this fraction of |dsmc| (or |theory|): rounding level.
inline constexpr double error_floor = 1e-12;

// Whether two tables' locations (t, v* or the swept value) are the same point: both sides use the scene's grid, so
// they agree to rounding.
inline bool same_location(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

// z needs this many replicas to mean anything (docs/judging.md §6): fewer, and the comparison says so.
inline constexpr std::size_t replicas_for_z = 8;

struct Deviation {
  double t;  // the location: t, or the swept value, or v*
  int species;
  std::string quantity;
  double theory, dsmc, dsmc_err, rel, z;
  bool judged, pass;
  double paper_rel = 0.0;  // (dsmc − paper level)/|paper level|; NaN without a paper column
  double model_error = 0.0;  // the relative tolerance applied at this point (relative + computed correction)
  bool resolved = true;      // model_error within the quantity's model_error_max (a point beyond fails)
  // |dsmc − theory| over the bound model_error·|theory| + z·σ (the smaller with |dsmc − theory|/absolute when an
  // absolute tolerance is set): at most 1 where the point passes on its bound; NaN without an error bar.
  double bound_ratio = NAN;
};

struct QuantityResult {
  model::CompareQuantity spec;
  std::size_t points = 0, judged = 0, failed = 0;
  std::size_t unresolved = 0;         // judged points failed because their model error exceeds model_error_max
  double max_rel = 0.0, max_z = 0.0;  // over judged points (|rel|, |z|)
  double max_paper_rel = NAN;         // the paper level's largest |rel| over the same points (NaN: none)
  double max_model_error = 0.0;       // largest relative tolerance applied (relative + correction)
  std::string not_judged;             // why no point was judged (no error bar: 1 replica); empty when judged
  std::vector<double> bound_ratios;   // the judged points' bound_ratio (granmix validate --seeds: calibration)
  bool pass() const { return failed == 0 && judged > 0; }
};

// A quantity's name in files and reports: "msd", or "msd[1,0]" when restricted to species.
std::string label(const model::CompareQuantity& q);

// "0.02+4σ" (and "or ±0.02" when an absolute tolerance is set), and the same as JSON.
std::string tolerance_text(const model::CompareQuantity& q);
nlohmann::ordered_json tolerance_json(const model::CompareQuantity& q);

class FrozenModelErrors;
// frozen: the scene's committed model errors (frozen_model_errors.hpp), used instead of the live computation for every
// quantity with computed parts; null: the live computation (a user's scene).
std::vector<Deviation> deviations(const model::Table& theory, const model::Table& dsmc,
                                  const std::vector<model::CompareQuantity>& quantities, const FrozenModelErrors* frozen = nullptr);
std::vector<QuantityResult> summarise(const std::vector<Deviation>& d, const std::vector<model::CompareQuantity>& quantities);
// deviations.tsv: provenance, then x species quantity theory dsmc dsmc_err rel z judged pass, where x is
// the location column of the theory table (t; eps, density, n_star for a sweep; v for a distribution).
std::string format_deviations(const std::string& provenance, const std::string& x, const std::vector<Deviation>& d);

}  // namespace granmix::compare
