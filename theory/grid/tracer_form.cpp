#include "theory/grid/tracer_form.hpp"

#include <cmath>
#include <limits>

#include "theory/histories/msd.hpp"
#include "theory/numerics/scaled_time_motion.hpp"
#include "theory/histories/tamsd.hpp"
#include "theory/grid/tracer_relaxation.hpp"

namespace granmix::theory {

namespace {

// The settled tracer state: gas by Haff's law, intruder at θ times it, each species' memory one exponential.
class ClosedTracerForm final : public TracerForm {
 public:
  explicit ClosedTracerForm(const TracerLimit& t) : t_(t) {}
  std::array<double, 2> temperatures(double t) const override {
    const double haff = std::isfinite(t_.tau0) ? 1.0 / std::pow(1.0 + t / t_.tau0, 2) : 1.0;
    return {haff, t_.theta * haff};
  }
  double msd(std::size_t k, double t) const override { return msd_closed(D(k), tau_v(k), t_.tau0, t); }
  double tamsd(std::size_t k, double measurement_time, double lag) const override {
    return theory::tamsd(D(k), tau_v(k), t_.tau0, measurement_time, lag);
  }
  double D_ratio(double) const override { return t_.D_intruder / t_.D_gas; }
  double reduced_time(double t) const override { return std::isfinite(t_.tau0) ? t_.tau0 * std::log1p(t / t_.tau0) : t; }

 private:
  double D(std::size_t k) const { return k == 0 ? t_.D_gas : t_.D_intruder; }
  double tau_v(std::size_t k) const { return k == 0 ? t_.tau_v_gas : t_.tau_v_intruder; }
  TracerLimit t_;
};

// The intruder relaxing on the speed grid; both species' displacements along its steps.
class RelaxingTracerForm final : public TracerForm {
 public:
  RelaxingTracerForm(const CollisionRates& rates, const VelocityMemory& gas, double gas_zeta, double theta0, double t_end, RelaxationOptions opt)
      : r_(relax_intruder(rates, theta0, t_end, opt)), m2_(rates.mixture()[1].mass), gas_(gas_motion(gas, gas_zeta)), intruder_(intruder_motion()) {}
  std::array<double, 2> temperatures(double t) const override {
    const ScaledTimeMotion::Place p = gas_.locate(t);
    const double T1 = gas_.T1(p), w = p.sigma / r_.h[p.n];
    return {T1, T1 * ((1.0 - w) * r_.theta_start[p.n] + w * r_.theta_start[p.n + 1])};
  }
  // The intruder's from the l = 1 harmonic (cubic Hermite between the steps' ends: dM/ds = 2Q).
  double msd(std::size_t k, double t) const override {
    if (k == 0) return gas_.msd(t);
    const ScaledTimeMotion::Place p = gas_.locate(t);
    const double h = r_.h[p.n], x = p.sigma / h, M0 = r_.msd_start[p.n], M1 = r_.msd_start[p.n + 1];
    const double d0 = 2.0 * h * r_.q_start[p.n], d1 = 2.0 * h * r_.q_start[p.n + 1];
    return (2 * x * x * x - 3 * x * x + 1) * M0 + (x * x * x - 2 * x * x + x) * d0 + (-2 * x * x * x + 3 * x * x) * M1 + (x * x * x - x * x) * d1;
  }
  // The intruder's increments from later starts by its one mode (ν of its distribution at each step; 0.3% from the l = 1
  // harmonic's MSD on v2 Fig. 5).
  double tamsd(std::size_t k, double measurement_time, double lag) const override { return of(k).tamsd(measurement_time, lag); }
  double D_ratio(double t) const override {
    const std::size_t n = gas_.locate(t).n;
    double D_gas = 0.0;
    for (std::size_t j = 0; j < gas_modes_.size(); ++j) D_gas += (gas_modes_[j].weight[n] / gas_modes_[j].kappa[n]).real() / 3.0;
    return (r_.theta[n] / (m2_ * (r_.nu[n] - 0.5 * r_.zeta[n]))) / D_gas;
  }
  double reduced_time(double t) const override { return gas_.scaled_time(gas_.locate(t)); }

 private:
  // The gas: its settled memory's modes (velocity_memory.hpp, at its cooling rate gas_zeta), each rate shifted by
  // −(ζ − gas_zeta)/2 where the intruders' heating changes the gas's cooling rate ζ.
  ScaledTimeMotion gas_motion(const VelocityMemory& gas, double gas_zeta) {
    for (std::size_t j = 0; j < gas.weight.size(); ++j) {
      MotionMode m;
      for (std::size_t n = 0; n < r_.h.size(); ++n) m.weight.push_back(gas.weight[j]), m.kappa.push_back(gas.rate[j] - 0.5 * (r_.zeta[n] - gas_zeta));
      gas_modes_.push_back(std::move(m));
    }
    return ScaledTimeMotion(r_.h, r_.zeta, gas_modes_);
  }
  // The intruder: one mode, 3θ/m₂ decaying at κ = ν − ζ/2 (ν of its distribution and the mutual collisions).
  ScaledTimeMotion intruder_motion() const {
    MotionMode m;
    for (std::size_t n = 0; n < r_.h.size(); ++n) m.weight.push_back(3.0 * r_.theta[n] / m2_), m.kappa.push_back(r_.nu[n] - 0.5 * r_.zeta[n]);
    return ScaledTimeMotion(r_.h, r_.zeta, {m});
  }
  const ScaledTimeMotion& of(std::size_t k) const { return k == 0 ? gas_ : intruder_; }
  TracerRelaxation r_;
  double m2_;
  std::vector<MotionMode> gas_modes_;
  ScaledTimeMotion gas_, intruder_;
};

}  // namespace

std::unique_ptr<TracerForm> closed_tracer_form(const TracerLimit& settled) { return std::make_unique<ClosedTracerForm>(settled); }

std::unique_ptr<TracerForm> relaxing_tracer_form(const CollisionRates& rates, const VelocityMemory& gas, double gas_zeta, double theta0, double t_end,
                                                 RelaxationOptions opt) {
  return std::make_unique<RelaxingTracerForm>(rates, gas, gas_zeta, theta0, t_end, opt);
}

}  // namespace granmix::theory
