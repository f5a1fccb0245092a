#pragma once
// What a theory level says about the tracer limit in time (scene `tracer = true`, docs/physics.md §4): species 0 the gas,
// 1 the intruder (n₂ → 0), T₁(0) = 1.
//   closed_tracer_form     the intruder at the level's own θ (TheoryLevel::tracer), θ and the memories settled from the
//                          start: every curve in closed form (msd.hpp, tamsd.hpp); the paper and kinetic levels.
//   relaxing_tracer_form   the intruder's temperature and velocity memory relaxing from a Maxwellian start at θ₀ (the
//                          scene's start, DSMC's too: initial_state.hpp's tracer_start_theta) on the
//                          speed grid (tracer_relaxation.hpp), the gas cooling with the intruders' heating, its MSD
//                          from the l = 1 harmonic there; the gas's settled multi-mode memory; both species' increments
//                          by the Q-form along those steps (scaled_time_motion.hpp); the kinetic-converged levels.
#include <array>
#include <memory>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/tracer_limit.hpp"
#include "theory/grid/tracer_relaxation.hpp"
#include "theory/rates/velocity_memory.hpp"

namespace granmix::theory {

class TracerForm {
 public:
  virtual ~TracerForm() = default;
  virtual std::array<double, 2> temperatures(double t) const = 0;
  virtual double msd(std::size_t k, double t) const = 0;
  virtual double tamsd(std::size_t k, double measurement_time, double lag) const = 0;
  virtual double D_ratio(double t) const = 0;  // D₂/D₁ at t
  virtual double reduced_time(double t) const = 0;  // the gas's ∫√T₁ dt
};

std::unique_ptr<TracerForm> closed_tracer_form(const TracerLimit& settled);
// gas: the gas's settled velocity memory alone (its self-diffusion; the level's), at the gas's cooling rate gas_zeta
// (T₁ = 1); theta0 the intruder's start; t_end the last time any curve asks for (a TAMSD's measurement time).
std::unique_ptr<TracerForm> relaxing_tracer_form(const CollisionRates& rates, const VelocityMemory& gas, double gas_zeta, double theta0, double t_end,
                                                 RelaxationOptions opt = {});

}  // namespace granmix::theory
