#pragma once
// Garzó–Dufty first-Sonine solution of the homogeneous cooling state (MG Sec. 2, Appendix A), for
// a binary (MG's setting) and, with the same pair terms summed over partners, for N species.
// Units are MG's: v0² = 2T(m_1+m_2)/(m_1 m_2) with T = Σ x_k T_k (m_2 = m_1 for one species),
// λ_k = m_k v0²/(2T_k) (binary: T/(T_k μ_jk)), ζ* = ζ/(n σ_12² v0) (σ_11 for one species).
// Unknowns: the cumulants c_k (N linear equations, MG Eqs. 31–38) and the temperature ratios from
// equal cooling rates (MG Eq. 45): Brent bracketing in ln γ for two species; gsl_multiroot (hybrids)
// in ln(T_k/T_1) from the Maxwellian ratios for more. `maxwell = true` sets every c_k = 0.
// Order 3 (beyond MG): every species also carries a₃, f_k = f_M[1 + a₂S₂ + a₃S₃], and the a's are the steady
// ones of the ⟨c⁴⟩ and ⟨c⁶⟩ balances (sonine_moment_cooling.hpp, the level kinetic-cooling3) — the first-Sonine
// truncation's next correction, which the γ-sweep scenes judge with. Order 4 adds a₄ and the ⟨c⁸⟩ balance (the level
// kinetic-cooling4: the order-3 temperatures' next correction).
#include <vector>

#include "model/mixture.hpp"
#include "model/restitution.hpp"

namespace granmix::theory {

struct SonineHcs {
  std::vector<double> T;       // T_k/T, normalised so that Σ x_k T_k = 1
  std::vector<double> c;       // c_k = 2 a₂ (docs/physics.md §6)
  std::vector<double> a3;      // a₃,k at order 3 (empty at the first Sonine, which truncates it)
  std::vector<double> a4;      // a₄,k at order 4 (empty below)
  std::vector<double> lambda;  // λ_k
  std::vector<double> beta;    // β_k = π Σ_j x_j χ_kj (σ_kj/σ_ref)² (MG Eq. 20)
  double zeta_star = 0.0;      // common reduced cooling rate ζ*
  double gamma() const { return T[0] / T[1]; }  // MG's γ = T_1/T_2 (binary)
  // Tail Φ_k ~ A exp(−(2β_k/ζ*) v*), linear in v* (docs/physics.md §6 correction of MG Eq. 21).
  double tail_exponent(std::size_t k) const { return 2.0 * beta[k] / zeta_star; }
  // MG Eq. (27)/(17): first-Sonine Φ_k(v*), its Sonine deviation Δ_k (Eq. 28) and G_k (Eq. 30); at order 3
  // with a₃ S₃ beside a₂ S₂, Δ_k being (Φ_k/Φ_M − 1)/a₂ as MG define it.
  double phi(std::size_t k, double v) const;
  double delta(std::size_t k, double v) const;
  double G(std::size_t k, double v) const;
};

// The Maxwellian of MG Eq. (27) with c = 0: (λ/π)^(3/2) exp(−λ v*²).
double maxwellian_phi(double lambda, double v);

// How the temperature ratios are found: automatic = bracketing for two species, multiroot above;
// multiroot can be forced for two species (to check one solver against the other).
enum class SonineSolver { automatic, multiroot };

// α = restitution matrix (constant law only); χ = contact values (1 dilute); order 2 (MG's first Sonine), 3 or 4
// (not with maxwell; up to the moment table's order).
SonineHcs sonine_hcs(const model::Mixture& mix, const model::Restitution& alpha, const std::vector<std::vector<double>>& chi,
                     bool maxwell = false, SonineSolver solver = SonineSolver::automatic, int order = 2);

}  // namespace granmix::theory
