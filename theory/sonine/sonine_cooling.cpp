#include "theory/sonine/sonine_cooling.hpp"

#include <algorithm>
#include <stdexcept>

namespace granmix::theory {

SonineCooling::SonineCooling(const CollisionRates& rates, CumulantMode mode, std::vector<double> c0,
                             std::shared_ptr<const SoninePairTerms> terms)
    : rates_(rates),
      mode_(mode),
      c0_(std::move(c0)),
      N_(rates.size()),
      n_(rates.mixture().total_density()),
      system_(rates.mixture(), rates.law(), rates.contact_values(), 1.0, std::move(terms)),
      lambda_(N_),
      c_(N_),
      r_(N_) {
  if (c0_.empty()) c0_.assign(N_, 0.0);
  if (c0_.size() != N_) throw std::invalid_argument("Sonine cooling rates: one initial cumulant per species needed");
}

void SonineCooling::assemble(const double* T) const {
  // The N² pair terms depend on T only: CVODE's difference-quotient Jacobian perturbs one unknown at a time,
  // and for the cumulants, MSDs and VACF modes (most columns) T is bitwise the same as at the last call.
  if (assembled_ && std::equal(T, T + N_, assembled_T_.begin())) return;
  assembled_T_.assign(T, T + N_), assembled_ = true;
  for (std::size_t k = 0; k < N_; ++k) lambda_[k] = rates_.mixture()[k].mass / (2.0 * T[k]);  // v0 = 1
  system_.assemble(lambda_.data());
}

void SonineCooling::initial_state(const double*, double rtol, double* z, double* atol) const {
  // c is O(0.01–0.3) and starts at 0: an absolute tolerance rtol, as for ln T.
  for (std::size_t k = 0; k < state_size(); ++k) z[k] = c0_[k], atol[k] = rtol;
}

void SonineCooling::rates(const double* T, const double* z, double* xi, double* dz_dt) const {
  assemble(T);
  if (mode_ == CumulantMode::quasi_static) {
    system_.solve_cumulants(c_.data());
    system_.cooling(c_.data(), xi);
  } else {
    system_.cooling(z, xi);
    system_.moment_residual(z, r_.data());
    for (std::size_t k = 0; k < N_; ++k) dz_dt[k] = n_ * (8.0 / 15.0) * lambda_[k] * lambda_[k] * r_[k];
  }
  for (std::size_t k = 0; k < N_; ++k) xi[k] *= n_;
}

bool SonineCooling::cumulants(const double* T, const double* z, double* c) const {
  if (mode_ == CumulantMode::relaxing) {
    std::copy(z, z + N_, c);
    return true;
  }
  assemble(T);
  system_.solve_cumulants(c);
  return true;
}

}  // namespace granmix::theory
