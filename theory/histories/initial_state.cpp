#include "theory/histories/initial_state.hpp"

#include <cmath>
#include <stdexcept>

#include "theory/numerics/bracketed_root.hpp"
#include "model/errors.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/histories/temperature_history.hpp"

namespace granmix::theory {

AgedState aged_state(double T_hot, const CollisionRates& rates, const TemperatureOptions& opt) {
  const std::size_t N = rates.size();
  const std::vector<double> hot(N, T_hot);
  std::vector<double> xi(N);
  rates.xi_all(hot.data(), xi.data());
  double xi_mean = 0.0;
  for (std::size_t k = 0; k < N; ++k) xi_mean += rates.mixture()[k].density * xi[k];
  xi_mean /= rates.mixture().total_density();
  if (!(xi_mean > 0.0)) throw InputError("initial state 'aged' needs a cooling gas (ε < 1)");
  // Haff estimate of the time to reach ⟨T⟩ = 1 from T_hot, with a wide margin for slow species.
  const double t_haff = 2.0 / xi_mean * (std::sqrt(T_hot) - 1.0);
  const TemperatureHistory h(rates, hot, 1e7 * t_haff, opt);  // covers the widest bracket below
  std::vector<double> T(N);
  auto excess = [&](double log_t) {
    h.temperatures(std::exp(log_t), T.data());
    return std::log(rates.mixture().mean_temperature(T));
  };
  // Root in ln t around the Haff estimate: ⟨T⟩ decreases monotonically.
  const double centre = std::log(t_haff);
  const double lt = centre + bracketed_root([&](double x) { return excess(centre + x); }, "aged start: ⟨T⟩(t) = 1",
                                            std::log(1e3))
                                 .x;
  h.temperatures(std::exp(lt), T.data());
  const double mean = rates.mixture().mean_temperature(T);
  for (double& v : T) v /= mean;  // remove the root's last rounding: ⟨T⟩ = 1 exactly
  std::vector<double> z(opt.cooling ? opt.cooling->state_size() : 0);
  if (!z.empty()) h.states(std::exp(lt), z.data());
  return {T, z};
}

std::vector<double> initial_temperatures(const model::InitialState& init, const CollisionRates& rates) {
  const std::size_t N = rates.size();
  switch (init.kind) {
    case model::InitialState::Kind::equal: return std::vector<double>(N, 1.0);
    case model::InitialState::Kind::hcs: return settled_temperatures(rates).T;
    case model::InitialState::Kind::aged: return aged_state(init.T_hot, rates, {}).T;
    case model::InitialState::Kind::explicit_list:
      if (init.values.size() != N) throw InputError("initial temperatures: one value per species needed");
      return init.values;
  }
  throw std::logic_error("unknown initial state");
}

double tracer_start_theta(const model::InitialState& init, const CollisionRates& rates) {
  if (rates.size() != 2) throw InputError("tracer limit: two species needed (the gas and the intruder)");
  const std::vector<double> T = initial_temperatures(init, rates);
  return T[1] / T[0];
}

}  // namespace granmix::theory
