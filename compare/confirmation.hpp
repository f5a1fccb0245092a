#pragma once
// granmix validate's confirmation (docs/judging.md §2.1). A quantity of n correlated points, each outside z·σ by chance
// with probability p = P(|t_{R−1}| > z), fails a seed by chance with probability up to 1 − (1 − p)^n, and a suite of some
// fifty quantities then fails most seeds somewhere (14 of 20 held-out seeds: docs/validation.md, "Held-out calibration").
// So a scene whose quantity fails on its points' statistics is measured again, independently and more precisely: at the
// confirmation seed with `factor` times the replicas (σ halves at 4×, and with 8 → 32 replicas a point's chance falls
// from t₇'s 0.52% to t₃₁'s 0.037%). A quantity fails validate when it fails both times; one that passes its confirmation
// failed by chance ("chance"). A wrong theory or DSMC fails both: the confirmation's bound is tighter, never wider.
// Failures that no DSMC can change — no judged point, a computed model error above its cap — fail without one.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "model/scene.hpp"
#include "scene_compare.hpp"

namespace granmix::compare {

inline constexpr std::size_t default_confirmation_factor = 4;

// The seed of the confirmation of a run at `seed`: seed + 2^52 below 2^52, seed − 2^52 from there (within [0, 2^53],
// never a seed of the design or held-out ranges, docs/validation.md).
std::uint64_t confirmation_seed(std::uint64_t seed);

// Failed on its points' statistics: some judged point outside its bound, none unresolved.
bool needs_confirmation(const QuantityResult& q);
// The scenes with such a quantity.
std::vector<std::string> scenes_to_confirm(const std::vector<SceneOutcome>& scenes);

// The scene with `factor` times the replicas of both fidelities (particles per replica unchanged).
model::Scene with_more_replicas(model::Scene s, std::size_t factor);

struct Confirmation {
  std::uint64_t seed = 0;
  std::size_t factor = 0;
  std::vector<SceneOutcome> scenes;  // the confirmed scenes' outcomes at `seed`
  std::vector<std::string> errors;   // confirmations that could not run: their quantities stay failed
};

// A quantity's verdict: "pass" (every judged point within its bound), "chance" (failed, then passed its confirmation)
// or "FAIL"; confirmation null: no confirmation was run.
std::string verdict(const std::string& scene, const QuantityResult& q, const Confirmation* confirmation);
// The scene passes validate: every quantity "pass" or "chance" (a theory-only scene: its own pass).
bool passes(const SceneOutcome& o, const Confirmation* confirmation);
// The run passes validate: no scene error, and every scene passes (its exit code, summary.json's "pass").
bool passes(const std::vector<SceneOutcome>& scenes, const std::vector<std::string>& errors, const Confirmation* confirmation);

}  // namespace granmix::compare
