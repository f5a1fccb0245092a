#include "sonine_system.hpp"

#include <cmath>

#include "equilibrated_solve.hpp"
#include "sonine_pair_terms.hpp"

namespace granmix::theory {

SonineSystem::SonineSystem(const model::Mixture& mix, const model::Restitution& alpha,
                           const std::vector<std::vector<double>>& chi, double sref2, std::shared_ptr<const SoninePairTerms> terms)
    : mix_(mix), chi_(chi), sref2_(sref2), N_(mix.size()), terms_(terms ? std::move(terms) : make_sonine_pair_terms(alpha)), K_(N_, N_), Z_(N_, N_), A_(N_),
      z0_(N_) {}

void SonineSystem::assemble(const double* lambda) {
  // Rows are independent (row i writes K_, Z_ (i, ·), A_, z0_ [i]) and each is summed wholly by one thread in a fixed
  // order, so the numbers do not depend on the thread count; worth it from ~100 species (v2 Fig. 6's 691: N² pairs at
  // every right-hand side).
#pragma omp parallel for schedule(static) if (N_ >= 100 && terms_->concurrent_cross())
  for (std::size_t i = 0; i < N_; ++i) {
    const double s_ii = std::pow(mix_[i].diameter, 2) / sref2_;
    SonineMoments own = terms_->self(i, mix_.fraction(i) * chi_[i][i] * s_ii, lambda[i]);
    const double f = 15.0 / (2.0 * lambda[i] * lambda[i]);
    for (std::size_t j = 0; j < N_; ++j) {
      if (j == i) continue;
      const double s_ij = std::pow(mix_.sigma(i, j), 2) / sref2_;
      const double mu_ji = mix_[j].mass / (mix_[i].mass + mix_[j].mass);
      const SonineMoments p = terms_->cross(i, j, mix_.fraction(j) * chi_[i][j] * s_ij, mu_ji, lambda[i], lambda[j]);
      own.zeta0 += p.zeta0, own.zeta_self += p.zeta_self;
      own.Lambda0 += p.Lambda0, own.Lambda_self += p.Lambda_self;
      K_(i, j) = f * p.zeta_cross + p.Lambda_cross, Z_(i, j) = p.zeta_cross;  // MG (35), (37), (41)
    }
    A_[i] = -f * own.zeta0 - own.Lambda0;                               // MG (33), (36)
    K_(i, i) = f * (own.zeta_self + 0.5 * own.zeta0) + own.Lambda_self;  // MG (34), (38)
    z0_[i] = own.zeta0;                                                 // MG (39)
    Z_(i, i) = own.zeta_self;                                           // MG (40)
  }
}

void SonineSystem::solve_cumulants(double* c) {
  Eigen::Map<Eigen::VectorXd>(c, Eigen::Index(N_)) = solve_equilibrated(K_, A_, "Sonine cumulants (MG Eqs. 33-38)");
}

void SonineSystem::cooling(const double* c, double* zeta) const {
  for (std::size_t i = 0; i < N_; ++i) {
    double s = 0.0;
    for (std::size_t j = 0; j < N_; ++j) s += Z_(i, j) * c[j];
    zeta[i] = z0_[i] + s;
  }
}

void SonineSystem::moment_residual(const double* c, double* r) const {
  for (std::size_t i = 0; i < N_; ++i) {
    double s = 0.0;
    for (std::size_t j = 0; j < N_; ++j) s += K_(i, j) * c[j];
    r[i] = s - A_[i];
  }
}

}  // namespace granmix::theory
