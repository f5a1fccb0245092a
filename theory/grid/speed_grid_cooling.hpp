#pragma once
// The temperatures in time without the Sonine truncation of the species' own distributions: every species'
// speed density on the cubic B-splines of the converged HCS (speed_grid.hpp, converged_hcs.hpp) integrated with
// the temperatures, from DSMC's Maxwellian start. Why: in time the Sonine series is asymptotic where a light species
// runs far from its partners' temperature — v1 Fig. 2's light species at t = 10: orders 2 / 3 / 4 of the temperatures
// (sonine_moment_cooling.hpp) give −3.8 / 0 / −3.4% against DSMC's −0.9%, so order 3 carries a model error of
// 4.0% there (the larger of its last and next corrections) that no further order removes.
//
// Species k's density P_k(u) lives in its own frame, velocities scaled by √(1/T_k(t)) so that its temperature there is
// 1 (U = speed_grid_history_widths/√m_k, speed_grid_history_knots per width, the 12-point collision rule). In that frame partner j is at
// the temperature ρ = T_j/T_k, and the real collisions run √T_k as fast as the frame's (hard spheres: the rate scales
// with the relative speed). The frame shrinks as T_k falls, an outward drift at ξ_k/2 (the HCS's ζ/2 term), so
//   gram dP_k/dt = [√T_k Σ_j C_kj(ρ; a₂,j, a₃,j) + (ξ_k/2) drift] P_k,     d ln T_k/dt = −ξ_k,
// with ξ_k the rate that keeps the frame's ⟨u²⟩ where it is (u² is in the splines' span, so c₂ = gram⁻¹u2 tests it
// exactly): ξ_k = −2√T_k c₂ᵀC P / c₂ᵀ drift P. Each partner j is seen as the converged HCS's solve sees it: a Maxwellian
// at its temperature times 1 + a₂,j S₂ + a₃,j S₃, its a's those of its own density now (the own species too: the
// collisions are bilinear, the partner's shape truncated, the species' own density not). C_kj is linear in the shape:
// three assembled operators per node of a grid in ln ρ (step `ratio_step`), interpolated by Catmull–Rom cubics (C¹ for
// CVODE's Newton iterations), the nodes assembled as the history reaches them.
// What is still truncated: the partners' shapes beyond a₃ (in the settled state the converged HCS computes that part
// with full partners: v1 Fig. 4's mixture T₂/T₁ −0.004% at n₂ = 0.1, −1.4% at n₂ = 0.01), and the grid.
// Constant restitution only (a viscoelastic ε(u) depends on the impact speed itself, so C_kj would need T_k too).
#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <map>
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/rates/cooling_model.hpp"
#include "theory/grid/speed_grid.hpp"

namespace granmix::theory {

// The grid step in ln(T_j/T_k) of the pair operators' tables: half of it moves v1 Fig. 6's temperatures by ≤ 3.6e-6
// relative along the history.
inline constexpr double speed_grid_ratio_step = 0.0625;

// The history's domain in thermal widths of each species' frame. Wider than the stationary solves' 7: in the transient
// a light species among hot heavy partners grows an overpopulated tail (v1 Fig. 6 at t = 1: P(7 widths) = 1.4e-5, 1e4
// times the Maxwellian's), whose mass leaves a 7-width domain (1.7e-4 of the light species' by t = 1e3) and moves its T
// by up to 4.5e-4; at 9 widths the tail left is 1.5e-6 and 11 widths move T by ≤ 6e-6.
inline constexpr double speed_grid_history_widths = 9.0;
// Knots per thermal width of the history's grid: fewer than the stationary solves' 8, since the history's cost grows as
// (knots)³ (CVODE's dense Jacobian of all the species' splines) and its temperatures do not need them: from 5 to 8
// knots v1 Fig. 6's move by ≤ 2.2e-7, from 5 to 4 by ≤ 2.4e-6, from 8 to 12 by ≤ 1e-7; 0.6 s against 8 knots' 1.8 s.
inline constexpr double speed_grid_history_knots = 5.0;

// The grid (defaults: the history's domain and knots, the stationary solves' collision rule); the error estimate's
// variants change it.
struct SpeedGridSettings {
  double widths = speed_grid_history_widths, knots = speed_grid_history_knots, ratio_step = speed_grid_ratio_step;
  std::size_t rule_points = speed_grid_rule_points;
};

class SpeedGridCooling final : public CoolingModel {
 public:
  // rates: constant restitution (std::invalid_argument otherwise). partner_order 3: partners through a₂ and a₃; 2: a₂
  // alone (the a₃ term's size: a cruder estimate of the partners' truncation than converged_hcs's full partners).
  // z0: the densities at t = 0 (empty: every species Maxwellian, DSMC's start; an aged start: those of the same history
  // at the end of the ageing, theory_level.cpp).
  explicit SpeedGridCooling(const CollisionRates& rates, int partner_order = 3, SpeedGridSettings grid = {}, std::vector<double> z0 = {});
  // z: the species' spline coefficients, species after species (K + 3 each).
  std::size_t state_size() const override { return N_ * nb_; }
  void initial_state(const double* T0, double rtol, double* z, double* atol) const override;
  void rates(const double* T, const double* z, double* xi, double* dz_dt) const override;
  bool cumulants(const double* T, const double* z, double* c) const override;  // c_k = 2a₂,k of each density
  bool third_sonine(const double* z, double* a3) const override;
  // Species k's moments of the density in z (θ = its frame temperature: 1 up to the integration's error).
  SpeedMoments moments(std::size_t k, const double* z) const;

 private:
  using Sources = std::array<Eigen::MatrixXd, 3>;  // C of the shapes 1, S₂, S₃
  const Sources& node(std::size_t k, std::size_t j, long at) const;
  double domain(std::size_t k) const;  // U of species k's frame: widths_ thermal widths at T = 1

  const CollisionRates& rates_;
  std::size_t N_, K_, nb_;
  int partner_order_;
  double step_, widths_;
  CollisionRule rule_;
  std::vector<SpeedGrid> grids_;              // per species: drift, Gram, moments (the frame at T = 1)
  std::vector<Eigen::LDLT<Eigen::MatrixXd>> gram_;
  std::vector<Eigen::VectorXd> c2_;           // gram⁻¹ u2: u² in the splines' span
  std::vector<double> z0_;
  mutable std::vector<std::map<long, Sources>> tables_;  // per pair k·N + j: ln ρ node ↦ sources
  mutable Eigen::VectorXd a2_, a3_, work_;
  // Each pair's shape products Σ_n w_n C_kj,q(node n) P_k (q = 1, S₂, S₃) at the T and P_k of the last call: a
  // difference-quotient Jacobian column moves one species' P_k alone, so only that species' N pairs are redone (not
  // N²); the right-hand side is the same sum either way, so the numbers do not depend on what was cached.
  mutable std::vector<std::array<Eigen::VectorXd, 3>> products_;
  mutable std::vector<double> products_T_, products_z_;
};

}  // namespace granmix::theory
