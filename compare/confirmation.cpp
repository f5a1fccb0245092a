#include "confirmation.hpp"

#include <algorithm>

namespace granmix::compare {

std::uint64_t confirmation_seed(std::uint64_t seed) {
  constexpr std::uint64_t half = 1ULL << 52;
  return seed < half ? seed + half : seed - half;
}

bool needs_confirmation(const QuantityResult& q) { return q.judged > 0 && q.failed > 0 && q.unresolved == 0; }

std::vector<std::string> scenes_to_confirm(const std::vector<SceneOutcome>& scenes) {
  std::vector<std::string> out;
  for (const SceneOutcome& o : scenes)
    if (std::any_of(o.quantities.begin(), o.quantities.end(), needs_confirmation)) out.push_back(o.scene);
  return out;
}

model::Scene with_more_replicas(model::Scene s, std::size_t factor) {
  s.dsmc.quick.replicas *= factor;
  s.dsmc.paper.replicas *= factor;
  return s;
}

std::string verdict(const std::string& scene, const QuantityResult& q, const Confirmation* confirmation) {
  if (q.pass()) return "pass";
  if (!confirmation || !needs_confirmation(q)) return "FAIL";
  for (const SceneOutcome& o : confirmation->scenes)
    if (o.scene == scene)
      for (const QuantityResult& c : o.quantities)
        if (label(c.spec) == label(q.spec)) return c.pass() ? "chance" : "FAIL";
  return "FAIL";  // its confirmation could not run
}

bool passes(const SceneOutcome& o, const Confirmation* confirmation) {
  if (o.quantities.empty()) return o.pass;
  return std::all_of(o.quantities.begin(), o.quantities.end(),
                     [&](const QuantityResult& q) { return verdict(o.scene, q, confirmation) != "FAIL"; });
}

bool passes(const std::vector<SceneOutcome>& scenes, const std::vector<std::string>& errors, const Confirmation* confirmation) {
  return errors.empty() && std::all_of(scenes.begin(), scenes.end(), [&](const SceneOutcome& o) { return passes(o, confirmation); });
}

}  // namespace granmix::compare
