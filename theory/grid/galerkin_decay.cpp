#include "theory/grid/galerkin_decay.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <string>

#include "theory/numerics/catmull_rom.hpp"
#include "model/errors.hpp"
#include "theory/numerics/parallel_each.hpp"
#include "theory/numerics/vector_clones.hpp"

namespace granmix::theory {

namespace {

constexpr double weight_temperature = 2.0;  // λ of the test weight (tracer_diffusion_galerkin.hpp: why 2)
// add_collisions requests the cache lines of the node this many terms ahead (v1 Fig. 8 on one thread:
// none 2.43 s, 1 ahead 2.19, 2 ahead 2.16–2.26, 4 ahead 2.17–2.26 — the nodes lie apart in memory, 768 bytes each).
constexpr std::size_t prefetch_ahead = 2;

// o[e] += c0·s[e] + c2·s[E + e] + c3·s[2E + e], E = entries: one table node's three sources (elementwise, in double:
// the same numbers in every build).
GRANMIX_VECTOR_CLONES void add_node(double* o, std::size_t entries, double c0, double c2, double c3, const GalerkinPairTables::Value* s) {
  const GalerkinPairTables::Value *s2 = s + entries, *s3 = s + 2 * entries;
  for (std::size_t e = 0; e < entries; ++e) o[e] += c0 * double(s[e]) + c2 * double(s2[e]) + c3 * double(s3[e]);
}

}  // namespace

GalerkinDecay::GalerkinDecay(const CollisionRates& rates, const std::vector<double>& T_ref, std::size_t size,
                             std::shared_ptr<GalerkinPairTables> tables, double coarse_share)
    : rates_(rates), size_(size), viscoelastic_(rates.law().is_viscoelastic()) {
  const std::size_t N = rates.size();
  const bool compatible =
      tables && (tables->pairs.empty() || (tables->T_ref == T_ref && tables->size == size && tables->coarse_share == coarse_share));
  tables_ = compatible ? std::move(tables) : std::make_shared<GalerkinPairTables>();
  if (tables_->pairs.empty()) tables_->T_ref = T_ref, tables_->size = size, tables_->coarse_share = coarse_share, tables_->pairs.resize(N * N);
  for (std::size_t k = 0; k < N; ++k) {
    Species sp;
    sp.basis = collision_weighted_basis(size, converged_basis_x0(rates, k, T_ref.data()));
    sp.smooth = sp.basis.hermite_points < RadialBasis{}.hermite_points;
    const GalerkinAverages avg = galerkin_averages(sp.basis, weight_temperature);
    const Eigen::MatrixXd Phi = m_orthonormal_basis(avg.M);
    sp.kept = std::size_t(Phi.cols());
    // H y₀ = α e₁ for y₀ = ΦᵀMe₀ (the coordinates of B₀ = 1), v = y₀ − α e₁ with α of the sign that avoids cancellation.
    const Eigen::VectorXd y0 = Phi.transpose() * avg.M.col(0);
    const double alpha = y0[0] > 0.0 ? -y0.norm() : y0.norm();
    Eigen::VectorXd v = y0;
    v[0] -= alpha;
    const auto n = Eigen::Index(sp.kept);
    const Eigen::MatrixXd H = Eigen::MatrixXd::Identity(n, n) - 2.0 * v * v.transpose() / v.squaredNorm();
    Eigen::VectorXd delta = Eigen::VectorXd::Ones(n);
    delta[0] = alpha;
    sp.Winv = delta.asDiagonal() * H * Phi.transpose();
    sp.W = Phi * H * delta.cwiseInverse().asDiagonal();
    sp.S = sp.Winv * avg.S.transpose() * sp.W;
    for (int j = 0; j < 3; ++j) sp.s[std::size_t(j)] = sp.Winv * avg.r[j];
    species_.push_back(std::move(sp));
  }
  linear_.resize(N);
  // Each partner's share of species k's collisions at the reference state: the rare ones get the coarse pair rule.
  const model::Mixture& mix = rates.mixture();
  coarse_.assign(N * N, false);
  for (std::size_t k = 0; k < N; ++k) {
    std::vector<double> share(N);
    double sum = 0.0;
    for (std::size_t i = 0; i < N; ++i) {
      const double s = mix.sigma(k, i);
      sum += share[i] = mix[i].density * s * s * rates.chi(k, i) * std::sqrt(T_ref[k] / mix[k].mass + T_ref[i] / mix[i].mass) *
                        mix[i].mass / (mix[i].mass + mix[k].mass);
    }
    const double limit = coarse_share * (species_[k].smooth ? smooth_basis_share_factor : 1.0);
    for (std::size_t i = 0; i < N; ++i) coarse_[k * N + i] = share[i] < limit * sum;
  }
  // Diffusive at the reference state (Maxwellian partners, ζ = ξ_k): every eigenvalue of Ã decays (Ã is similar to
  // the settled problem's K of galerkin_memory).
  std::vector<double> xi(N);
  rates.xi_all(T_ref.data(), xi.data());
  prefetch(T_ref.data());
  for (std::size_t k = 0; k < N; ++k) {
    Species& sp = species_[k];
    const Eigen::MatrixXd A = collision_operator(k, T_ref.data(), nullptr, nullptr) - 0.5 * xi[k] * sp.S;
    const Eigen::EigenSolver<Eigen::MatrixXd> es(A, false);
    if (es.info() != Eigen::Success) throw NumericalError("converged velocity memory: eigenvalues (Eigen EigenSolver) failed");
    for (Eigen::Index j = 0; j < es.eigenvalues().size(); ++j) sp.diffusive = sp.diffusive && es.eigenvalues()[j].real() > 0.0;
  }
}

GalerkinDecay::Sources GalerkinDecay::pair_sources(std::size_t k, std::size_t i, double theta_k, double rho) const {
  // At constant ε the pair problem at θ_k = 1/2 (√(2θ_k) = 1) serves every θ_k; a viscoelastic ε(u) needs the true θ_k.
  const Species& sp = species_[k];
  const auto n = Eigen::Index(size_);
  const PartnerShape shapes[3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  Eigen::MatrixXd G[3] = {Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  const double th = viscoelastic_ ? theta_k : 0.5;
  RadialBasis basis = sp.basis;
  if (coarse_[k * rates_.size() + i]) basis.hermite_points = 20, basis.laguerre_points = 12, basis.speed_points = coarse_speed_points;
  add_pair_collisions(rates_, k, i, th, rho * th, basis, weight_temperature, shapes, 3, G);
  Sources out;
  const double unscale = 1.0 / std::sqrt(2.0 * th);
  for (std::size_t j = 0; j < 3; ++j) out[j] = unscale * (sp.Winv * G[j].transpose() * sp.W);
  return out;
}

double GalerkinDecay::grid_step(std::size_t pair) const {
  if (coarse_[pair]) return coarse_grid_factor * pair_grid_step;
  return species_[pair / rates_.size()].smooth ? smooth_basis_grid_step : pair_grid_step;
}

void GalerkinDecay::stencil(std::size_t k, std::size_t i, const double* T, std::vector<std::pair<Node, double>>& out) const {
  const model::Mixture& mix = rates_.mixture();
  const double theta_k = T[k] / mix[k].mass, rho = T[i] / mix[i].mass / theta_k;
  const CatmullRom r = catmull_rom(std::log(rho) / grid_step(k * rates_.size() + i), "converged velocity memory: temperature ratio");
  const CatmullRom h = viscoelastic_ ? catmull_rom(std::log(theta_k) / scale_grid_step, "converged velocity memory: temperature")
                                    : CatmullRom{0, 1, {1.0, 0.0, 0.0, 0.0}};
  const double flux = std::sqrt(weight_temperature + rho);  // the tables hold each source over it (pair_grid_step)
  for (int a = 0; a < h.count; ++a)
    for (int j = 0; j < r.count; ++j) out.push_back({{h.first + a, r.first + j}, flux * h.w[a] * r.w[j]});
}

void GalerkinDecay::prefetch(const double* T, std::size_t species) const {
  // The nodes the assembly needs and the tables lack, computed together on OpenMP threads (each node wholly on one
  // thread: the numbers do not depend on the thread count). A history moves every pair's ratio at once, so most new
  // nodes come in batches. Then each pair's terms point into the tables (std::map nodes stay where they are); a pair
  // whose stencil has the nodes of the last call keeps that call's pointers (most right-hand sides move no pair to a
  // new cell: the lookups would be 8% of v1 Fig. 8's time).
  const std::size_t N = rates_.size();
  std::swap(stencils_, last_stencils_), std::swap(terms_, last_terms_), std::swap(first_term_, last_first_term_);
  const bool have_last = last_first_term_.size() == N * N + 1;
  stencils_.clear();
  first_term_.assign(N * N + 1, 0);
  relook_.assign(N * N, false);
  std::vector<std::pair<std::size_t, Node>> missing;  // pair k·N + i, node
  for (std::size_t k = 0; k < N; ++k) {
    const bool wanted = species == all_species ? species_[k].diffusive : k == species;
    for (std::size_t i = 0; i < N; ++i) {
      const std::size_t p = k * N + i, from = stencils_.size();
      if (wanted) stencil(k, i, T, stencils_);
      first_term_[p + 1] = stencils_.size();
      const std::size_t count = stencils_.size() - from;
      bool same = have_last && last_first_term_[p + 1] - last_first_term_[p] == count;
      for (std::size_t j = 0; same && j < count; ++j) same = stencils_[from + j].first == last_stencils_[last_first_term_[p] + j].first;
      if (same) continue;
      relook_[p] = true;
      for (std::size_t j = from; j < stencils_.size(); ++j)
        if (!tables_->pairs[p].count(stencils_[j].first)) missing.push_back({p, stencils_[j].first});  // a pair's stencil nodes are distinct
    }
  }
  if (!missing.empty()) compute(missing);
  terms_.resize(stencils_.size());
  for (std::size_t p = 0; p < N * N; ++p)
    for (std::size_t j = first_term_[p], last = have_last ? last_first_term_[p] : 0; j < first_term_[p + 1]; ++j, ++last)
      terms_[j] = {relook_[p] ? tables_->pairs[p].find(stencils_[j].first)->second.data() : last_terms_[last].sources, stencils_[j].second};
}

void GalerkinDecay::compute(const std::vector<std::pair<std::size_t, Node>>& missing) const {
  const std::size_t N = rates_.size();
  std::vector<GalerkinPairTables::Stored> computed(missing.size());
  parallel_each(missing.size(), [&](std::size_t m) {
    const Node& at = missing[m].second;
    const double rho = std::exp(double(at.second) * grid_step(missing[m].first));
    const Sources s = pair_sources(missing[m].first / N, missing[m].first % N, std::exp(double(at.first) * scale_grid_step), rho);
    const double unflux = 1.0 / std::sqrt(weight_temperature + rho);
    const auto entries = std::size_t(s[0].size());
    computed[m].resize(3 * entries);
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t e = 0; e < entries; ++e) computed[m][j * entries + e] = GalerkinPairTables::Value(s[j].data()[e] * unflux);
  });
  for (std::size_t m = 0; m < missing.size(); ++m) tables_->pairs[missing[m].first].emplace(missing[m].second, std::move(computed[m]));
}

// exact: assembled directly at T; else from the terms of the last prefetch (at T).
void GalerkinDecay::add_collisions(std::size_t k, const double* T, const double* a2, const double* a3, bool exact, Eigen::MatrixXd& out) const {
  const model::Mixture& mix = rates_.mixture();
  const std::size_t N = mix.size();
  const double theta_k = T[k] / mix[k].mass, scale = std::sqrt(2.0 * theta_k);
  for (std::size_t i = 0; i < N; ++i) {
    const double w[3] = {scale, scale * (a2 ? a2[i] : 0.0), scale * (a3 ? a3[i] : 0.0)};
    if (exact) {
      const Sources s = pair_sources(k, i, theta_k, T[i] / mix[i].mass / theta_k);
      for (std::size_t j = 0; j < 3; ++j) out += w[j] * s[j];
      continue;
    }
    // The three sources of each node in one pass over the entries (this loop reads ~N²·4 nodes per right-hand side,
    // each apart in memory: the node `ahead` terms on is fetched meanwhile, its cache lines requested now).
    double* o = out.data();
    const std::size_t entries = std::size_t(out.size()), last = first_term_[k * N + N];
    for (std::size_t j = first_term_[k * N + i]; j < first_term_[k * N + i + 1]; ++j) {
      if (j + prefetch_ahead < last) {
        const char* next = reinterpret_cast<const char*>(terms_[j + prefetch_ahead].sources);
        for (std::size_t b = 0; b < 3 * entries * sizeof(GalerkinPairTables::Value); b += 64) __builtin_prefetch(next + b);
      }
      add_node(o, entries, w[0] * terms_[j].weight, w[1] * terms_[j].weight, w[2] * terms_[j].weight, terms_[j].sources);
    }
  }
}

Eigen::MatrixXd GalerkinDecay::collision_operator(std::size_t k, const double* T, const double* a2, const double* a3) const {
  const auto n = Eigen::Index(species_[k].kept);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  prefetch(T, k);
  add_collisions(k, T, a2, a3, false, out);
  return out;
}

Eigen::MatrixXd GalerkinDecay::collision_operator_exact(std::size_t k, const double* T, const double* a2, const double* a3) const {
  const auto n = Eigen::Index(species_[k].kept);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
  add_collisions(k, T, a2, a3, true, out);
  return out;
}

double GalerkinDecay::first_sonine_rate(std::size_t k, const double* T, const double* xi) const {
  return 0.5 * xi[k] + rates_.inv_tau_v_species(k, T);
}

void GalerkinDecay::rates(const double* T, const double* xi, double* nu) const {
  for (std::size_t k = 0; k < rates_.size(); ++k) nu[k] = first_sonine_rate(k, T, xi);
}

void GalerkinDecay::correlation_rates(const CollisionRates&, const double* T, const double* xi, const double* Q, double* dQ, double*,
                                      const double* a2, const double* a3) const {
  const std::size_t N = rates_.size();
  prefetch(T);
  // The species on OpenMP threads, each wholly on one (its operator reads the tables, ~N·4 nodes of 3 kept² entries:
  // memory-bound, 2 s of v1 Fig. 8's 43 species on one thread); a few species on the calling thread (v1 Fig. 3-aged's
  // two: 51 s against 3 s on a loaded machine, the other thread spinning at every right-hand side's join).
  parallel_each(N, [&](std::size_t k) {
    const Species& sp = species_[k];
    const double theta = T[k] / rates_.mixture()[k].mass;
    Eigen::MatrixXd& L = linear_[k];
    if (!sp.diffusive) {  // no diffusive solution: first-Sonine ν_k, the other unknowns decoupled
      const double nu1 = first_sonine_rate(k, T, xi);
      L.setConstant(1, 1, -nu1);
      dQ[k] = 3.0 * theta - nu1 * Q[k];
      for (std::size_t p = 1; p < size_; ++p) dQ[p * N + k] = -nu1 * Q[p * N + k];
      return;
    }
    const auto n = Eigen::Index(sp.kept);
    L.setZero(n, n);
    add_collisions(k, T, a2, a3, false, L);
    L -= 0.5 * xi[k] * sp.S;
    L.diagonal().array() += 0.5 * xi[k];
    L = -L;
    Eigen::VectorXd u(n);
    for (Eigen::Index p = 0; p < n; ++p) u[p] = Q[std::size_t(p) * N + k];
    Eigen::VectorXd du = L * u;
    du += 2.0 * theta * (sp.s[0] + (a2 ? a2[k] : 0.0) * sp.s[1] + (a3 ? a3[k] : 0.0) * sp.s[2]);
    for (Eigen::Index p = 0; p < n; ++p) dQ[std::size_t(p) * N + k] = du[p];
    for (std::size_t p = sp.kept; p < size_; ++p) dQ[p * N + k] = 0.0;  // unknowns beyond the kept span stay 0
  }, N >= parallel_species);
}

void GalerkinDecay::correlation_jacobian_times(const double* v, double* Jv) const {
  const std::size_t N = rates_.size();
  for (std::size_t k = 0; k < N; ++k) {
    const Eigen::MatrixXd& L = linear_[k];
    if (!species_[k].diffusive) {
      for (std::size_t p = 0; p < size_; ++p) Jv[p * N + k] = L(0, 0) * v[p * N + k];
      continue;
    }
    const Eigen::Index n = L.rows();
    u_.resize(n);
    for (Eigen::Index p = 0; p < n; ++p) u_[p] = v[std::size_t(p) * N + k];
    du_.noalias() = L * u_;
    for (Eigen::Index p = 0; p < n; ++p) Jv[std::size_t(p) * N + k] = du_[p];
    for (std::size_t p = species_[k].kept; p < size_; ++p) Jv[p * N + k] = 0.0;
  }
}

}  // namespace granmix::theory
