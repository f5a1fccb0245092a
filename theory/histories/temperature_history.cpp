#include "theory/histories/temperature_history.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <cmath>
#include <stdexcept>
#include <string>

#include "model/cvode_session.hpp"
#include "model/errors.hpp"
#include "model/sundials_check.hpp"

namespace granmix::theory {

TemperatureHistory::TemperatureHistory(const CollisionRates& rates, std::vector<double> T0, double t_end,
                                       TemperatureOptions opt)
    : rates_(rates), T0_(std::move(T0)), t_end_(t_end), opt_(opt), N_(rates.size()) {
  if (T0_.size() != N_) throw std::invalid_argument("temperatures: one initial temperature per species needed");
  for (double T : T0_)
    if (!(T > 0.0) || !std::isfinite(T)) throw std::invalid_argument("temperatures: initial T_k must be positive");
  if (!(t_end > 0.0) || !std::isfinite(t_end)) throw std::invalid_argument("temperatures: end time must be positive");
  // Default closures: one MaxwellClosures object for both, so the VACF's τ_v⁻¹ comes from the
  // cooling rates' pair pass.
  const auto maxwell = std::make_shared<MaxwellClosures>(rates_, opt_.vacf && !opt_.cooling && !opt_.decay);
  cooling_ = opt_.cooling ? opt_.cooling : std::shared_ptr<const CoolingModel>(maxwell);
  decay_ = opt_.decay ? opt_.decay : std::shared_ptr<const VelocityDecay>(maxwell);
  n_ = N_;
  nz_ = cooling_->state_size();
  z_at_ = n_, n_ += nz_;
  if (opt_.reduced_time) tau_at_ = n_, n_ += N_;
  if (opt_.diffusion_integral) int_at_ = n_, n_ += N_;
  if (opt_.vacf) r2_at_ = n_, j_at_ = n_ + N_, n_ += (1 + decay_->modes()) * N_;
  kept_ = opt_.vacf ? j_at_ : n_;  // J = ⟨Δr·v⟩ and its modes are last and never read back: not kept
  work_T_.resize(N_);
  work_a_.resize(N_);
  work_xi_.resize(N_);
  work_nu_.resize(N_);
  work_a2_.resize(N_), work_a3_.resize(N_);

  // Clock (see the header): Haff time of the mean cooling rate, or the fastest relaxation time.
  std::vector<double> xi(N_), itau(N_), z0(nz_), z_atol(nz_), dz(nz_);
  cooling_->initial_state(T0_.data(), opt_.rtol, z0.data(), z_atol.data());
  cooling_->rates(T0_.data(), z0.data(), xi.data(), dz.data());
  rates_.inv_tau_v_all(T0_.data(), itau.data());
  double fastest = 0.0, loss = 0.0, energy = 0.0;
  for (std::size_t k = 0; k < N_; ++k) {
    fastest = std::max({fastest, std::abs(xi[k]), itau[k]});
    const double w = rates_.mixture()[k].density * T0_[k];
    loss += w * xi[k], energy += w;
  }
  const double xi_mean = loss / energy;
  log_clock_ = xi_mean > 1e-12 * fastest;  // below: energy is conserved to rounding (ε = 1)
  t_c_ = log_clock_ ? 2.0 / xi_mean : 1.0 / fastest;

  const auto t0 = std::chrono::steady_clock::now();
  // Unpreconditioned GMRES fails on stiff mixtures (masses 1e-3–1e3, ε = 1, 23 and 26 species with
  // the VACF MSD: CV_CONV_FAILURE before t = 1e9, property tests); dense LU solves them at the same
  // cost up to a few hundred unknowns (160 random mixtures of 1–50 species: 6.1 s against 5.8 s).
  const bool gmres = opt_.solver == TemperatureOptions::Solver::gmres ||
                     (opt_.solver == TemperatureOptions::Solver::automatic && n_ > dense_unknowns_max);
  model::CvodeSession cv(n_, rhs, this, gmres ? model::LinearSolver::gmres : model::LinearSolver::dense);
  double* y = cv.data();
  // Absolute tolerances. ln T: rtol (an absolute error in ln T is a relative error in T). The
  // companions start at 0 and grow like t or t²: their atol is rtol times their size at t_first,
  // τ ~ t, I ~ D(0) t, ⟨R²⟩ ~ 3T t²/m, J ~ 3T t/m. Much smaller values (e.g. 1e-60) make
  // CVODE start with a step of 1e-37 and grow it tenfold per step for ~50 steps, where the BDF
  // error estimate fails and ln T ends up 1e-4 off at rtol 1e-10.
  const double t1 = opt_.t_first > 0.0 ? opt_.t_first : 1e-8 * t_c_;
  std::vector<double> atol(n_);
  for (std::size_t k = 0; k < N_; ++k) {
    y[k] = std::log(T0_[k]), atol[k] = opt_.rtol;
    const double v = 3.0 * T0_[k] / rates_.mixture()[k].mass;  // ⟨v_k²⟩(0)
    if (opt_.reduced_time) atol[tau_at_ + k] = opt_.rtol * t1;
    if (opt_.diffusion_integral) atol[int_at_ + k] = opt_.rtol * t1 * rates_.diffusion(k, T0_.data());
    if (opt_.vacf) {
      atol[r2_at_ + k] = opt_.rtol * v * t1 * t1;
      for (std::size_t j = 0; j < decay_->modes(); ++j) atol[j_at_ + j * N_ + k] = opt_.rtol * v * t1;  // modes ~ J
    }
  }
  for (std::size_t j = 0; j < nz_; ++j) y[z_at_ + j] = z0[j], atol[z_at_ + j] = z_atol[j];
  y0_.assign(y, y + n_);
  cv.init(0.0, opt_.rtol, atol.data());
  // GMRES's products J·v: see jacobian_times.
  const bool own_jtimes = gmres && opt_.vacf && decay_->offers_correlation_jacobian();
  if (own_jtimes) {
    model::check_cvode(CVodeSetJacTimes(cv.mem(), nullptr, jtimes), "CVodeSetJacTimes");
    cvode_mem_ = cv.mem();
    weights_ = model::check_alloc(N_VClone(cv.y()), "N_VClone");
  }
  const double s_end = to_s(t_end_);
  model::check_cvode(CVodeSetStopTime(cv.mem(), s_end), "CVodeSetStopTime");
  model::check_cvode(CVodeSetMaxNumSteps(cv.mem(), 100000), "CVodeSetMaxNumSteps");

  std::vector<double> dky(n_);
  N_Vector dky_v = model::check_alloc(N_VMake_Serial(static_cast<sunindextype>(n_), dky.data(), cv.context()),
                                      "N_VMake_Serial");
  double s = 0.0;
  try {
    while (s < s_end) {
      const int flag = CVode(cv.mem(), s_end, cv.y(), &s, CV_ONE_STEP);
      if (rhs_error_) std::rethrow_exception(rhs_error_);
      model::check_cvode(flag, "CVode", "temperature ODE at t = " + std::to_string(to_t(s)));
      int q = 0;
      model::check_cvode(CVodeGetLastOrder(cv.mem(), &q), "CVodeGetLastOrder");
      // One block per step (a single growing array would be copied on every reallocation: 10% of the
      // time at 500 species with the VACF MSD), of the kept components only.
      Step st{s, q, std::vector<double>(std::size_t(q + 1) * kept_)};
      double factorial = 1.0;
      for (int j = 0; j <= q; ++j) {
        model::check_cvode(CVodeGetDky(cv.mem(), s, j, dky_v), "CVodeGetDky");
        if (j > 0) factorial *= j;
        for (std::size_t c = 0; c < kept_; ++c) st.taylor[j * kept_ + c] = dky[c] / factorial;
      }
      steps_.push_back(std::move(st));
    }
  } catch (...) {
    N_VDestroy(dky_v);
    if (weights_) N_VDestroy(weights_), weights_ = nullptr;
    throw;
  }
  N_VDestroy(dky_v);
  if (weights_) N_VDestroy(weights_), weights_ = nullptr;
  cvode_mem_ = nullptr;
  long v = 0;
  model::check_cvode(CVodeGetNumSteps(cv.mem(), &v), "CVodeGetNumSteps");
  stats_.steps = v;
  model::check_cvode(CVodeGetNumRhsEvals(cv.mem(), &v), "CVodeGetNumRhsEvals");
  stats_.rhs_evals = v;
  model::check_cvode(CVodeGetNumNonlinSolvIters(cv.mem(), &v), "CVodeGetNumNonlinSolvIters");
  stats_.nonlinear_iterations = v;
  model::check_cvode(CVodeGetNumErrTestFails(cv.mem(), &v), "CVodeGetNumErrTestFails");
  stats_.error_test_failures = v;
  model::check_cvode(CVodeGetNumLinIters(cv.mem(), &v), "CVodeGetNumLinIters");
  stats_.linear_iterations = v;
  stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int TemperatureHistory::rhs(double s, N_Vector yv, N_Vector dyv, void* self_ptr) {
  auto& self = *static_cast<TemperatureHistory*>(self_ptr);
  try {
    return derivatives(self, s, N_VGetArrayPointer(yv), N_VGetArrayPointer(dyv));
  } catch (...) {  // e.g. a singular Sonine system: rethrown by the constructor, never across CVODE's C frames
    self.rhs_error_ = std::current_exception();
    return -1;
  }
}

int TemperatureHistory::jtimes(N_Vector v, N_Vector Jv, double s, N_Vector y, N_Vector fy, void* self_ptr, N_Vector tmp) {
  auto& self = *static_cast<TemperatureHistory*>(self_ptr);
  try {
    return self.jacobian_times(N_VGetArrayPointer(v), N_VGetArrayPointer(Jv), s, N_VGetArrayPointer(y), N_VGetArrayPointer(fy),
                               N_VGetArrayPointer(tmp));
  } catch (...) {
    self.rhs_error_ = std::current_exception();
    return -1;
  }
}

// GMRES's J·v where the velocity correlation's rates are affine in its unknowns (GalerkinDecay): its block exactly,
// from the operators the last right-hand side assembled (in CVODE's Newton iteration the right-hand side at y comes
// before the products at y; checked, and assembled again if not), dR²/ds = 2J exactly, and the rest (ln T, z, τ, I)
// as CVODE's own difference quotient (perturbation 1/‖v‖ in its weighted norm) of the right-hand side without the
// correlation: no collision integral of the memory. Left out: how the memory's rates move with ln T and z. The
// unknowns before the correlation do not depend on it, so the Jacobian is block lower-triangular and this keeps its
// diagonal blocks exact; the Newton iteration converges on the true right-hand side (its convergence test), the
// left-out block costs it iterations at most. v1 Fig. 8's judged level: 1899 right-hand sides, against 1885 right-hand
// sides + 1475 difference quotients without it (docs/performance.md).
int TemperatureHistory::jacobian_times(const double* v, double* Jv, double s, const double* y, const double* fy, double* tmp) {
  const std::size_t state = z_at_ + nz_;
  if (assembled_at_.size() != state || !std::equal(y, y + state, assembled_at_.begin())) {
    const int flag = derivatives(*this, s, y, tmp);
    if (flag != 0) return flag;
  }
  model::check_cvode(CVodeGetErrWeights(cvode_mem_, weights_), "CVodeGetErrWeights");
  const double* w = N_VGetArrayPointer(weights_);
  double norm = 0.0;
  for (std::size_t c = 0; c < n_; ++c) norm += (v[c] * w[c]) * (v[c] * w[c]);
  norm = std::sqrt(norm / double(n_));
  const double dt_ds = this->dt_ds(s);
  if (norm > 0.0) {
    const double sigma = 1.0 / norm;
    for (std::size_t c = 0; c < r2_at_; ++c) tmp[c] = y[c] + sigma * v[c];
    const int flag = derivatives(*this, s, tmp, Jv, false);
    if (flag != 0) return flag;
    for (std::size_t c = 0; c < r2_at_; ++c) Jv[c] = (Jv[c] - fy[c]) / sigma;
  } else {
    std::fill(Jv, Jv + r2_at_, 0.0);
  }
  for (std::size_t k = 0; k < N_; ++k) Jv[r2_at_ + k] = 2.0 * v[j_at_ + k] * dt_ds;
  decay_->correlation_jacobian_times(v + j_at_, Jv + j_at_);
  for (std::size_t j = 0; j < decay_->modes() * N_; ++j) Jv[j_at_ + j] *= dt_ds;
  return 0;
}

int TemperatureHistory::derivatives(TemperatureHistory& self, double s, const double* y, double* dy, bool correlation) {
  const std::size_t N = self.N_;
  const double dt_ds = self.dt_ds(s);
  double* T = self.work_T_.data();
  for (std::size_t k = 0; k < N; ++k) T[k] = std::exp(y[k]);
  for (std::size_t k = 0; k < N; ++k)
    if (!std::isfinite(T[k]) || T[k] <= 0.0) return 1;  // recoverable: CVODE retries with a smaller step
  double* xi = self.work_xi_.data();
  self.cooling_->rates(T, y + self.z_at_, xi, dy + self.z_at_);
  for (std::size_t k = 0; k < N; ++k) dy[k] = -xi[k] * dt_ds;  // d ln T_k/ds = −ξ_k dt/ds (v1 Eq. 22)
  for (std::size_t j = 0; j < self.nz_; ++j) dy[self.z_at_ + j] *= dt_ds;
  if (self.opt_.reduced_time)
    for (std::size_t k = 0; k < N; ++k) dy[self.tau_at_ + k] = std::sqrt(T[k] / self.T0_[k]) * dt_ds;
  if (self.opt_.diffusion_integral) {
    double* itau = self.work_a_.data();
    self.rates_.inv_tau_v_all(T, itau);
    for (std::size_t k = 0; k < N; ++k)
      dy[self.int_at_ + k] = T[k] / (itau[k] * self.rates_.mixture()[k].mass) * dt_ds;  // D_k, v1 Eq. (19)
  }
  if (self.opt_.vacf && correlation) {
    // A tagged velocity decays at ν_k (default τ_v⁻¹ + ξ_k/2, docs/physics.md §3: (A1) is that rate minus
    // ξ/2); with it this ODE reproduces Eq. (17) exactly when τ̂ is constant. The decay model may bring
    // more modes (the kinetic level's second Sonine mode).
    // The cooling closure's distribution shape (a₂, a₃; null when Maxwellian) for the decay's source and partners.
    double *a2 = self.work_a2_.data(), *a3 = self.work_a3_.data();
    const double* z = y + self.z_at_;
    const bool shaped = self.decay_->uses_sonine_coefficients() && self.cooling_->cumulants(T, z, a2);
    if (shaped)
      for (std::size_t k = 0; k < N; ++k) a2[k] *= 0.5;
    const bool third = shaped && self.cooling_->third_sonine(z, a3);
    self.decay_->correlation_rates(self.rates_, T, xi, y + self.j_at_, dy + self.j_at_, self.work_nu_.data(), shaped ? a2 : nullptr,
                                   third ? a3 : nullptr);
    for (std::size_t k = 0; k < N; ++k) dy[self.r2_at_ + k] = 2.0 * y[self.j_at_ + k] * dt_ds;
    for (std::size_t j = 0; j < self.decay_->modes() * N; ++j) dy[self.j_at_ + j] *= dt_ds;
    if (self.cvode_mem_) self.assembled_at_.assign(y, y + self.z_at_ + self.nz_);
  }
  return 0;
}

const TemperatureHistory::Step* TemperatureHistory::locate(double t, double& x) const {
  if (!(t >= 0.0) || t > t_end_ * (1.0 + 1e-12))
    throw std::out_of_range("temperature history: t = " + std::to_string(t) + " outside [0, " +
                            std::to_string(t_end_) + "]");
  const double s = to_s(t);
  if (s <= 0.0 || steps_.empty()) return nullptr;
  auto it = std::lower_bound(steps_.begin(), steps_.end(), s, [](const Step& st, double v) { return st.s_end < v; });
  if (it == steps_.end()) --it;
  x = s - it->s_end;  // <= 0, within the step
  return &*it;
}

double TemperatureHistory::component_at(const Step* st, double x, std::size_t c) const {
  if (!st) return y0_[c];
  double v = 0.0;
  for (int j = st->order; j >= 0; --j) v = v * x + st->taylor[j * kept_ + c];
  return v;
}

double TemperatureHistory::component(double t, std::size_t c) const {
  double x = 0.0;
  const Step* st = locate(t, x);
  return component_at(st, x, c);
}

double TemperatureHistory::temperature(double t, std::size_t k) const { return std::exp(component(t, k)); }

void TemperatureHistory::temperatures(double t, double* T) const {
  // The step found once for all species (Eq. 17's quadrature asks for all N at each node: per species, the search and
  // the clock's log1p would be half of a 500-species MSD's time).
  double x = 0.0;
  const Step* st = locate(t, x);
  for (std::size_t k = 0; k < N_; ++k) T[k] = std::exp(component_at(st, x, k));
}

double TemperatureHistory::reduced_time(double t, std::size_t k) const {
  if (!opt_.reduced_time) throw std::logic_error("temperature history: reduced time was not integrated");
  return component(t, tau_at_ + k);
}

double TemperatureHistory::diffusion_integral(double t, std::size_t k) const {
  if (!opt_.diffusion_integral) throw std::logic_error("temperature history: ∫D dt was not integrated");
  return component(t, int_at_ + k);
}

double TemperatureHistory::msd_vacf(double t, std::size_t k) const {
  if (!opt_.vacf) throw std::logic_error("temperature history: the VACF ODE was not integrated");
  return component(t, r2_at_ + k);
}

double TemperatureHistory::state(double t, std::size_t j) const {
  if (j >= nz_) throw std::out_of_range("temperature history: the cooling model has " + std::to_string(nz_) + " extra unknowns");
  return component(t, z_at_ + j);
}

void TemperatureHistory::states(double t, double* z) const {
  double x = 0.0;
  const Step* st = locate(t, x);
  for (std::size_t j = 0; j < nz_; ++j) z[j] = component_at(st, x, z_at_ + j);
}

}  // namespace granmix::theory
