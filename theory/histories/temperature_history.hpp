#pragma once
// Partial temperatures of an N-species mixture, dT_k/dt = −ξ_k T_k (v1 Eqs. 22–23), integrated
// with CVODE (BDF) in the unknowns ln T_k and a time variable that follows the collision clock:
//   cooling gas (mean cooling rate ξ̄ = Σ n_k T_k ξ_k / Σ n_k T_k > 0):  s = ln(1 + t/t_c), t_c = 2/ξ̄(0),
//     so Haff-like decay T ∝ t^(-2) is linear in s and t = 1e12 takes a few hundred steps;
//   no net cooling (ε = 1):  s = t/t_c with t_c the fastest relaxation time; a log clock would make
//     the equipartition mode ever stiffer (rate ν (t_c + t) in s) until rounding noise wins.
// Optional companions integrated with the same solver (only when asked for):
//   reduced time       τ_k(t) = ∫₀ᵗ √(T_k/T_k(0)) dt'          (v1 Eq. 17, Fig. 1 t_s)
//   diffusion integral I_k(t) = ∫₀ᵗ D_k dt'                     (v1 Eq. 21, long-time MSD = 6 I_k)
//   VACF ODE           d⟨R²⟩/dt = 2J,  dJ/dt = 3T_k/m_k − ν_k J  (docs/physics-beyond.md §2; J = ⟨Δr·v⟩), or
//                      more modes per species if the decay model has them (VelocityDecay::modes)
// The cooling rates ξ_k and the velocity decay rate ν_k are pluggable (cooling_model.hpp); by
// default ξ_k of v1 (A2) and ν_k = τ_v,k⁻¹ + ξ_k/2 (docs/physics.md §3: the tagged velocity decays at the
// momentum-relaxation rate, not at τ_v,k⁻¹). A cooling model may bring extra unknowns (the relaxing
// Sonine cumulants), integrated beside ln T_k and read back with state().
// The whole solution is kept as CVODE's own interpolating polynomials (Nordsieck data of every
// step), so any time up to t_end is available at solver accuracy.
#include <cmath>
#include <cstddef>
#include <exception>
#include <memory>
#include <vector>

#include <sundials/sundials_nvector.h>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/cooling_model.hpp"

namespace granmix::theory {

struct GalerkinPairTables;  // galerkin_decay.hpp

// Above this many unknowns (ln T_k, companions) the automatic solver switches from dense LU to GMRES.
inline constexpr std::size_t dense_unknowns_max = 256;

struct TemperatureOptions {
  double rtol = 1e-11;  // relative tolerance of CVODE (ln T also gets atol = rtol)
  bool reduced_time = false;
  bool diffusion_integral = false;
  bool vacf = false;
  enum class Solver { automatic, dense, gmres } solver = Solver::automatic;  // automatic: dense up to dense_unknowns_max
  // Earliest time at which the companions must be accurate (0: 1e-8 of the clock's time unit).
  // Their absolute tolerances are rtol times their size there; see temperature_history.cpp.
  double t_first = 0.0;
  // Closures (cooling_model.hpp); null: MaxwellClosures of the rates (the paper level).
  std::shared_ptr<const CoolingModel> cooling;
  std::shared_ptr<const VelocityDecay> decay;
  // The Galerkin pair tables the converged levels of one scene share (scene_theory.cpp run_theory; null: a level's own).
  // Read by the level's configure, which builds `decay` on them; the integration itself does not use it.
  std::shared_ptr<GalerkinPairTables> galerkin_tables;
};

struct SolverStats {
  long steps = 0, rhs_evals = 0, nonlinear_iterations = 0, error_test_failures = 0, linear_iterations = 0;
  double seconds = 0.0;
};

class TemperatureHistory {
 public:
  TemperatureHistory(const CollisionRates& rates, std::vector<double> T0, double t_end, TemperatureOptions opt = {});

  std::size_t species() const { return N_; }
  double t_end() const { return t_end_; }
  const std::vector<double>& initial() const { return T0_; }
  const SolverStats& stats() const { return stats_; }
  double rtol() const { return opt_.rtol; }
  const CollisionRates& rates() const { return rates_; }

  double temperature(double t, std::size_t k) const;
  void temperatures(double t, double* T) const;  // all species
  double reduced_time(double t, std::size_t k) const;
  double diffusion_integral(double t, std::size_t k) const;
  double msd_vacf(double t, std::size_t k) const;
  // Extra unknown j of the cooling model (e.g. the cumulant c_k of SonineCooling's relaxing mode).
  double state(double t, std::size_t j) const;
  void states(double t, double* z) const;  // all cooling_model().state_size() of them
  const CoolingModel& cooling_model() const { return *cooling_; }

  // The solver's time variable (see above) and its derivative.
  double to_s(double t) const { return log_clock_ ? std::log1p(t / t_c_) : t / t_c_; }
  double to_t(double s) const { return log_clock_ ? t_c_ * std::expm1(s) : t_c_ * s; }
  double dt_ds(double s) const { return log_clock_ ? t_c_ * std::exp(s) : t_c_; }

 private:
  struct Step {
    double s_end;
    int order;
    std::vector<double> taylor;  // (order+1) blocks of kept_ values, y^(j)(s_end)/j!
  };
  double component(double t, std::size_t index) const;
  const Step* locate(double t, double& x) const;  // the step holding t (null: before the first), x = s − its s_end
  double component_at(const Step* step, double x, std::size_t index) const;
  static int rhs(double s, N_Vector y, N_Vector dy, void* self);
  // correlation = false: only the unknowns before the velocity correlation's (ln T, z, τ, I).
  static int derivatives(TemperatureHistory& self, double s, const double* y, double* dy, bool correlation = true);
  static int jtimes(N_Vector v, N_Vector Jv, double s, N_Vector y, N_Vector fy, void* self, N_Vector tmp);
  int jacobian_times(const double* v, double* Jv, double s, const double* y, const double* fy, double* tmp);

  const CollisionRates& rates_;
  std::vector<double> T0_;
  double t_end_, t_c_;
  bool log_clock_ = true;
  TemperatureOptions opt_;
  std::size_t N_, n_, kept_ = 0;  // unknowns; the first kept_ of them are kept per step
  std::shared_ptr<const CoolingModel> cooling_;
  std::shared_ptr<const VelocityDecay> decay_;
  std::size_t z_at_ = 0, nz_ = 0, tau_at_ = 0, int_at_ = 0, r2_at_ = 0, j_at_ = 0;
  std::vector<Step> steps_;
  std::vector<double> y0_;
  SolverStats stats_;
  std::exception_ptr rhs_error_;
  void* cvode_mem_ = nullptr;       // for the error weights of jtimes's difference quotient
  N_Vector weights_ = nullptr;      // those weights (owned by the constructor's scope)
  std::vector<double> assembled_at_;  // ln T and z of the decay's last correlation_rates (empty: none yet)
  mutable std::vector<double> work_T_, work_a_, work_xi_, work_nu_, work_a2_, work_a3_;
};

}  // namespace granmix::theory
