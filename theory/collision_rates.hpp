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
  // Largest pair table the constructor accepts (1 GB: about 3700 species); above, std::invalid_argument.
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

  // ξ_k = Σ_i ξ_ki (v1 Eq. 23) and τ_v,k⁻¹ = Σ_i τ_v,ki⁻¹ (v1 Eq. 20) for all k at once.
  void xi_all(const double* T, double* xi) const;
  void inv_tau_v_all(const double* T, double* inv_tau) const;
  double xi_species(std::size_t k, const double* T) const;
  double inv_tau_v_species(std::size_t k, const double* T) const;

  // D_k = T_k τ_v,k / m_k (v1 Eq. 19).
  double diffusion(std::size_t k, const double* T) const;

 private:
  struct Pair {
    double prefactor;  // (4/3)√(2π) n_i σ_ki² χ_ki
    double mu;         // m_i / (m_i + m_k)
    double mu_k;       // m_k / (m_i + m_k)
    double inv_mk, inv_mi;
    CollisionMoments W;  // constant law: the pair's moments, computed once
  };
  const Pair& pair(std::size_t k, std::size_t i) const { return pairs_[k * mix_.size() + i]; }
  // ξ_ki from its parts (the formula at the top of this file); shared by xi() and xi_all().
  static double xi_formula(const Pair& p, double sqrtV, double Tk, double Ti, const CollisionMoments& W) {
    return p.prefactor * sqrtV * p.mu * (W.D - p.mu_k * (Ti - Tk) / Tk * W.W2);
  }
  // τ_v,ki⁻¹ likewise; shared by inv_tau_v() and inv_tau_v_all().
  static double inv_tau_formula(const Pair& p, double sqrtV, double Tk, double Ti, const CollisionMoments& W) {
    return p.prefactor * (sqrtV * p.mu) * (1.0 + p.mu_k * (Ti - Tk) / Tk) * W.W2 * 0.5;
  }
  // Σ_i f(pair k i) for all k, each unordered pair once with √V shared (constant law: the hot path
  // of the temperature ODE with hundreds of species); summation order per k as in the plain loop.
  template <class F>
  void symmetric_sum(const double* T, double* out, F f) const;

  model::Mixture mix_;
  model::Restitution law_;
  std::vector<std::vector<double>> chi_;
  MomentMethod method_;
  std::vector<Pair> pairs_;
};

}  // namespace granmix::theory
