#pragma once
// First-Sonine collision integrals of one pair (k, i) whose restitution coefficient depends on the
// normal impact speed u = g·σ̂ (viscoelastic spheres, Brilliantov & Pöschel; v1 Eq. 5), by quadrature
// over u (docs/physics-beyond.md §4). The distributions are f_k = f_M,k (1 + a_k S₂(c_k²)) and
// f_i likewise, kept to first order in the a's as Garzó–Dufty/MG do (so at constant ε these integrals
// are MG's Eqs. 39–44 and the C_pq of sonine2_diffusion.hpp). With θ = T/m and V = θ_k + θ_i,
//   collisional rate of ⟨ψ(v_k)⟩ from partner i = n_i σ_ki² χ_ki · 4π ∫₀^∞ du u φ_V(u) E[w Δψ | g_z = u],
// φ_V the Gaussian density of one component of g, w = 1 + a_k S₂(c_k²) + a_i S₂(c_i²), Δψ = ψ(v_k′) − ψ(v_k),
// v_k′ = v_k − μ_ik (1 + ε(u)) u σ̂. Why it reduces to one integral: the σ̂ integral of a rotation-invariant
// integrand is 4π times its value at σ̂ = ẑ, and given g_z = u the Maxwellian pair splits into independent parts
//   v_kz = W + (θ_k/V) u,  v_iz = W − (θ_i/V) u,  W ~ N(0, θ_kθ_i/V);   |v_k⊥|² ~ Exp(mean 2θ_k), |v_i⊥|² ~ Exp(2θ_i).
// E[· | u] of these polynomials is exact: Gauss–Hermite in W (max(5, 2M) points: degree 8 for ⟨v⁴⟩, 4M − 2 for
// C_pq with M modes), Gauss–Laguerre in |v_k⊥|² (max(2, M) points: degree 3, 2M − 1), and
// E[S₂(c_i²) | v_iz] = y²/2 − 3y/2 + 3/8, y = v_iz²/(2θ_i), in closed form.
// The u integral is the half-range Gauss rule below (half_range_rule): fixed nodes keep ODE right-hand sides
// smooth.
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "theory/sonine/sonine2_diffusion.hpp"
#include "theory/sonine/sonine_moment_table.hpp"
#include "theory/sonine/sonine_terms.hpp"

namespace granmix::theory {

// The rules of these quadratures, shared with other pair integrals of the same form (tracer_diffusion_galerkin.cpp).
struct GaussRule {
  std::vector<double> x, weight;
};
// Expectation over N(0, 1) (laguerre = false) or Exp(1) (true), n points, exact to degree 2n − 1, by Golub–Welsch
// (the eigen-decomposition of the recurrence's Jacobi matrix).
GaussRule golub_welsch(std::size_t n, bool laguerre);
// ∫₀^∞ u φ_V(u) g(u) du ≈ √(2V/π) Σ_n weight_n g(√(2V) x_n), φ_V the N(0, V) density: the Gauss rule of the weight
// x e^(−x²) on [0, ∞) (u = √(2V) x), n nodes, exact to degree 2n − 1 in x; n one of half_range_rule_sizes, each built
// once. At constant ε the integrands are smooth in u (polynomials, for the Sonine quadratures). A viscoelastic ε(u) is
// a function of u^(1/10) (v1 Eq. 5), not smooth at u = 0; there the momentum transfer ∝ (1 + ε)u and the weight ∝ u
// make the rule's error fall algebraically, ~n^(−6): the moment rates of 200 random viscoelastic pairs (θ_k over
// e^(±6), θ_i/θ_k over e^(±4), μ 0.01–0.99, A κ^(2/5) e^(−4)–1) against the 160-node Gauss–Legendre rule in
// w = (u/√(2V))^(1/10): 16 nodes 4.2e-9, 24 4.2e-10, 32 8.1e-11, 48 7.3e-12 of the
// pair's largest rate (that rule's 80 nodes: 5.8e-12 on the moments, but 2.4e-7 on the tracer problem's pair sources,
// against 3e-8 for 24 nodes of this one: tests/theory/test_tracer_diffusion_galerkin.cpp). 48: the tests' reference
// (beyond it the discretised weight's Stieltjes recurrence loses digits).
inline constexpr std::size_t half_range_rule_sizes[] = {12, 16, 24, 32, 48};
const GaussRule& half_range_rule(std::size_t n);

// All per unit n_i σ_ki² χ_ki (multiply by it for the pair's rates).
struct PairSonineIntegrals {
  // Collisional rates of ⟨v_k²⟩ and ⟨v_k⁴⟩: [0] at a = 0, [1] coefficient of a_k, [2] coefficient of a_i.
  std::array<double, 3> energy{}, fourth{};
  SonineCollisionIntegrals C;  // the Maxwellian C_pq of the tracer problem (sonine2_diffusion.hpp), p, q < modes
};

// eps(u): the pair's restitution at normal impact speed u >= 0 (in the units of √θ).
// mu = μ_ik = m_i/(m_i + m_k); theta_k = T_k/m_k, theta_i = T_i/m_i.
// modes: the C_pq computed (p, q < modes ≤ max_sonine_modes).
PairSonineIntegrals sonine_pair_quadrature(double theta_k, double theta_i, double mu, const std::function<double(double)>& eps,
                                           std::size_t modes = 2);

// The normal impact speeds u_n at which the quadrature needs ε for a pair with V = θ_k + θ_i, and the same
// integrals with ε given there (eps_nodes[n] = ε(u_n)): callers that reuse ε between calls of equal V
// (pairs k–i and i–k, the cooling and the velocity-decay closures) evaluate the law once. The nodes: the half-range
// rule's 32 (8e-11 of a viscoelastic pair's largest moment rate, see above; at constant ε exact).
inline constexpr std::size_t impact_speed_points = 32;
std::size_t sonine_quadrature_nodes();
void sonine_quadrature_speeds(double V, double* u, std::size_t nodes = impact_speed_points);
PairSonineIntegrals sonine_pair_quadrature(double theta_k, double theta_i, double mu, const double* eps_nodes, std::size_t modes = 2);

// The rates of the moment closure at order 3 or 4 (sonine_moment_cooling.hpp) by the same quadrature: rates of ⟨c^(2p)⟩_k,
// c = v/√(2θ_k), p = 1…order, per unit n_i σ_ki² χ_ki and Sonine coefficient, in the table's layout
// (sonine_moment_table.hpp; Maxwell, own a₂ … a_order, partner's a₂ … a_order; order 3: the ⟨c⁸⟩ row and the a₄
// sources NaN), with f = f_M(1 + Σ a_q S_q) kept to first order in the a's; at constant ε
// these are the closed forms of sonine_moment_pair (tested). E[· | u] exact: Hermite 8 points in W (degree 12:
// S₃ times the change of v⁶), Laguerre 4 in |v_k⊥|² (degree 6), E[S_q(c_i²) | v_iz] = L_q^(−1/2)(y) in closed form;
// order 4: Hermite 10, Laguerre 5 (S₄ times the change of v⁸: degree 16 and 8).
// nodes: the rule's (sonine_quadrature_speeds' for the same eps_nodes; another than impact_speed_points: tests).
SonineMomentRates sonine_moment_quadrature(double theta_k, double theta_i, double mu, const double* eps_nodes, int order = 3,
                                           std::size_t nodes = impact_speed_points);

// The same integrals as MG's reduced pair terms of species k (sonine_terms.hpp) in units with v0 = 1
// (θ_k = 1/(2λ_k)): ζ = −rate⟨v_k²⟩/(3θ_k), Λ = rate⟨v_k⁴⟩ (the ⟨V⁴⟩ balance of sonine_system.hpp), the
// coefficients of c = 2a halved; w = x_i χ_ki s_ki. self: the partner is species k itself (both a's are a_k).
SonineMoments sonine_moments(const PairSonineIntegrals& q, double w, double theta_k, bool self);

}  // namespace granmix::theory
