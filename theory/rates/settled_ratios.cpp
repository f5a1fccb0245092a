#include "theory/rates/settled_ratios.hpp"

#include <cvode/cvode.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "theory/numerics/bracketed_root.hpp"
#include "model/cvode_session.hpp"
#include "model/errors.hpp"
#include "model/sundials_check.hpp"

namespace granmix::theory {

namespace {

// Temperatures from log ratios x_k = ln(T_k/T_1) (x_1 = 0), normalised to ⟨T⟩ = 1.
std::vector<double> from_log_ratios(const model::Mixture& mix, const double* x) {
  std::vector<double> T(mix.size());
  for (std::size_t k = 0; k < T.size(); ++k) T[k] = std::exp(x[k]);
  const double mean = mix.mean_temperature(T);
  for (double& v : T) v /= mean;
  return T;
}

// Rate scale for relative residuals: the fastest cooling or velocity relaxation (ξ = 0 at ε = 1).
double rate_scale(const CollisionRates& r, const std::vector<double>& T) {
  std::vector<double> xi(T.size()), it(T.size());
  r.xi_all(T.data(), xi.data());
  r.inv_tau_v_all(T.data(), it.data());
  double s = 0.0;
  for (std::size_t k = 0; k < T.size(); ++k) s = std::max({s, std::abs(xi[k]), it[k]});
  return s;
}

// Residuals F_k = (ξ_k − ξ_1)/scale, k = 2..N, at log ratios x.
Eigen::VectorXd residual(const CollisionRates& r, const Eigen::VectorXd& x_tail, double scale) {
  const std::size_t N = r.size();
  std::vector<double> x(N, 0.0);
  for (std::size_t k = 1; k < N; ++k) x[k] = x_tail[k - 1];
  const std::vector<double> T = from_log_ratios(r.mixture(), x.data());
  std::vector<double> xi(N);
  r.xi_all(T.data(), xi.data());
  Eigen::VectorXd F(N - 1);
  for (std::size_t k = 1; k < N; ++k) F[k - 1] = (xi[k] - xi[0]) / scale;
  return F;
}

SettledState binary_bracket(const CollisionRates& r) {
  const double x0[2] = {0.0, 0.0};
  const double scale = rate_scale(r, from_log_ratios(r.mixture(), x0));
  auto f = [&](double x) {
    Eigen::VectorXd v(1);
    v[0] = x;
    return residual(r, v, scale)[0];
  };
  const Root root = bracketed_root(f, "settled temperature ratio: ξ_2 = ξ_1 in ln(T_2/T_1)");
  SettledState out;
  const double x[2] = {0.0, root.x};
  out.T = from_log_ratios(r.mixture(), x);
  out.residual = std::abs(f(root.x));
  out.iterations = root.iterations;
  return out;
}

// Ratio dynamics at fixed ⟨T⟩: d ln T_k/dt = −(ξ_k − ξ̄), ξ̄ = Σ n_k T_k ξ_k / Σ n_k T_k keeps ⟨T⟩.
struct Relaxation {
  const CollisionRates* r;
  std::vector<double> T, xi;
  static int rhs(double, N_Vector yv, N_Vector dyv, void* p) {
    auto& self = *static_cast<Relaxation*>(p);
    const double* y = N_VGetArrayPointer(yv);
    double* dy = N_VGetArrayPointer(dyv);
    const auto& mix = self.r->mixture();
    const std::size_t N = mix.size();
    for (std::size_t k = 0; k < N; ++k) self.T[k] = std::exp(y[k]);
    self.r->xi_all(self.T.data(), self.xi.data());
    double num = 0.0, den = 0.0;
    for (std::size_t k = 0; k < N; ++k) num += mix[k].density * self.T[k] * self.xi[k], den += mix[k].density * self.T[k];
    for (std::size_t k = 0; k < N; ++k) dy[k] = -(self.xi[k] - num / den);
    return 0;
  }
};

std::vector<double> relax(const CollisionRates& r, double scale) {
  const std::size_t N = r.size();
  Relaxation rel{&r, std::vector<double>(N, 1.0), std::vector<double>(N)};
  model::CvodeSession cv(N, Relaxation::rhs, &rel, N > 64 ? model::LinearSolver::gmres : model::LinearSolver::dense);
  std::vector<double> atol(N, 1e-10);
  cv.init(0.0, 1e-8, atol.data());
  model::check_cvode(CVodeSetMaxNumSteps(cv.mem(), 50000), "CVodeSetMaxNumSteps");
  double t = 0.0;
  // Stop at a 1e-8 relative residual: Newton finishes from there in a few steps.
  for (double tout = 10.0 / scale; tout < 1e12 / scale; tout *= 2.0) {
    model::check_cvode(CVode(cv.mem(), tout, cv.y(), &t, CV_NORMAL), "CVode", "relaxation to the settled ratios");
    for (std::size_t k = 0; k < N; ++k) rel.T[k] = std::exp(cv.data()[k]);
    r.xi_all(rel.T.data(), rel.xi.data());
    double worst = 0.0;
    for (std::size_t k = 1; k < N; ++k) worst = std::max(worst, std::abs(rel.xi[k] - rel.xi[0]) / scale);
    if (worst < 1e-8) break;
  }
  std::vector<double> x(N);
  for (std::size_t k = 0; k < N; ++k) x[k] = cv.data()[k] - cv.data()[0];
  return x;
}

SettledState relax_and_polish(const CollisionRates& r) {
  const std::size_t N = r.size();
  const std::vector<double> equal(N, 1.0);
  const double scale = rate_scale(r, equal);
  const std::vector<double> x_relaxed = relax(r, scale);
  Eigen::VectorXd x(N - 1);
  for (std::size_t k = 1; k < N; ++k) x[k - 1] = x_relaxed[k];
  Eigen::VectorXd F = residual(r, x, scale);
  SettledState out;
  // Damped Newton with a forward-difference Jacobian; stop when the residual no longer drops.
  for (int it = 0; it < 50 && F.lpNorm<Eigen::Infinity>() > 1e-15; ++it) {
    out.iterations = it + 1;
    Eigen::MatrixXd J(N - 1, N - 1);
    for (std::size_t j = 0; j + 1 < N; ++j) {
      Eigen::VectorXd xp = x;
      const double h = 1e-7 * std::max(1.0, std::abs(x[j]));
      xp[j] += h;
      J.col(j) = (residual(r, xp, scale) - F) / h;
    }
    const Eigen::VectorXd dx = J.partialPivLu().solve(-F);
    double lambda = 1.0;
    Eigen::VectorXd x_new, F_new;
    for (; lambda > 1e-4; lambda *= 0.5) {
      x_new = x + lambda * dx;
      F_new = residual(r, x_new, scale);
      if (F_new.lpNorm<Eigen::Infinity>() < F.lpNorm<Eigen::Infinity>()) break;
    }
    if (!(F_new.lpNorm<Eigen::Infinity>() < F.lpNorm<Eigen::Infinity>())) break;  // at rounding level
    x = x_new, F = F_new;
  }
  std::vector<double> xs(N, 0.0);
  for (std::size_t k = 1; k < N; ++k) xs[k] = x[k - 1];
  out.T = from_log_ratios(r.mixture(), xs.data());
  out.residual = F.lpNorm<Eigen::Infinity>();
  if (!(out.residual < 1e-8))
    throw NumericalError("settled temperature ratios: residual " + std::to_string(out.residual) +
                         " after relaxation and Newton polishing");
  return out;
}

}  // namespace

SettledState settled_temperatures(const CollisionRates& rates) {
  if (rates.size() == 1) return {{1.0}, 0.0, 0};
  return rates.size() == 2 ? binary_bracket(rates) : relax_and_polish(rates);
}

std::vector<double> settled_ratios(const CollisionRates& rates) {
  std::vector<double> T = settled_temperatures(rates).T;
  const double T1 = T[0];
  for (double& v : T) v /= T1;
  return T;
}

}  // namespace granmix::theory
