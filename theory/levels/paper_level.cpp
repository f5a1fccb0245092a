// The paper level: the closure of Bodrova & Osinsky's papers (docs/levels.md, "paper"), and its declaration.
#include <string>
#include <vector>

#include "theory/histories/initial_state.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/levels/level_families.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/sonine/sonine_hcs.hpp"

namespace granmix::theory {

namespace {

// The papers' closure (Bodrova & Osinsky v1): Maxwellian rates, v1 Eq. (19) D.
class PaperLevel final : public TheoryLevel {
 public:
  MsdMethod msd_method(const model::Scene& s) const override { return parse_msd_method(s.theory.msd); }
  void configure(TemperatureOptions&, const CollisionRates&) const override {}
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    return theory::diffusion_at(rates, std::move(T));
  }
  std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates,
                                           TemperatureOptions&) const override {
    return theory::initial_temperatures(init, rates);
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override { return theory::settled_temperatures(rates).T; }
  SonineHcs hcs(const CollisionRates& rates) const override { return sonine_hcs(rates.mixture(), rates.law(), rates.contact_values()); }
  TracerLimit tracer(const CollisionRates& rates) const override { return tracer_limit(rates); }
};

}  // namespace

void declare_paper_levels(LevelCatalogue& c) {
  LevelDescriptor d;
  d.name = "paper";
  d.family = "paper";
  d.summary = "the papers' closure: Maxwellian cooling rates, the scene's MSD form, D_k = T_k tau_v,k/m_k (v1 Eq. 19)";
  d.parts = {"Maxwellian rates (v1 App. A)", "first-Sonine D (v1 Eq. 19); MSD by the scene's `msd` form (v1 Eq. 17 by default)",
             "first Sonine (MG App. A)", "Maxwellian theta, Haff gas, first-Sonine D", "first-Sonine Phi_k"};
  d.applies = "any mixture and restitution law; the papers' own theory, reported beside every other level as `paper rel`";
  d.cost = "milliseconds (v2 Fig. 6's 691 species: ~1 s)";
  d.scene_may_choose = true;
  d.reported_beside_others = true;
  d.auto_step = 1, d.auto_max_species = 100000;  // level = "auto": milliseconds per species (691 species: ~1 s)
  // The temperatures and HCS one Sonine order up (a2 and a3 relaxing): the size of the closure's next correction.
  d.companions.push_back({"cooling3", "kinetic-cooling3", "the temperatures and HCS at Sonine order 3", {}});
  d.construct = [] { return std::make_unique<PaperLevel>(); };
  c.add(std::move(d));
}

}  // namespace granmix::theory
