#include "theory/levels/theory_level.hpp"

#include <stdexcept>
#include <string>

#include "theory/levels/level_catalogue.hpp"

namespace granmix::theory {

const char* TheoryLevel::name() const { return descriptor_->name.c_str(); }

std::unique_ptr<TracerForm> TheoryLevel::tracer_form(const CollisionRates& rates, double, double) const { return closed_tracer_form(tracer(rates)); }

TheoryLevel::SettledDistribution TheoryLevel::settled_distribution(const CollisionRates& rates) const {
  SettledDistribution d{hcs(rates), {}, {}};
  d.phi = [h = d.hcs](std::size_t k, double v) { return h.phi(k, v); };
  return d;
}

std::vector<double> TheoryLevel::d_ratio_error(const CollisionRates&) const {
  throw std::logic_error(std::string("level ") + name() + " computes no model error of its D ratios");
}

}  // namespace granmix::theory
