#include "theory/sonine/sonine_system.hpp"

#include <cmath>
#include <vector>

#include "theory/numerics/equilibrated_solve.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"

namespace granmix::theory {

SonineSystem::SonineSystem(const model::Mixture& mix, const model::Restitution& alpha,
                           const std::vector<std::vector<double>>& chi, double sref2, std::shared_ptr<const SoninePairTerms> terms)
    : N_(mix.size()), terms_(terms ? std::move(terms) : make_sonine_pair_terms(alpha)), w_(N_ * N_), mu_(N_ * N_), sqrt_lambda_(N_),
      inv_sqrt_lambda_(N_), K_(N_, N_), Z_(N_, N_), A_(N_), z0_(N_) {
  for (std::size_t i = 0; i < N_; ++i)
    for (std::size_t j = 0; j < N_; ++j) {
      const double sigma = mix.sigma(i, j);  // σ_ii = σ_i
      w_[i * N_ + j] = mix.fraction(j) * chi[i][j] * sigma * sigma / sref2;
      mu_[i * N_ + j] = mix[j].mass / (mix[i].mass + mix[j].mass);
    }
}

void SonineSystem::assemble(const double* lambda) {
  // Rows are independent (row i writes K_, Z_ (i, ·), A_, z0_ [i]) and each is summed wholly by one thread in a fixed
  // order, so the numbers do not depend on the thread count; worth it from ~100 species (v2 Fig. 6's 691: N² pairs at
  // every right-hand side).
  for (std::size_t i = 0; i < N_; ++i) sqrt_lambda_[i] = std::sqrt(lambda[i]), inv_sqrt_lambda_[i] = 1.0 / sqrt_lambda_[i];
  const SonineLambdas lambdas{lambda, sqrt_lambda_.data(), inv_sqrt_lambda_.data()};
#pragma omp parallel for schedule(static) if (N_ >= 100 && terms_->concurrent())
  for (std::size_t i = 0; i < N_; ++i) {
    thread_local std::vector<double> buffer;  // the row's six fields
    buffer.resize(6 * N_);
    double* b = buffer.data();
    const SonineRow p{b, b + N_, b + 2 * N_, b + 3 * N_, b + 4 * N_, b + 5 * N_};
    terms_->cross_row(i, &w_[i * N_], &mu_[i * N_], lambdas, p);
    SonineMoments own = terms_->self(i, w_[i * N_ + i], lambda[i]);
    const double f = 15.0 / (2.0 * lambda[i] * lambda[i]);
    // Vector sums over the partners (entry i, the species itself, zeroed first; its K, Z entries are set below).
    const auto n = Eigen::Index(N_);
    const auto field = [n](double* x) { return Eigen::Map<Eigen::VectorXd>(x, n); };
    for (double* x : {p.zeta0, p.zeta_self, p.Lambda0, p.Lambda_self}) x[i] = 0.0;
    own.zeta0 += field(p.zeta0).sum(), own.zeta_self += field(p.zeta_self).sum();
    own.Lambda0 += field(p.Lambda0).sum(), own.Lambda_self += field(p.Lambda_self).sum();
    K_.row(Eigen::Index(i)) = (f * field(p.zeta_cross) + field(p.Lambda_cross)).transpose();  // MG (35), (37), (41)
    Z_.row(Eigen::Index(i)) = field(p.zeta_cross).transpose();
    A_[i] = -f * own.zeta0 - own.Lambda0;                               // MG (33), (36)
    K_(i, i) = f * (own.zeta_self + 0.5 * own.zeta0) + own.Lambda_self;  // MG (34), (38)
    z0_[i] = own.zeta0;                                                 // MG (39)
    Z_(i, i) = own.zeta_self;                                           // MG (40)
  }
}

void SonineSystem::solve_cumulants(double* c) {
  Eigen::Map<Eigen::VectorXd>(c, Eigen::Index(N_)) = solve_equilibrated(K_, A_, "Sonine cumulants (MG Eqs. 33-38)");
}

// Eigen's products (vectorised row sums: v2 Fig. 6's 691 species read both N² matrices at every right-hand side).
void SonineSystem::cooling(const double* c, double* zeta) const {
  const auto n = Eigen::Index(N_);
  Eigen::Map<Eigen::VectorXd>(zeta, n).noalias() = z0_ + Z_ * Eigen::Map<const Eigen::VectorXd>(c, n);
}

void SonineSystem::moment_residual(const double* c, double* r) const {
  const auto n = Eigen::Index(N_);
  Eigen::Map<Eigen::VectorXd>(r, n).noalias() = K_ * Eigen::Map<const Eigen::VectorXd>(c, n) - A_;
}

}  // namespace granmix::theory
