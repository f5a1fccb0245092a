#pragma once
// The converged tracer problem in time: the velocity correlation of the kinetic-converged level along a history
// (docs/levels.md). tracer_diffusion_galerkin.hpp solves the tracer problem at one settled state; here the same Galerkin
// problem follows the temperatures T(t) and the Sonine shapes a₂(t), a₃(t) of the cooling closure, as SonineDecay
// (sonine2_diffusion.hpp) does in the Sonine basis, whose expansion does not converge at strong dissipation.
//
// Forward form (the Q_k = ⟨Δr·v⟩ form of docs/physics-beyond.md §2 with the Galerkin closure of tracer_diffusion_galerkin
// in place of the first Sonine's one mode). g(v, t) = ⟨Δr_k δ(v − v_k(t))⟩ obeys the tracer (Boltzmann–Lorentz) equation with the source v f_k
// (dΔr/dt = v), and Q_k = ⟨Δr_k·v_k⟩ = ∫v·g dv. With g in the trial space f_w c Σ_q b_q B_q(c²) (f_w the Maxwellian of
// temperature λT_k(t), c = v/√(2θ_k(t)), θ_k = T_k/m_k) and Y_n = ⟨c B_n·Δr_k⟩ = (M b)_n, the moment equations
// are exact up to the closure g ≈ its projection:
//   dY/dt = √(2θ_k) r − Aᵀ M⁻¹ Y,   A = A_coll − (ξ_k/2) S,
// with A_coll, M, S, r of tracer_diffusion_galerkin.hpp at the current state (S, the scaling term, from dc/dt =
// (ξ_k/2)c; ξ_k = −d ln T_k/dt of the cooling closure, the rate of the same a's the operator holds). In the
// elastic limit the steady Q is 2θ_k r·A⁻¹M e₀ = 3D_k of galerkin_diffusion: the adjoint problem's D (duality).
// The unknowns are U = Δ H Φᵀ-coordinates of Z = √(2θ_k) Y: Φ the M-orthonormal basis (m_orthonormal_basis), H
// the Householder reflection taking y₀ = ΦᵀMe₀ (the coordinates of B₀ = 1) to α e₁, α = ∓|y₀|, Δ = diag(α, 1, …), so that
// U₀ = Q_k (the VelocityDecay contract) and
//   dU/dt = 2θ_k s − Ã U − (ξ_k/2) U,   s = ΔHΦᵀ r,   Ã = ΔHΦᵀ Aᵀ ΦHΔ⁻¹;   U = 0 at t = 0 (any start).
// The state enters A_coll only through the pairs: at constant ε partner i contributes √(2θ_k)[G⁰(ρ) + a_i2 G²(ρ) +
// a_i3 G³(ρ)], ρ = θ_i/θ_k, the pair problem at θ_k = 1/2 (add_pair_collisions). Those are tabulated on a grid in
// ln ρ (steps pair_grid_step, smooth_basis_grid_step; each source over √(λ + ρ)) as the history reaches them, 0.07–0.5 ms per node by the pair rule (v1 Fig. 8, AVX-512 machine) (those one right-hand side needs on OpenMP
// threads together), and interpolated by Catmull–Rom cubics
// (C¹, so CVODE's Newton iterations see a smooth right-hand side); the basis (x₀) is each species' at the
// reference temperatures (the level's settled ones) for the whole history, so M, S, Φ and r are fixed.
// A viscoelastic ε(u) breaks that scaling (ε depends on the impact speed itself): its tables have a second axis, ln θ_k
// (step scale_grid_step), and bicubic Catmull–Rom weights (16 nodes per pair and right-hand side).
// A species whose settled problem has no decaying solution (a rare grain at the Santos–Dufty edge) keeps one mode at
// the first-Sonine ν_k = τ_v,k⁻¹ + ξ_k/2, its other unknowns decoupled, as SonineDecay does.
#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/cooling_model.hpp"
#include "theory/grid/tracer_diffusion_galerkin.hpp"

namespace granmix::theory {

// The step in ln(θ_i/θ_k) of the pair tables. They hold each source over √(λ + ρ), the collision flux's factor
// (V = θ_k(λ + ρ), add_pair_collisions), which the interpolated operator takes back at the current ρ: what Catmull–Rom
// interpolates then varies less with ln ρ where the partner is hot. Measured: the operator's worst entry
// against the direct assembly, partner shapes on: v1 Fig. 8's 43 species at four states between the equal start and
// the settled ratios, 1.06e-5 without the factor, 4.2e-6 with it; bo1-fig05's binary (tests/theory/
// test_galerkin_decay.cpp) 4.8e-5 without, 4.2e-5 with, its light species at ρ = 0.92 (at step 1/6: 4.3e-4, so not for it).
inline constexpr double pair_grid_step = 0.125;
// A species of a smooth basis (x₀ ≥ 1.5: its own pair rule 40 × 24 or coarser) takes this step: with the flux factor
// v1 Fig. 8's 43 species then err by 1.16e-5 (16 species 7.6e-6; at 1/5: 2.0e-5), the error of step 1/8 without the
// factor, for ~25% fewer of its nodes — v1 Fig. 8's costliest (40 × 24: 4 039 of its 25 275 nodes, 1.0 of 2.7 s).
inline constexpr double smooth_basis_grid_step = 1.0 / 6.0;
// A coarse pair (coarse_pair_share) takes twice pair_grid_step and coarse_speed_points impact speeds: its share of the
// collisions is ≤ 1e-2, and v1 Fig. 8's operator moves by ≤ 1.3e-7 from the step (43 species, the four states above)
// and ≤ 1e-8 from the speeds (the coarse rule's check in tests/theory/test_galerkin_decay.cpp: 6.82e-6 → 6.83e-6 with
// 12 speeds; with 10 speeds 1.1e-5, with 8 4.5e-4).
inline constexpr double coarse_grid_factor = 2.0;
inline constexpr std::size_t coarse_speed_points = 12;
// A viscoelastic ε(u) depends on the impact speed itself, so its tables have a second axis, ln θ_k, of this step (ε
// varies as θ^(1/10); tests/theory/test_galerkin_decay.cpp: worst 1.5e-5 at step 2 (2.0e-5 without the flux
// factor √(λ + ρ)), 2.2e-5 at step 1; the MSDs of
// v1 Figs. 9/10 move ≤ 3e-6 from step 1, with 3/4 of the nodes: 219/612 against 289/787).
inline constexpr double scale_grid_step = 2.0;
// A partner whose share of species k's collisions (n_i σ_ki² χ_ki √(θ_k + θ_i) μ_ik over the sum, at the reference
// temperatures) is below this gets the coarsest pair rule, 20 × 12 (tracer_diffusion_galerkin.hpp): the operator
// moves by ≤ 1.4e-6 of its largest entry (every pair coarse: 3.5e-4), far below the 60 × 36 rule's own 1e-3 for a
// light species (tests/theory/test_galerkin_decay.cpp). v1 Fig. 8: ~3/4 of its pairs; its MSDs move ≤ 5.5e-6, the
// whole-scene theory takes 14.5 s instead of 20.7 s (9.5 s together with the 40 × 24 rule of
// tracer_diffusion_galerkin.hpp).
inline constexpr double coarse_pair_share = 1e-3;
// A species whose basis is smooth on the scale of the velocities that meet (x₀ ≥ 1.5: its own pair rule 40 × 24 or
// coarser, tracer_diffusion_galerkin.hpp) loses far less to the coarse rule, so its partners take it up to this many
// times coarse_pair_share: the operator then moves by ≤ 6.8e-6 of its largest entry (1.4e-6 without; ×30: 1.8e-5,
// beyond the test's 1e-5; tests/theory/test_galerkin_decay.cpp), v1 Fig. 8's judged curves by ≤ 0.16% of the model
// error computed at each row (v1 Figs. 6, 8-θ4, 10 ≤ 0.07%, except a v1 Fig. 6 point where the computed part is
// 6.6e-7 and the scene's `relative` 1e-4), its judged level 2.6 s instead of 3.0 s. A light species (x₀ < 1.5)
// keeps 1e-3: at 3e-2 v1 Fig. 10's MSDs move by 2e-4.
inline constexpr double smooth_basis_share_factor = 10.0;
// From this many species a right-hand side assembles the species' operators on OpenMP threads (fewer: on the calling
// thread, whose work per right-hand side, ~N²·4·3·kept² entries, is smaller than a fork and join).
inline constexpr std::size_t parallel_species = 8;

// The pair tables of GalerkinDecay, kept apart from it so that the levels of one scene that solve the same Galerkin
// problem (the judged kinetic-converged-cooling3 and its `converged` companion, kinetic-converged: the same mixture and
// restitution, the same basis) build them once (scene_theory.cpp; v1 Fig. 8: ~3/4 of each converged level's time is
// its tables). The tables depend on the mixture, the restitution law and the basis, the basis on T_ref and the size:
// a store serves the decays of one scene built with one T_ref, size and coarse share (any other gets tables of its own).
struct GalerkinPairTables {
  using Node = std::pair<long, long>;              // grid indices in ln θ_k (0 at constant ε) and ln ρ
  using Sources = std::array<Eigen::MatrixXd, 3>;  // Ã of G⁰, G², G³, over √(2θ_k)
  // One node's three sources over √(λ + ρ) (pair_grid_step), one after the other (kept² entries each, column-major), in
  // single precision: a right-hand side of v1 Fig. 8 reads ~7 400 nodes (11 MB in double, beyond the caches; its
  // kinetic level on one thread takes 2.15 s in single, 2.26 s in double), and their rounding, 6e-8 of an entry, is ~200×
  // below the interpolation's error (1.2e-5 of the operator).
  using Value = float;
  using Stored = std::vector<Value>;
  std::vector<double> T_ref;
  std::size_t size = 0;
  double coarse_share = 0.0;
  std::vector<std::map<Node, Stored>> pairs;  // per ordered pair (k·N + i): node ↦ sources
};

class GalerkinDecay final : public VelocityDecay {
 public:
  // T_ref: the temperatures that fix each species' basis (x₀), whether it is diffusive and the partners' shares. tables:
  // a store shared with other decays of the same scene (null, or one built for another T_ref, size or coarse share:
  // tables of its own). coarse_share: coarse_pair_share (0: every pair at its basis's rule).
  GalerkinDecay(const CollisionRates& rates, const std::vector<double>& T_ref, std::size_t size = converged_diffusion_basis,
                std::shared_ptr<GalerkinPairTables> tables = nullptr, double coarse_share = coarse_pair_share);
  void rates(const double* T, const double* xi, double* nu) const override;  // the first-Sonine ν_k
  std::size_t modes() const override { return size_; }
  bool uses_sonine_coefficients() const override { return true; }
  void correlation_rates(const CollisionRates& r, const double* T, const double* xi, const double* Q, double* dQ, double* nu,
                         const double* a2, const double* a3) const override;
  bool offers_correlation_jacobian() const override { return true; }
  void correlation_jacobian_times(const double* v, double* Jv) const override;  // −(Ã + ξ_k/2) v per species, kept from the last call
  // Ã_coll of species k at the temperatures T and shapes a2, a3 (null: Maxwellian), interpolated; for tests.
  Eigen::MatrixXd collision_operator(std::size_t k, const double* T, const double* a2, const double* a3) const;
  // The same assembled directly (no table): the interpolation's reference.
  Eigen::MatrixXd collision_operator_exact(std::size_t k, const double* T, const double* a2, const double* a3) const;

 private:
  using Sources = GalerkinPairTables::Sources;
  struct Species {
    RadialBasis basis;
    Eigen::MatrixXd W, Winv;  // coordinates: Ã = Winv·Xᵀ·W for an assembled X; W = ΦHΔ⁻¹, Winv = ΔHΦᵀ
    Eigen::MatrixXd S;        // Ã of the scaling matrix
    std::array<Eigen::VectorXd, 3> s;
    std::size_t kept = 0;
    bool diffusive = true;
    bool smooth = false;  // x₀ past the finest pair rule's tier (smooth_basis_share_factor, smooth_basis_grid_step)
  };
  using Node = GalerkinPairTables::Node;
  struct Term {  // one node of a pair's stencil at the current state
    const GalerkinPairTables::Value* sources;  // GalerkinPairTables::Stored
    double weight;
  };
  static constexpr std::size_t all_species = std::size_t(-1);
  Sources pair_sources(std::size_t k, std::size_t i, double theta_k, double rho) const;  // assembled, transformed, over √(2θ_k)
  void stencil(std::size_t k, std::size_t i, const double* T, std::vector<std::pair<Node, double>>& out) const;  // appends nodes, weights at T
  // The stencils of every pair of the diffusive species (or of `species` alone) at T into terms_, the nodes the tables
  // lack computed first, together on OpenMP threads.
  void prefetch(const double* T, std::size_t species = all_species) const;
  void compute(const std::vector<std::pair<std::size_t, Node>>& missing) const;  // pair k·N + i and node, into the tables
  double grid_step(std::size_t pair) const;  // in ln ρ: pair_grid_step, smooth_basis_grid_step or the coarse pairs'
  double first_sonine_rate(std::size_t k, const double* T, const double* xi) const;  // ν_k = τ_v,k⁻¹ + ξ_k/2
  void add_collisions(std::size_t k, const double* T, const double* a2, const double* a3, bool exact, Eigen::MatrixXd& out) const;

  const CollisionRates& rates_;
  std::size_t size_;
  std::vector<Species> species_;
  bool viscoelastic_;
  std::vector<bool> coarse_;  // per pair k·N + i: the coarsest pair rule (coarse_pair_share)
  std::shared_ptr<GalerkinPairTables> tables_;  // filled as the history reaches new nodes (prefetch)
  mutable std::vector<std::pair<Node, double>> stencils_;  // prefetch's, all pairs together
  mutable std::vector<Term> terms_;                         // pair p's: terms_[first_term_[p] … first_term_[p + 1])
  mutable std::vector<std::size_t> first_term_;
  mutable std::vector<std::pair<Node, double>> last_stencils_;  // the previous prefetch's, whose pointers a pair may keep
  mutable std::vector<Term> last_terms_;
  mutable std::vector<std::size_t> last_first_term_;
  mutable std::vector<bool> relook_;  // per pair: its stencil's nodes changed since the previous prefetch
  mutable std::vector<Eigen::MatrixXd> linear_;  // per species, the last correlation_rates's −(Ã + ξ_k/2) (1×1 −ν_k if not diffusive)
  mutable Eigen::VectorXd u_, du_;
};

}  // namespace granmix::theory
