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

#include "collision_moments.hpp"
#include "model/mixture.hpp"
#include "model/restitution.hpp"

namespace granmix::theory {

// How viscoelastic moments are computed: the paper's series (v1 A3/A4) or a quadrature with
// ε(y) of the law's form. `automatic`: series for form = series, quadrature otherwise.
enum class MomentMethod { automatic, series, quadrature };

class CollisionRates {
 public:
  // Largest pair table the constructor accepts (1 GB: N(N+1)/2 × 48 bytes, about 6400 species);
  // above, std::invalid_argument.
  static constexpr double max_pair_table_bytes = 1e9;

  CollisionRates(model::Mixture mix, model::Restitution law, std::vector<std::vector<double>> chi,
                 MomentMethod method = MomentMethod::automatic);

  const model::Mixture& mixture() const { return mix_; }
  const model::Restitution& law() const { return law_; }
  std::size_t size() const { return mix_.size(); }
  double chi(std::size_t k, std::size_t i) const { return chi_[k][i]; }
  const std::vector<std::vector<double>>& contact_values() const { return chi_; }

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
  // The constants of every unordered pair k <= i in both directions, in a packed upper triangle
  // (row k holds i = k … N−1 contiguously), one array per constant so that the symmetric sums
  // stream through them and vectorise.
  struct Links {
    std::vector<double> pref_ki, pref_ik;  // (4/3)√(2π) n_i σ_ki² χ_ki and (4/3)√(2π) n_k σ_ki² χ_ik
    std::vector<double> mu_ki, mu_ik;      // m_i/(m_i+m_k) and m_k/(m_i+m_k)
    std::vector<double> W2, D;             // constant law: the pair's moments, computed once (ε_ki = ε_ik)
  };
  static constexpr std::size_t link_bytes = 6 * sizeof(double);
  std::size_t link_index(std::size_t k, std::size_t i) const { return k * (2 * mix_.size() - k + 1) / 2 + (i - k); }
  // One direction k → i of a link: what the formulas need.
  struct Pair {
    double prefactor, mu, mu_k;  // (4/3)√(2π) n_i σ_ki² χ_ki, m_i/(m_i+m_k), m_k/(m_i+m_k)
    double inv_mk, inv_mi;
  };
  Pair pair(std::size_t k, std::size_t i) const;
  // ξ_ki and τ_v,ki⁻¹ from their parts (the formulas at the top of this file); shared by the single
  // pair functions and the sums over all pairs, so that both give the same numbers.
  static double xi_formula(double pref, double mu, double mu_k, double sqrtV, double Tk, double Ti, const CollisionMoments& W) {
    return pref * sqrtV * mu * (W.D - mu_k * (Ti - Tk) / Tk * W.W2);
  }
  static double inv_tau_formula(double pref, double mu, double mu_k, double sqrtV, double Tk, double Ti,
                                const CollisionMoments& W) {
    return pref * (sqrtV * mu) * (1.0 + mu_k * (Ti - Tk) / Tk) * W.W2 * 0.5;
  }
  // Σ_i over all pairs for every k, each unordered pair once with √V (and a viscoelastic pair's
  // moments) shared, the sum for each k in the order i = 0 … N−1 (as the single-species sums, same
  // numbers); xi or inv_tau may be null.
  void symmetric_sums(const double* T, double* xi, double* inv_tau) const;

  model::Mixture mix_;
  model::Restitution law_;
  std::vector<std::vector<double>> chi_;
  MomentMethod method_;
  std::vector<double> inv_m_;
  Links links_;
};

}  // namespace granmix::theory
