#pragma once
// The Garzó–Dufty first-Sonine equations of an N-species mixture at given temperatures (MG Sec. 2,
// Eqs. 31–45, Appendix A: the pair terms of sonine_pair_terms.hpp — MG's closed forms, or their quadrature over
// the impact speed for a viscoelastic law — summed over partners), in MG's reduced
// units with the reference scales left to the caller: λ_k = m_k v0²/(2T_k), s_ij = (σ_ij/σ_ref)²,
// rates in units of ν_ref = n σ_ref² v0 (n the total density). With c_k = 2a₂,k (docs/physics.md §6):
//   cooling rates   ζ_i/ν_ref = z0_i + Σ_j Z_ij c_j                               (MG Eqs. 39–41)
//   fourth moment   dc_i/dt  = ν_ref (8λ_i²/15) (Σ_j K_ij c_j − A_i)              (MG Eqs. 31–38)
// The second line is the balance of ⟨V⁴⟩_i = 15(T_i/m_i)²(1 + c_i/2) under dT_i/dt = −ζ_i T_i and
// collisions, linear in c as MG's: MG's row i is (15/(2λ_i²)) ζ_i(1 + c_i/2) + Λ_i = 0, the
// stationary cumulant. So K c = A gives the cumulants that are steady at the current temperatures
// (sonine_hcs.hpp solves it at the HCS ratios), and the same K, A drive the relaxing cumulants of
// sonine_cooling.hpp, whose fixed point is therefore the same.
#include <Eigen/Dense>
#include <cstddef>
#include <memory>
#include <vector>

#include "model/mixture.hpp"
#include "model/restitution.hpp"
#include "theory/sonine/sonine_pair_terms.hpp"

namespace granmix::theory {

class SonineSystem {
 public:
  // α = restitution law; χ = contact values; σ_ref² in the units of the diameters. The pair weights are read here
  // (fixed); alpha is referenced by the pair terms made from it: it must outlive the system. The pair terms follow the law
  // (sonine_pair_terms.hpp): MG's closed forms at constant ε; for a viscoelastic law the quadrature over
  // the impact speed, which needs λ_k in units with v0 = 1 (λ_k = m_k/(2T_k), as sonine_cooling.hpp).
  // terms: the pair terms to use (null: made from alpha; pass one to share it with other closures).
  SonineSystem(const model::Mixture& mix, const model::Restitution& alpha, const std::vector<std::vector<double>>& chi,
               double sref2, std::shared_ptr<const SoninePairTerms> terms = nullptr);

  std::size_t size() const { return N_; }
  // Fill K, A, z0, Z at the given λ_k (no allocation).
  void assemble(const double* lambda);
  // c from K c = A (full-pivot LU on equilibrated rows: equilibrated_solve.hpp); throws NumericalError if K is singular.
  void solve_cumulants(double* c);
  // ζ_i/ν_ref = z0_i + Σ_j Z_ij c_j.
  void cooling(const double* c, double* zeta) const;
  // (K c − A)_i: zero at the steady cumulants.
  void moment_residual(const double* c, double* r) const;

 private:
  std::size_t N_;
  std::shared_ptr<const SoninePairTerms> terms_;
  // Per ordered pair (row i, partner j), fixed by the mixture: w_ij = x_j χ_ij s_ij and μ_ji = m_j/(m_i + m_j).
  std::vector<double> w_, mu_;
  std::vector<double> sqrt_lambda_, inv_sqrt_lambda_;  // of the last assembly
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> K_, Z_;  // row i: species i's equation
  Eigen::VectorXd A_, z0_;
};

}  // namespace granmix::theory
