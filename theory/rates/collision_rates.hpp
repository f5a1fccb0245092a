#pragma once
// Partial cooling rates ξ_ki and inverse velocity correlation times τ_v,ki⁻¹ of a mixture
// (v1 Appendix A), with the Enskog factor χ_ki. For a pair with moments W2, D
// (collision_moments.hpp), V = T_k/m_k + T_i/m_i, μ = m_i/(m_i+m_k), X = μ V m_k / T_k:
//   ξ_ki       = (4/3)√(2π) n_i σ_ki² χ_ki √V μ (D − (X−1) W2)   = v1 (A2) / (A4)
//   τ_v,ki⁻¹   = (4/3)√(2π) n_i σ_ki² χ_ki √V μ X W2 / 2         = v1 (A1) / (A3)
// with X − 1 = m_k (T_i − T_k) / (T_k (m_i+m_k)) written out, so that ξ has no cancellation at
// ε = 1 and T_i = T_k (it is then exactly 0; CVODE needs that at t ~ 1e12).
// (derivation: the energy and momentum change of particle k averaged over the Maxwellian pair
// measure; ⟨v_k·e | g⟩ = (m_i T_k/(m_k T_i + m_i T_k)) g·e).
#include <cstddef>
#include <vector>

#include "theory/rates/collision_moments.hpp"
#include "model/mixture.hpp"
#include "model/restitution.hpp"

namespace granmix::theory {

// How viscoelastic moments are computed: the paper's series (v1 A3/A4) or a quadrature with
// ε(y) of the law's form. `automatic`: series for form = series, quadrature otherwise.
enum class MomentMethod { automatic, series, quadrature };

class CollisionRates {
 public:
  // Largest pair data the constructor accepts (1 GB): the contact values χ_ki (N² × 8 bytes) and,
  // for a per-pair or viscoelastic law, the moments (N(N+1)/2 × 16 bytes); about 11 000 species with
  // one ε for all pairs. Above, std::invalid_argument (the O(N²) right-hand sides would run for hours).
  static constexpr double max_pair_data_bytes = 1e9;

  CollisionRates(model::Mixture mix, model::Restitution law, std::vector<std::vector<double>> chi,
                 MomentMethod method = MomentMethod::automatic);

  const model::Mixture& mixture() const { return mix_; }
  const model::Restitution& law() const { return law_; }
  std::size_t size() const { return mix_.size(); }
  double chi(std::size_t k, std::size_t i) const { return chi_[k][i]; }
  const std::vector<std::vector<double>>& contact_values() const { return chi_; }
  // What a settled answer depends on besides T: the species (m, σ, n) and every pair's ε and χ — a memo's key (constant
  // restitution: a viscoelastic law has no settled state).
  std::vector<double> key() const;

  CollisionMoments moments(std::size_t k, std::size_t i, double V) const;
  double xi(std::size_t k, std::size_t i, double Tk, double Ti) const;         // ξ_ki
  double inv_tau_v(std::size_t k, std::size_t i, double Tk, double Ti) const;  // τ_v,ki⁻¹

  // ξ_k = Σ_i ξ_ki (v1 Eq. 23) and τ_v,k⁻¹ = Σ_i τ_v,ki⁻¹ (v1 Eq. 20) for all k at once; both
  // together in one pass over the pairs (the same numbers as the two calls).
  void xi_all(const double* T, double* xi) const;
  void inv_tau_v_all(const double* T, double* inv_tau) const;
  void xi_and_inv_tau_v_all(const double* T, double* xi, double* inv_tau) const;
  double xi_species(std::size_t k, const double* T) const;
  double inv_tau_v_species(std::size_t k, const double* T) const;

  // D_k = T_k τ_v,k / m_k (v1 Eq. 19).
  double diffusion(std::size_t k, const double* T) const;

 private:
  // No table of pair constants: every pair's are computed from per-species arrays and the row of χ
  // where they are used (a table of 48 bytes per pair streamed 600 MB per right-hand side at 5000
  // species and made the pass memory-bound). Only a law with more than one ε (constant per pair,
  // or viscoelastic at the current V) keeps the pair moments, in a packed upper triangle (row k
  // holds i = k … N−1).
  //
  // The sums are taken in a factored form: with a_ki = σ_ki² χ_ki √V μ_ki and
  // p_ki = σ_ki² χ_ki √V μ_ki μ_ik (T_i − T_k), and c = (4/3)√(2π),
  //   ξ_k = c (D S_k − W2 U_k / T_k),  τ_v,k⁻¹ = c W2 (S_k + U_k / T_k) / 2,
  //   S_k = Σ_i n_i a_ki,  U_k = Σ_i n_i p_ki
  // (per-pair moments move inside the sums: S_D = Σ n_i a D, S_W = Σ n_i a W2, U_W = Σ n_i p W2).
  // p_ik = −p_ki to the last bit, so one evaluation serves both rows; U_k is exactly 0 when all
  // T_i = T_k, and so is ξ at ε = 1 (CVODE needs that at t ~ 1e12).
  struct RowSums {
    double S_D = 0.0, S_W = 0.0, U_W = 0.0;  // uniform moments: S_D = S_W = S, U_W = U
  };
  // The sums of the one pair (k, i), and of row k over all partners at temperatures T in the order
  // i = 0 … N−1 (the pass over all pairs gives the same numbers).
  RowSums pair_sums(std::size_t k, std::size_t i, double Tk, double Ti) const;
  RowSums row_sums(std::size_t k, const double* T) const;
  void finish(const RowSums& r, double Tk, double* xi, double* inv_tau) const;
  // Every k at once over the unordered pairs, the sum for each k in the order i = 0 … N−1 (as
  // row_sums); xi or inv_tau may be null.
  void symmetric_sums(const double* T, double* xi, double* inv_tau) const;

  model::Mixture mix_;
  model::Restitution law_;
  std::vector<std::vector<double>> chi_;
  MomentMethod method_;
  std::vector<double> inv_m_, density_, diameter_;
  std::vector<const double*> chi_rows_;  // row k of χ for the pass (chi_uniform_row_ when all χ_ki are equal)
  std::vector<double> chi_uniform_row_;
  bool uniform_moments_ = false;           // constant law with one ε: W_ holds its moments
  CollisionMoments W_{};
  std::vector<double> W2_, D_;             // constant law with per-pair ε: each link's moments
};

}  // namespace granmix::theory
