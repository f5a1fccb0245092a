#pragma once
// The settled D_k/D_1 of kinetic-converged's tracer problem (tracer_diffusion_galerkin.hpp) at a converged HCS state
// (converged_hcs.hpp), and its computed model error: the level kinetic-converged-hcs's D ratios and what a scene judges
// them with (error_column = "D_ratio_error", docs/scenes.md).
#include <vector>

#include "theory/rates/collision_rates.hpp"
#include "theory/grid/converged_hcs.hpp"

namespace granmix::theory {

// D_k/D_1 (species 1: 1) with the state's T_k, a₂,k, a₃,k as the species' and partners' shapes and its one ζ as the
// scaling rate. basis: per species, the tracer problem's own truncation of the ratio, |D(size) − D(size − 1)|/D of
// species k and of species 1, summed (species 1: 0). full_shapes: the state's solved densities themselves as the
// partners' shapes and the species' sources instead of a₂, a₃ (partner_axial_shape.hpp).
std::vector<double> converged_d_ratios(const CollisionRates& rates, const SettledHcs& state, std::vector<double>* basis = nullptr,
                                       bool full_shapes = false);

// The relative model error of each D_k/D_1 (species 1: 0), the sum of four computed parts, each a relative change of
// the ratio: the HCS grid's (twice the largest change with knots 3/2 apart, the 16-point rule or the domain 9/7 as
// wide), the HCS partners' truncation (partners through their full solved densities
// against a₂, a₃: converged_hcs.hpp), the tracer problem's partners' (every partner's shape and the species' own source
// from the solved densities against a₂, a₃), its basis (one
// function fewer). checked: converged_hcs(rates, true).
struct ConvergedRatioError {
  std::vector<double> grid, hcs_partners, partners, basis;  // per species
  std::vector<double> total() const;
};
ConvergedRatioError converged_d_ratio_error(const CollisionRates& rates, const ConvergedHcs& checked);

}  // namespace granmix::theory
