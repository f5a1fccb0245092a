// The hcs-converged family (docs/levels.md, "hcs-converged"): the kinetic level with its HCS and settled
// distributions solved without the Sonine truncation, the four companions of its distributions' model error, and their
// declarations.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "theory/grid/converged_hcs.hpp"
#include "theory/levels/kinetic_level.hpp"
#include "theory/levels/level_catalogue.hpp"
#include "theory/levels/level_families.hpp"
#include "theory/numerics/shell_average.hpp"

namespace granmix::theory {

namespace {

// "kinetic-hcs-converged": the kinetic level whose homogeneous cooling state (γ, c_k, the settled T_k) is solved
// without the Sonine truncation of the species' own distributions (converged_hcs.hpp); everything in time is the kinetic
// level's. Why: the HCS Sonine series is asymptotic — over MG Figs. 4–5's 18 DSMC points (mean of three paper seeds)
// orders 2/3/4 swing by 0.3–0.7% at α ≤ 0.5 and the first Sonine is within 0.3% at 15 of them; the converged state is
// within 0.27% at all 18, and MG Fig. 2's c_k 10–12% below the first Sonine at α = 0.3, as DSMC (docs/levels.md,
// "The converged HCS"). Constant restitution only (a viscoelastic gas has no HCS).
// Its settled distributions Φ_k are the solved speed densities themselves, no Sonine form at all (MG Figs. 3, 7), solved
// with a finer collision rule and every partner through its full solved density (converged_distribution: why); their
// model error is computed per bin by four companions from that solve — "-knots" (knots 3/2 as far apart), "-rule" (the
// coarser rule), "-partners" (the partners' rests taken finer), "-domain" (the grid 9/7 as wide) — and the level's own
// elastic-limit error (elastic_bin_error).
class HcsConvergedLevel final : public TheoryLevel {
 public:
  explicit HcsConvergedLevel(DistributionVariant variant = DistributionVariant::solved) : variant_(variant) {}
  MsdMethod msd_method(const model::Scene& s) const override { return base_.msd_method(s); }
  void configure(TemperatureOptions& opt, const CollisionRates& rates) const override { base_.configure(opt, rates); }
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override { return base_.diffusion_at(rates, std::move(T)); }
  std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates, TemperatureOptions& opt) const override {
    return base_.initial_temperatures(init, rates, opt);
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override {
    return rates.law().is_viscoelastic() ? base_.settled_temperatures(rates) : hcs(rates).T;
  }
  // The companions' HCS is their distributions' state; the level's own the converged HCS (its 12-point rule and Sonine
  // partners, their truncation its computed model error; the distributions take panels and full partners).
  SonineHcs hcs(const CollisionRates& rates) const override {
    return variant_ == DistributionVariant::solved ? converged_hcs(rates).hcs : converged_distribution(rates, variant_).hcs;
  }
  SettledDistribution settled_distribution(const CollisionRates& rates) const override {
    SettledHcs s = converged_distribution(rates, variant_);
    SettledDistribution d{s.hcs, {}, {}};
    if (variant_ == DistributionVariant::solved) d.bin_error = elastic_bin_error(rates, s.hcs.lambda);
    d.phi = [density = std::move(s.density)](std::size_t k, double v) { return density[k].phi(v); };
    return d;
  }
  TracerLimit tracer(const CollisionRates& rates) const override { return base_.tracer(rates); }
  std::unique_ptr<TracerForm> tracer_form(const CollisionRates& rates, double theta0, double t_end) const override {
    return base_.tracer_form(rates, theta0, t_end);
  }

 private:
  // The grid's error where the answer is known: the same mixture elastic, whose settled Φ_k is the Maxwellian, solved
  // by the same grid; its relative error over the same bin in thermal widths (λ_k: the inelastic state's). Why: the
  // variants' changes (knots, rule) under-estimate the grid's pointwise error up to ~3× in places — the elastic MG
  // Fig. 3 mixture's bins of 0.05 err by 0.05–0.5% between one and two thermal widths where the variants move them by
  // 0.02–0.3% — so both parts enter the model error.
  static std::function<double(std::size_t, double, double)> elastic_bin_error(const CollisionRates& rates, std::vector<double> lambda) {
    const CollisionRates elastic(rates.mixture(), model::Restitution::constant(rates.size(), 1.0), rates.contact_values());
    return [e = converged_distribution(elastic, DistributionVariant::solved), lambda = std::move(lambda)](std::size_t k, double lo, double hi) {
      const double scale = std::sqrt(lambda[k] / e.hcs.lambda[k]);  // v* here ↦ the same thermal widths there
      const double grid = shell_average([&](double v) { return e.density[k].phi(v); }, scale * lo, scale * hi);
      const double exact = shell_average([&](double v) { return maxwellian_phi(e.hcs.lambda[k], v); }, scale * lo, scale * hi);
      return std::abs(grid / exact - 1.0);
    };
  }
  KineticLevel base_{kinetic_sonine_order};
  DistributionVariant variant_;
};

struct DistributionCompanion {
  DistributionVariant variant;
  const char* correction;  // also the companion level's suffix
  const char* changes;
};

}  // namespace

void declare_hcs_converged_levels(LevelCatalogue& c) {
  const std::string name = "kinetic-hcs-converged";
  const std::vector<DistributionCompanion> companions = {
      {DistributionVariant::sparser_knots, "knots", "the grid's knots 3/2 as far apart"},
      {DistributionVariant::coarser_rule, "rule", "the coarser collision rule"},
      {DistributionVariant::partners_finer, "partners", "the partners' rests taken finer"},
      {DistributionVariant::wider_domain, "domain", "the grid 9/7 as wide"},
  };
  LevelDescriptor d;
  d.name = name;
  d.family = "hcs-converged";
  d.summary = "the kinetic level with its HCS and settled distributions solved without the Sonine truncation (MG Figs. 2-5, 7)";
  d.parts = {"first Sonine, a2 relaxing", "D to Sonine order 4", "converged HCS (speed grid, no Sonine truncation)", "the kinetic level's",
             "the solved speed densities themselves"};
  d.applies = "constant restitution for its HCS and distributions (a viscoelastic gas has no HCS)";
  d.cost = "~0.3 s per HCS; its distributions with companions ~10 s (MG Fig. 3)";
  d.scene_may_choose = true;
  d.auto_step = 7, d.auto_max_species = 10;  // level = "auto": settled distributions, ~10 s with companions
  d.error_columns.push_back({"phi_error", "the grid error " + name + " computes for its settled distributions", {"phi", "G"}});
  d.error_columns.push_back({"delta_error", "the grid error " + name + " computes for its settled distributions", {"delta"}});
  d.companions.push_back({"paper", "paper", "the papers' closure", {}});
  for (const DistributionCompanion& k : companions)
    d.companions.push_back({k.correction, name + "-" + k.correction, k.changes, {}, false, true});
  d.construct = [] { return std::make_unique<HcsConvergedLevel>(); };
  c.add(d);
  for (const DistributionCompanion& k : companions) {
    LevelDescriptor v;
    v.name = name + "-" + k.correction;
    v.family = "hcs-converged";
    v.summary = std::string("kinetic-hcs-converged's distributions with ") + k.changes + " (a companion of its model error)";
    v.parts = d.parts;
    v.applies = d.applies;
    v.cost = d.cost;
    v.companions.push_back({"paper", "paper", "the papers' closure", {}});
    v.construct = [variant = k.variant] { return std::make_unique<HcsConvergedLevel>(variant); };
    c.add(std::move(v));
  }
}

}  // namespace granmix::theory
