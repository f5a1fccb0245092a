#include "theory/grid/speed_grid_cooling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "theory/numerics/catmull_rom.hpp"
#include "model/errors.hpp"

namespace granmix::theory {

SpeedGridCooling::SpeedGridCooling(const CollisionRates& rates, int partner_order, SpeedGridSettings grid, std::vector<double> z0)
    : rates_(rates),
      N_(rates.size()),
      K_(std::size_t(std::ceil(grid.widths * grid.knots))),
      nb_(K_ + 3),
      partner_order_(partner_order),
      step_(grid.ratio_step),
      widths_(grid.widths),
      rule_(grid.rule_points),
      tables_(N_ * N_) {
  if (rates.law().is_viscoelastic())
    throw std::invalid_argument("speed-grid temperatures: constant restitution only (a viscoelastic eps(u) has no scale-free pair operator)");
  if (partner_order != 2 && partner_order != 3) throw std::invalid_argument("speed-grid temperatures: partner order 2 or 3");
  for (std::size_t k = 0; k < N_; ++k) {
    // The frame's own grid (drift, Gram, moments do not depend on the partner): any pair's assembly.
    grids_.push_back(assemble_speed_grid(speed_grid_pair(rates, k, k, 1.0, {}), domain(k), K_, rule_,
                                         SpeedGridParts::density));
    gram_.emplace_back(grids_[k].gram);
    if (gram_[k].info() != Eigen::Success) throw NumericalError("speed-grid temperatures: the Gram matrix (Eigen LDLT) failed");
    c2_.push_back(gram_[k].solve(grids_[k].u2));
  }
  a2_.resize(Eigen::Index(N_)), a3_.resize(Eigen::Index(N_));
  if (!z0.empty() && z0.size() != state_size()) throw std::invalid_argument("speed-grid temperatures: the start has the wrong number of spline coefficients");
  z0_ = std::move(z0);
}

double SpeedGridCooling::domain(std::size_t k) const { return widths_ / std::sqrt(rates_.mixture()[k].mass); }

const SpeedGridCooling::Sources& SpeedGridCooling::node(std::size_t k, std::size_t j, long at) const {
  std::map<long, Sources>& table = tables_[k * N_ + j];
  const auto found = table.find(at);
  if (found != table.end()) return found->second;
  const double rho = std::exp(double(at) * step_);
  const PartnerShape shapes[3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  Sources s;
  for (std::size_t q = 0; q < 3; ++q)
    s[q] = assemble_speed_grid(speed_grid_pair(rates_, k, j, rho, shapes[q]), domain(k), K_, rule_,
                               SpeedGridParts::density)
               .collisions;
  return table.emplace(at, std::move(s)).first->second;
}

SpeedMoments SpeedGridCooling::moments(std::size_t k, const double* z) const {
  const Eigen::Map<const Eigen::VectorXd> P(z + k * nb_, Eigen::Index(nb_));
  SpeedGridProblem own{};
  own.m2 = rates_.mixture()[k].mass;
  return speed_moments(grids_[k], own, P);
}

void SpeedGridCooling::initial_state(const double*, double rtol, double* z, double* atol) const {
  // DSMC's start: every species Maxwellian (at its frame's T = 1), or the given densities. The coefficients are O(√m_k)
  // (a density in u): the Maxwellian's largest sets the absolute tolerance.
  for (std::size_t k = 0; k < N_; ++k) {
    const Eigen::VectorXd P = maxwellian_speed_density(grids_[k], rates_.mixture()[k].mass, 1.0);
    const double scale = P.cwiseAbs().maxCoeff();
    for (std::size_t i = 0; i < nb_; ++i)
      z[k * nb_ + i] = z0_.empty() ? P[Eigen::Index(i)] : z0_[k * nb_ + i], atol[k * nb_ + i] = rtol * scale;
  }
}

void SpeedGridCooling::rates(const double* T, const double* z, double* xi, double* dz_dt) const {
  for (std::size_t j = 0; j < N_; ++j) {
    const SpeedMoments m = moments(j, z);
    a2_[Eigen::Index(j)] = m.a2, a3_[Eigen::Index(j)] = partner_order_ == 3 ? m.a3 : 0.0;
  }
  const bool same_T = products_T_.size() == N_ && std::equal(T, T + N_, products_T_.begin());
  if (!same_T) products_T_.assign(T, T + N_), products_.resize(N_ * N_);
  const std::vector<double> cached_z = same_T ? std::move(products_z_) : std::vector<double>{};
  products_z_.clear();  // until this call's products are all made (a throw below leaves nothing to reuse)
  const std::size_t shapes = partner_order_ == 3 ? 3 : 2;
  for (std::size_t k = 0; k < N_; ++k) {
    const Eigen::Map<const Eigen::VectorXd> P(z + k * nb_, Eigen::Index(nb_));
    const bool same_P = !cached_z.empty() && std::equal(z + k * nb_, z + (k + 1) * nb_, cached_z.begin() + std::ptrdiff_t(k * nb_));
    if (!same_P)
      for (std::size_t j = 0; j < N_; ++j) {
        const CatmullRom r = catmull_rom(std::log(T[j] / T[k]) / step_, "speed-grid temperatures: temperature ratio");
        std::array<Eigen::VectorXd, 3>& v = products_[k * N_ + j];
        for (std::size_t q = 0; q < shapes; ++q) v[q].setZero(Eigen::Index(nb_));
        for (int n = 0; n < r.count; ++n) {
          const Sources& s = node(k, j, r.first + n);
          for (std::size_t q = 0; q < shapes; ++q) v[q].noalias() += r.w[n] * (s[q] * P);
        }
      }
    work_.setZero(Eigen::Index(nb_));
    for (std::size_t j = 0; j < N_; ++j) {
      const std::array<Eigen::VectorXd, 3>& v = products_[k * N_ + j];
      const double shape[3] = {1.0, a2_[Eigen::Index(j)], a3_[Eigen::Index(j)]};
      for (std::size_t q = 0; q < shapes; ++q) work_.noalias() += shape[q] * v[q];
    }
    const double scale = std::sqrt(T[k]);
    Eigen::VectorXd drift = grids_[k].drift * P;
    xi[k] = -2.0 * scale * c2_[k].dot(work_) / c2_[k].dot(drift);
    if (xi[k] > 0.0) {  // the drift flows out at U: its boundary term (upwind; speed_grid.hpp SpeedGrid::edge)
      drift -= (domain(k) * grids_[k].edge.dot(P)) * grids_[k].edge;
      xi[k] = -2.0 * scale * c2_[k].dot(work_) / c2_[k].dot(drift);
    }
    if (dz_dt == nullptr) continue;
    const Eigen::VectorXd rhs = scale * work_ + 0.5 * xi[k] * drift;
    Eigen::Map<Eigen::VectorXd>(dz_dt + k * nb_, Eigen::Index(nb_)) = gram_[k].solve(rhs);
  }
  products_z_.assign(z, z + N_ * nb_);
}

bool SpeedGridCooling::cumulants(const double*, const double* z, double* c) const {
  for (std::size_t k = 0; k < N_; ++k) c[k] = 2.0 * moments(k, z).a2;
  return true;
}

bool SpeedGridCooling::third_sonine(const double* z, double* a3) const {
  for (std::size_t k = 0; k < N_; ++k) a3[k] = moments(k, z).a3;
  return true;
}

}  // namespace granmix::theory
