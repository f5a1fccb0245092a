#pragma once
// First-Sonine collision moments of the Garzó–Dufty HCS theory (MG Appendix A, Eqs. 39–44), in
// MG's reduced units (ζ* = ζ/(n σ_ref² v0), v* = v/v0), split into the contribution of the
// species' own collisions ("self") and of one partner species j ("cross"). For a binary the sums
// reproduce MG Eqs. (39)–(44) term by term; for N species the same pair terms are summed over the
// partners, each cross term carrying its size factor (σ_ij/σ_ref)² (MG writes σ_ref = σ_12, so the
// binary cross terms show no size factor).
// Correction applied (docs/physics.md §6): the first prefactor of MG Eq. (40) is (1/8)√(π/2), not
// (1/8)(√π/2); then ζ_11⁽¹⁾/ζ_1⁽⁰⁾ = 3/32 for one species.
#include <cstddef>

namespace granmix::theory {

struct SonineMoments {
  double zeta0 = 0.0;      // ζ_i⁽⁰⁾
  double zeta_self = 0.0;  // ζ_ii⁽¹⁾ (coefficient of c_i in ζ_i)
  double zeta_cross = 0.0; // ζ_ij⁽¹⁾ (coefficient of c_j in ζ_i; cross terms only)
  double Lambda0 = 0.0;    // Λ_i⁽⁰⁾
  double Lambda_self = 0.0;
  double Lambda_cross = 0.0;
};

// Self collisions of species i: x_i, χ_ii, s_ii = (σ_ii/σ_ref)², α_ii, λ_i.
SonineMoments sonine_self(double x_i, double chi_ii, double s_ii, double alpha_ii, double lambda_i);

// Collisions of species i with partner j: x_j, χ_ij, s_ij = (σ_ij/σ_ref)², α_ij, μ_ji = m_j/(m_i+m_j),
// λ_i, λ_j (η = λ_i/λ_j). zeta_self and Lambda_self hold the partner's share of ζ_ii⁽¹⁾ and Λ_ii⁽¹⁾.
SonineMoments sonine_cross(double x_j, double chi_ij, double s_ij, double alpha_ij, double mu_ji, double lambda_i,
                           double lambda_j);

// The same for n partners j at once, field by field (out.zeta0[j], …), with w_j = x_j χ_ij s_ij and the partners'
// √λ_j, 1/√λ_j given (made once per species): one square root and one division per pair, in a loop that runs on
// vector registers (v2 Fig. 6's 691 species evaluate all N² pairs at every right-hand side). sonine_cross is its
// n = 1 case.
struct SonineRow {
  double *zeta0, *zeta_self, *zeta_cross, *Lambda0, *Lambda_self, *Lambda_cross;
};
void sonine_cross_row(std::size_t n, const double* w, const double* alpha, const double* mu, double lambda_i, const double* sqrt_lambda_j,
                      const double* inv_sqrt_lambda_j, const SonineRow& out);

}  // namespace granmix::theory
