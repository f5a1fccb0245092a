// The kinetic family's declarations (docs/levels.md, "kinetic"): the kinetic level and its variants, each a point of
// (D's Sonine order, the temperatures' Sonine order, shaped), named by KineticLevel::level_name.
#include "theory/levels/kinetic_level.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "theory/levels/level_catalogue.hpp"
#include "theory/levels/level_families.hpp"

namespace granmix::theory {

namespace {

struct KineticVariant {
  std::size_t order = kinetic_sonine_order;  // D_k's Sonine order (the VACF modes per species)
  int cooling_order = 2;                     // the temperatures' Sonine order: 2 (a2), 3 (a2, a3), 4 (a2 … a4)
  bool shaped = false;                       // the species' a2, a3 in the velocity modes too
  bool operator==(const KineticVariant&) const = default;
  std::string name() const { return KineticLevel::level_name(order, cooling_order, shaped); }
};

// A part changed: the companion of a variant (nullopt where the part does not change).
struct KineticCompanion {
  const char* correction;
  const char* changes;
  std::optional<KineticVariant> (*change)(KineticVariant);
  std::vector<std::string> quantities;
};

std::string sonine_suffix(std::size_t order) { return order == kinetic_sonine_order ? "D to Sonine order 4" : "D to Sonine order " + std::to_string(order); }

}  // namespace

void declare_kinetic_levels(LevelCatalogue& c) {
  // The levels a scene may choose first, then the companions and study levels (D at another Sonine order).
  std::vector<KineticVariant> variants = {{}, {kinetic_sonine_order, 3, false}, {kinetic_sonine_order, 3, true}, {kinetic_sonine_order, 4, false}};
  for (int cooling : {2, 3})
    for (std::size_t n = 1; n <= max_sonine_modes; ++n)
      if (n != kinetic_sonine_order) variants.push_back({n, cooling, false});
  const std::vector<KineticCompanion> companions = {
      {"sonine1", "D at first Sonine (its second-Sonine correction's size)",
       [](KineticVariant v) -> std::optional<KineticVariant> { return v.order == kinetic_sonine_order && !v.shaped ? std::optional(KineticVariant{1, v.cooling_order, false}) : std::nullopt; }, {}},
      {"kinetic", "the temperatures at first Sonine, the Maxwellian velocity modes",
       [](KineticVariant v) -> std::optional<KineticVariant> { return v.cooling_order != 2 ? std::optional(KineticVariant{v.order, 2, false}) : std::nullopt; }, {}},
      {"cooling3", "the temperatures and HCS at Sonine order 3",
       [](KineticVariant v) -> std::optional<KineticVariant> { return v.cooling_order == 2 ? std::optional(KineticVariant{v.order, 3, v.shaped}) : std::nullopt; }, {}},
      {"cooling4", "the temperatures at Sonine order 4 (a4 relaxing too)",
       [](KineticVariant v) -> std::optional<KineticVariant> { return v.cooling_order == 3 ? std::optional(KineticVariant{v.order, 4, v.shaped}) : std::nullopt; }, {"T", "gamma"}},
  };
  for (const KineticVariant& v : variants) {
    LevelDescriptor d;
    d.name = v.name();
    d.family = "kinetic";
    const std::string cooling = v.cooling_order == 2 ? "first Sonine (Garzo-Dufty), a2 relaxing" : v.cooling_order == 3 ? "Sonine order 3, a2 and a3 relaxing" : "Sonine order 4, a2 … a4 relaxing";
    d.summary = v.order == kinetic_sonine_order && v.cooling_order == 2 && !v.shaped
                    ? "first-Sonine temperatures with relaxing cumulants, the MSD by the VACF ODE with D to Sonine order 4"
                    : "the kinetic level with " + (v.cooling_order == 2 ? std::string() : "temperatures at " + cooling + ", ") +
                          (v.shaped ? "the species' a2, a3 in the velocity modes, " : "") + sonine_suffix(v.order);
    d.parts = {cooling + " (docs/physics-beyond.md §4)", sonine_suffix(v.order) + (v.shaped ? ", shaped modes" : "") + "; MSD by the VACF ODE (§2, §3)",
               v.cooling_order == 2 ? "first Sonine (MG App. A)" : "Sonine order 3", "first-Sonine theta (both a2), D to its order",
               v.cooling_order == 2 ? "first-Sonine Phi_k" : "Sonine order 3 Phi_k"};
    d.applies = "any restitution law; the Sonine closure up to 1000 species (Maxwellian above), order 3 up to 100";
    d.cost = v.cooling_order == 2 ? "tens of ms (691 species to t = 10: ~8 s)" : "~0.1 s for a few species (691 species: ~30 s)";
    d.scene_may_choose = v == KineticVariant{} || v == KineticVariant{kinetic_sonine_order, 3, false} || v == KineticVariant{kinetic_sonine_order, 3, true};
    // level = "auto": the first-Sonine level up to the Sonine closure's 1000 species, order 3 up to 100 (seconds each)
    if (v == KineticVariant{}) d.auto_step = 2, d.auto_max_species = 1000;
    if (v == KineticVariant{kinetic_sonine_order, 3, false}) d.auto_step = 3, d.auto_max_species = 100;
    if (v.order == kinetic_sonine_order && !v.shaped && v.cooling_order < 4)
      d.synonyms.push_back(KineticLevel::level_name(v.order, v.cooling_order, false) + "-sonine" + std::to_string(v.order));
    d.companions.push_back({"paper", "paper", "the papers' closure", {}});
    for (const KineticCompanion& k : companions)
      if (const std::optional<KineticVariant> w = k.change(v); w && std::find(variants.begin(), variants.end(), *w) != variants.end())
        d.companions.push_back({k.correction, w->name(), k.changes, k.quantities});
    d.construct = [v] { return std::make_unique<KineticLevel>(v.order, v.cooling_order, v.shaped); };
    c.add(std::move(d));
  }
}

}  // namespace granmix::theory
