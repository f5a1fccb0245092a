#include "theory_level.hpp"

#include <stdexcept>

#include "settled_ratios.hpp"

namespace granmix::theory {

namespace {

// The papers' closure (Bodrova & Osinsky v1): Maxwellian rates, v1 Eq. (19) D.
class PaperLevel final : public TheoryLevel {
 public:
  const char* name() const override { return "paper"; }
  MsdMethod msd_method(const model::Scene& s) const override { return parse_msd_method(s.theory.msd); }
  void configure(TemperatureOptions&, const CollisionRates&) const override {}
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    return theory::diffusion_at(rates, std::move(T));
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override { return theory::settled_temperatures(rates).T; }
};

// The exact first-Sonine MSD: the VACF ODE (physics-beyond §2), transients included.
class KineticLevel final : public TheoryLevel {
 public:
  const char* name() const override { return "kinetic"; }
  MsdMethod msd_method(const model::Scene&) const override { return MsdMethod::vacf; }
  void configure(TemperatureOptions&, const CollisionRates&) const override {}
  SettledDiffusion diffusion_at(const CollisionRates& rates, std::vector<double> T) const override {
    return theory::diffusion_at(rates, std::move(T));
  }
  std::vector<double> settled_temperatures(const CollisionRates& rates) const override { return theory::settled_temperatures(rates).T; }
};

}  // namespace

std::unique_ptr<TheoryLevel> make_theory_level(const std::string& name) {
  if (name == "paper") return std::make_unique<PaperLevel>();
  if (name == "kinetic") return std::make_unique<KineticLevel>();
  throw std::invalid_argument("theory level '" + name + "' (allowed: paper, kinetic)");
}

}  // namespace granmix::theory
