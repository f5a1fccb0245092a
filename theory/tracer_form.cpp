#include "tracer_form.hpp"

#include <cmath>
#include <limits>

#include "msd.hpp"
#include "scaled_time_motion.hpp"
#include "tamsd.hpp"
#include "tracer_relaxation.hpp"

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
  RelaxingTracerForm(const CollisionRates& rates, const TracerLimit& settled, double theta0, double t_end)
      : r_(relax_intruder(rates, theta0, t_end)), gas_(motion(rates, settled, 0)), intruder_(motion(rates, settled, 1)) {}
  std::array<double, 2> temperatures(double t) const override {
    const ScaledTimeMotion::Place p = gas_.locate(t);
    const double T1 = gas_.T1(p), w = p.sigma / r_.h[p.n];
    return {T1, T1 * ((1.0 - w) * r_.theta_start[p.n] + w * r_.theta_start[p.n + 1])};
  }
  // The intruder's from the l = 1 harmonic (cubic Hermite between the steps' ends: dM/ds = 2Q); the gas's one exponential.
  double msd(std::size_t k, double t) const override {
    if (k == 0) return gas_.msd(t);
    const ScaledTimeMotion::Place p = gas_.locate(t);
    const double h = r_.h[p.n], x = p.sigma / h, M0 = r_.msd_start[p.n], M1 = r_.msd_start[p.n + 1];
    const double d0 = 2.0 * h * r_.q_start[p.n], d1 = 2.0 * h * r_.q_start[p.n + 1];
    return (2 * x * x * x - 3 * x * x + 1) * M0 + (x * x * x - 2 * x * x + x) * d0 + (-2 * x * x * x + 3 * x * x) * M1 + (x * x * x - x * x) * d1;
  }
  double tamsd(std::size_t k, double measurement_time, double lag) const override { return of(k).tamsd(measurement_time, lag); }
  double D_ratio(double t) const override {
    const std::size_t n = gas_.locate(t).n;
    return (v_intruder_[n] / kappa_intruder_[n]) / (v_gas_[n] / kappa_gas_[n]);
  }
  double reduced_time(double t) const override { return gas_.scaled_time(gas_.locate(t)); }

 private:
  // Per step: the scaled velocity's mean square 3T_k/(m_k T₁) and its decay κ_k = ν_k − ζ/2. The gas: its kinetic
  // memory (τ_v,gas⁻¹ = ν₁ − ζ₁/2, D to Sonine order 4) with ζ = ζ₁ + ξ₁₂ the heated cooling rate; the intruder: ν̄ of
  // its distribution at that step (tracer_speed_grid.hpp).
  ScaledTimeMotion motion(const CollisionRates& rates, const TracerLimit& settled, std::size_t k) {
    const std::size_t N = r_.h.size();
    std::vector<double>& v = k == 0 ? v_gas_ : v_intruder_;
    std::vector<double>& kappa = k == 0 ? kappa_gas_ : kappa_intruder_;
    const double m = rates.mixture()[k].mass, zeta1 = 2.0 / settled.tau0;
    for (std::size_t n = 0; n < N; ++n) {
      v.push_back(3.0 * (k == 0 ? 1.0 : r_.theta[n]) / m);
      kappa.push_back(k == 0 ? 1.0 / settled.tau_v_gas - 0.5 * (r_.zeta[n] - zeta1) : r_.nu[n] - 0.5 * r_.zeta[n]);
    }
    return ScaledTimeMotion(r_.h, r_.zeta, v, kappa);
  }
  const ScaledTimeMotion& of(std::size_t k) const { return k == 0 ? gas_ : intruder_; }
  TracerRelaxation r_;
  std::vector<double> v_gas_, kappa_gas_, v_intruder_, kappa_intruder_;
  ScaledTimeMotion gas_, intruder_;
};

}  // namespace

std::unique_ptr<TracerForm> closed_tracer_form(const TracerLimit& settled) { return std::make_unique<ClosedTracerForm>(settled); }

std::unique_ptr<TracerForm> relaxing_tracer_form(const CollisionRates& rates, const TracerLimit& settled, double theta0, double t_end) {
  return std::make_unique<RelaxingTracerForm>(rates, settled, theta0, t_end);
}

}  // namespace granmix::theory
