#include "theory/grid/tracer_diffusion_galerkin.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/errors.hpp"
#include "theory/grid/partner_axial_shape.hpp"
#include "theory/grid/point_kernels.hpp"
#include "theory/sonine/sonine_polynomials.hpp"
#include "theory/sonine/sonine_quadrature.hpp"

namespace granmix::theory {

namespace {

// Gauss points in W (Hermite) and |v_⊥|² (Laguerre) given the impact speed, and for the averages over f_w and f_k:
// the Sonine basis (degree ≤ 2·5 in each) is integrated exactly; the weighted basis's near-singular 1/√(c² + x₀)
// to 5e-4 of the factor (see the header).
// (collision_weighted_basis at large x₀ takes coarser rules: its tiers below; the averages keep the finest.)
struct Rules {
  GaussRule hermite, laguerre;
};
struct Tier {
  double x0;  // from this x₀ on
  std::size_t hermite, laguerre;
};
constexpr Tier tiers[] = {{0.0, 60, 36}, {1.5, 40, 24}, {4.0, 30, 16}, {15.0, 20, 12}};

// The rules of one tier's point counts, built once (thread-safe static initialisation).
const Rules& rules(std::size_t hermite, std::size_t laguerre) {
  static const std::vector<Rules> all = [] {
    std::vector<Rules> r;
    for (const Tier& t : tiers) r.push_back({golub_welsch(t.hermite, false), golub_welsch(t.laguerre, true)});
    return r;
  }();
  for (std::size_t j = 0; j < std::size(tiers); ++j)
    if (tiers[j].hermite == hermite && tiers[j].laguerre == laguerre) return all[j];
  throw std::invalid_argument("tracer diffusion Galerkin: no pair rule of " + std::to_string(hermite) + " x " + std::to_string(laguerre) + " points");
}
const Rules& finest_rules() { return rules(tiers[0].hermite, tiers[0].laguerre); }

constexpr std::size_t max_basis = 16;

// Row m of x dL_m/dx = m L_m − (m + 3/2) L_{m−1} (associated Laguerre, α = 3/2), plus h_p L_m(x_p) (h null: 0).
void x_derivative_row(const double* L, std::size_t count, std::size_t m, const double* h, double* out) {
  const double* Lm = L + m * count;
  if (m == 0) {
    for (std::size_t p = 0; p < count; ++p) out[p] = h ? h[p] : 0.0;
    return;
  }
  const double* Lm1 = L + (m - 1) * count;
  for (std::size_t p = 0; p < count; ++p) out[p] = double(m) * Lm[p] - (double(m) + 1.5) * Lm1[p] + (h ? h[p] * Lm[p] : 0.0);
}

// A factor along a run of points: one value for all (double), or an array's, times `scale`.
template <class T>
struct Along;
template <>
struct Along<double> {
  double v;
  double operator[](std::size_t) const { return v; }
};
template <>
struct Along<const double*> {
  const double* __restrict v;
  double scale = 1.0;
  double operator[](std::size_t j) const { return scale * v[j]; }  // 1 · v = v exactly
};

// The pair integrals' per-point columns: c², c′², w c², w c·c′.
struct PointColumns {
  double *x, *x1, *wx, *wcc;
  PointColumns at(std::size_t p) const { return {x + p, x1 + p, wx + p, wcc + p}; }
};

// n contiguous points: c² = r + q, c′² = r + q₁, w c², w (r + q_c) with w = w_a w_b, the factors given along the run
// (restrict: the loop vectorises; the same roundings as one point at a time).
template <class R, class Wa, class Wb, class Q>
[[gnu::always_inline]] inline void point_run(std::size_t n, PointColumns to, R r, Wa wa, Wb wb, Q q, Q q1, Q qc) {
  double *__restrict x = to.x, *__restrict x1 = to.x1, *__restrict wx = to.wx, *__restrict wcc = to.wcc;
#pragma GCC ivdep  // the factors' arrays are not the columns
  for (std::size_t j = 0; j < n; ++j) {
    const double rj = r[j], w = wb[j] * wa[j], c2 = rj + q[j];
    x[j] = c2, x1[j] = rj + q1[j], wx[j] = w * c2, wcc[j] = w * (rj + qc[j]);
  }
}

}  // namespace

RadialBasis sonine_radial_basis(std::size_t modes) {
  if (modes < 1 || modes > max_basis) throw std::invalid_argument("sonine_radial_basis: 1 to 16 functions");
  RadialBasis b{modes, [modes](const double* x, std::size_t count, double* B, double* xdB) {
                  laguerre_rows(x, count, modes, B);
                  if (xdB)
                    for (std::size_t m = 0; m < modes; ++m) x_derivative_row(B, count, m, nullptr, xdB + m * count);
                }};
  b.loss = [modes](const double* x1, std::size_t count, const double* B, const double* wx, const double* wcc, double* loss) {
    thread_local std::vector<double> B1;  // reused: a fresh one costs page faults at every call
    B1.resize(modes * count);
    laguerre_rows(x1, count, modes, B1.data());
    loss_rows(B, B1.data(), wx, wcc, modes, count, loss);
  };
  return b;
}

RadialBasis collision_weighted_basis(std::size_t size, double x0) {
  if (size < 2 || size > max_basis) throw std::invalid_argument("collision_weighted_basis: 2 to 16 functions");
  if (!(x0 >= 0.0 && std::isfinite(x0))) throw std::invalid_argument("collision_weighted_basis: x0 must be finite and >= 0");
  const Tier* tier = tiers;
  for (const Tier& t : tiers)
    if (x0 >= t.x0) tier = &t;
  RadialBasis b{size, [size, x0](const double* x, std::size_t count, double* B, double* xdB) {
            for (std::size_t p = 0; p < count; ++p) B[p] = 1.0;
            double* L = B + count;  // rows 1…: L_{m−1}, then weighted by r = (x + x₀)^(−1/2)
            if (!xdB) return weighted_laguerre_rows(x, count, x0, size - 1, L);  // the pair integrals' case: one pass
            laguerre_rows(x, count, size - 1, L);
            if (xdB) {
              thread_local std::vector<double> h;  // reused: a fresh one costs page faults at every call
              h.resize(count);
              for (std::size_t p = 0; p < count; ++p) h[p] = -0.5 * x[p] / (x[p] + x0);  // h = x d ln r/dx
              for (std::size_t p = 0; p < count; ++p) xdB[p] = 0.0;
              for (std::size_t m = 1; m < size; ++m) x_derivative_row(L, count, m - 1, h.data(), xdB + m * count);
              weight_rows(x, count, x0, 1, size, xdB);
            }
            weight_rows(x, count, x0, 1, size, B);
          },
          tier->hermite, tier->laguerre};
  b.loss = [size, x0](const double* x1, std::size_t count, const double* B, const double* wx, const double* wcc, double* loss) {
    collision_weighted_loss_rows(x1, count, x0, size, B, wx, wcc, loss);
  };
  return b;
}

void add_pair_collisions(const CollisionRates& rates, std::size_t k, std::size_t i, double theta_k, double theta_i, const RadialBasis& basis,
                         double weight_temperature, const PartnerShape* shapes, std::size_t count, Eigen::MatrixXd* out) {
  const model::Mixture& mix = rates.mixture();
  const double s = mix.sigma(k, i), weight = mix[i].density * s * s * rates.chi(k, i);
  if (weight == 0.0) return;
  const std::size_t N = basis.size;
  const Rules& g = rules(basis.hermite_points, basis.laguerre_points);
  const GaussRule& speed = half_range_rule(rates.law().is_viscoelastic() ? basis.impact_points : basis.speed_points);
  const double lam = weight_temperature, theta_w = lam * theta_k, inv2k = 0.5 / theta_k, inv2i = 0.5 / theta_i;
  const double mu = mix[i].mass / (mix[i].mass + mix[k].mass);
  const double V = theta_w + theta_i, alpha = theta_w / V, sW = std::sqrt(theta_w * theta_i / V);
  const double flux = weight * 4.0 * std::numbers::pi * std::sqrt(2.0 * V / std::numbers::pi);
  bool shaped = false;  // a Maxwellian partner alone: no shape factors to evaluate
  for (std::size_t j = 0; j < count; ++j)
    shaped = shaped || shapes[j].a2 != 0.0 || shapes[j].a3 != 0.0 || shapes[j].one != 1.0 || shapes[j].full != nullptr;
  // Given the impact speed, the (W, |v_⊥|²) grid's points are evaluated together and summed into A by one product,
  // A += B·Lᵀ with the loss columns L_p = w_p [c_p² B(c_p²) − c_p·c_p′ B(c_p′²)], i.e. Σ_p B_q · c·[c B_m(c²) − c′ B_m(c′²)].
  // A partner's shape factor depends on W alone (c_iz), so with shapes the points are laid out W fastest (p = l·Hs + h,
  // Hs = H rounded up to 4; the extra points weigh 0) and shaped_products weights each W's sums by every shape at once.
  const std::size_t H = g.hermite.x.size(), L = g.laguerre.x.size(), Hs = shaped ? (H + 3) / 4 * 4 : H, P = Hs * L;
  // reused (fresh ones cost page faults)
  thread_local std::vector<double> B, loss, sums, weights, lanes, shape_w, x, x1, wx, wcc, zk, zk1, wh, qk, qk1, qkk1;
  thread_local Eigen::VectorXd y;
  for (std::vector<double>* m : {&B, &loss}) m->resize(N * P);  // row-major, RadialBasis's layout
  for (std::vector<double>* v : {&x, &x1, &wx, &wcc}) v->resize(P);
  for (std::vector<double>* v : {&zk, &zk1, &wh, &qk, &qk1, &qkk1}) v->resize(Hs);
  y.resize(Eigen::Index(H));
  sums.assign(count * N * N, 0.0);  // every shape's products, row by row (point_kernels.hpp)
  weights.assign(count, 1.0);       // a Maxwellian partner's factor
  if (shaped) lanes.assign(count * N * N * 4, 0.0), shape_w.assign(count * Hs, 0.0);
  // The f_w-tracer and f_i pair given the impact speed u (sonine_quadrature.hpp), the partner's shape as
  // E[f_i/f_M,i | v_iz] (its perpendicular components do not reach the tracer's v′).
  for (std::size_t n = 0; n < speed.x.size(); ++n) {
    const double u = std::sqrt(2.0 * V) * speed.x[n], bu = mu * (1.0 + rates.law().eps_at(k, i, u)) * u;
    const double wn = flux * speed.weight[n];
    for (std::size_t h = 0; h < Hs; ++h) {  // v_kz before and after, the W weights (padding: any finite point of weight 0)
      const double W = h < H ? sW * g.hermite.x[h] : 0.0;
      zk[h] = W + alpha * u, zk1[h] = zk[h] - bu, wh[h] = h < H ? wn * g.hermite.weight[h] : 0.0;
      qk[h] = zk[h] * zk[h] * inv2k, qk1[h] = zk1[h] * zk1[h] * inv2k, qkk1[h] = zk[h] * zk1[h] * inv2k;  // their parts of c², c′², c·c′
      if (h < H) y[Eigen::Index(h)] = (W - (1.0 - alpha) * u) * (W - (1.0 - alpha) * u) * inv2i;  // c_iz²
    }
    // Point p = l·Hs + h with shapes (W fastest, each l's points contiguous), h·L + l without: each run of points
    // written by one contiguous loop (point_run: vectorised).
    const PointColumns to{x.data(), x1.data(), wx.data(), wcc.data()};
    if (shaped)
      for (std::size_t l = 0; l < L; ++l)  // r = |v_k⊥|²/(2θ_k) and the weight's factor w_l along the run
        point_run(Hs, to.at(l * Hs), Along<double>{lam * g.laguerre.x[l]}, Along<double>{g.laguerre.weight[l]}, Along<const double*>{wh.data()},
                  Along<const double*>{qk.data()}, Along<const double*>{qk1.data()}, Along<const double*>{qkk1.data()});
    else
      for (std::size_t h = 0; h < H; ++h)
        point_run(L, to.at(h * L), Along<const double*>{g.laguerre.x.data(), lam}, Along<const double*>{g.laguerre.weight.data()},
                  Along<double>{wh[h]}, Along<double>{qk[h]}, Along<double>{qk1[h]}, Along<double>{qkk1[h]});
    basis.eval(x.data(), P, B.data(), nullptr);
    basis.loss(x1.data(), P, B.data(), wx.data(), wcc.data(), loss.data());
    if (!shaped) {  // every shape Maxwellian: one product
      row_products(B.data(), loss.data(), P, N, 0, P, weights.data(), count, sums.data());
      continue;
    }
    for (std::size_t h = 0; h < H; ++h) {
      const double S2 = sonine_axial_S2(y[Eigen::Index(h)]), S3 = sonine_axial_S3(y[Eigen::Index(h)]);
      for (std::size_t j = 0; j < count; ++j)
        shape_w[j * Hs + h] = shapes[j].full ? shapes[j].full->at(y[Eigen::Index(h)]) : shapes[j].one + shapes[j].a2 * S2 + shapes[j].a3 * S3;
    }
    shaped_products(B.data(), loss.data(), P, N, Hs, L, shape_w.data(), count, lanes.data());
  }
  if (shaped) reduce_lanes(lanes.data(), count * N * N, sums.data());
  for (std::size_t j = 0; j < count; ++j)
    for (std::size_t q = 0; q < N; ++q)
      for (std::size_t m = 0; m < N; ++m) out[j](Eigen::Index(q), Eigen::Index(m)) += sums[(j * N + q) * N + m];
}

GalerkinAverages galerkin_averages(const RadialBasis& basis, double weight_temperature) {
  const Rules& g = finest_rules();
  const double lam = weight_temperature;
  const std::size_t P = g.hermite.x.size() * g.laguerre.x.size();
  const auto n_rows = static_cast<Eigen::Index>(basis.size), n_cols = static_cast<Eigen::Index>(P);
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;  // RadialBasis's layout
  Rows B(n_rows, n_cols), dB(n_rows, n_cols);
  Eigen::VectorXd x(n_cols), xw(n_cols), wm(n_cols);
  Eigen::MatrixXd wr(n_cols, 3);
  // c_z = z√(λ/2) resp. z/√2, z ~ N(0, 1), |c_⊥|² = λ·Exp(1) resp. Exp(1).
  Eigen::Index p = 0;
  for (std::size_t h = 0; h < g.hermite.x.size(); ++h)
    for (std::size_t l = 0; l < g.laguerre.x.size(); ++l, ++p) {
      const double w = g.hermite.weight[h] * g.laguerre.weight[l];
      x[p] = 0.5 * g.hermite.x[h] * g.hermite.x[h] + g.laguerre.x[l], xw[p] = lam * x[p], wm[p] = w * xw[p];
      wr(p, 0) = w * x[p], wr(p, 1) = w * sonine_S2(x[p]) * x[p], wr(p, 2) = w * sonine_S3(x[p]) * x[p];
    }
  GalerkinAverages out;
  basis.eval(x.data(), P, B.data(), nullptr);
  const Eigen::MatrixXd r = B * wr;
  for (int j = 0; j < 3; ++j) out.r[j] = r.col(j);
  basis.eval(xw.data(), P, B.data(), dB.data());
  const Rows BW = B.array().rowwise() * wm.transpose().array();  // B_q w c_w²
  out.M.noalias() = BW * B.transpose();
  out.S.noalias() = BW * (B + 2.0 * dB).transpose();
  return out;
}

TracerGalerkin tracer_galerkin(const CollisionRates& rates, std::size_t k, const double* T, const RadialBasis& basis, const GalerkinOptions& opt) {
  const model::Mixture& mix = rates.mixture();
  const std::size_t N = basis.size;
  const double lam = opt.weight_temperature;
  if (!(lam > 0.0 && std::isfinite(lam))) throw std::invalid_argument("tracer_galerkin: the weight temperature must be positive");
  TracerGalerkin out;
  const double theta_k = T[k] / mix[k].mass;
  out.theta = theta_k;
  out.A = Eigen::MatrixXd::Zero(Eigen::Index(N), Eigen::Index(N));
  RadialBasis pair_basis = basis;
  if (opt.full) pair_basis.speed_points = full_shape_speed_points;
  for (std::size_t i = 0; i < mix.size(); ++i) {  // collisions with every partner i
    const PartnerShape shape{1.0, opt.a2 ? opt.a2[i] : 0.0, opt.a3 ? opt.a3[i] : 0.0, opt.full ? &(*opt.full)[i] : nullptr};
    add_pair_collisions(rates, k, i, theta_k, T[i] / mix[i].mass, pair_basis, lam, &shape, 1, &out.A);
  }
  const GalerkinAverages avg = galerkin_averages(basis, lam);
  const double zeta = std::isnan(opt.zeta) ? rates.xi_species(k, T) : opt.zeta;
  out.M = avg.M;
  out.A -= 0.5 * zeta * avg.S;
  out.r = opt.full ? (*opt.full)[k].source(basis) : avg.r[0] + (opt.a2 ? opt.a2[k] : 0.0) * avg.r[1] + (opt.a3 ? opt.a3[k] : 0.0) * avg.r[2];
  return out;
}

Eigen::MatrixXd m_orthonormal_basis(const Eigen::MatrixXd& M) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(M);
  if (es.info() != Eigen::Success) throw NumericalError("tracer diffusion Galerkin: the mass matrix (Eigen SelfAdjointEigenSolver) failed");
  const Eigen::VectorXd mu = es.eigenvalues();
  const double floor = 1e-11 * mu.maxCoeff();
  std::vector<Eigen::Index> kept;
  for (Eigen::Index j = 0; j < mu.size(); ++j)
    if (mu[j] > floor) kept.push_back(j);
  Eigen::MatrixXd Phi(M.rows(), Eigen::Index(kept.size()));
  for (std::size_t j = 0; j < kept.size(); ++j) Phi.col(Eigen::Index(j)) = es.eigenvectors().col(kept[j]) / std::sqrt(mu[kept[j]]);
  return Phi;
}

namespace {

// The problem in an M-orthonormal basis of the span (m_orthonormal_basis): ẏ = −K y, K = ΦᵀAΦ, y(0) = ΦᵀM e₀ (the M-projection of
// d(0) = e₀, exact where e₀ lies in the kept span), C(s) = 2θ (Φᵀr)·y(s).
struct Reduced {
  Eigen::MatrixXd K;
  Eigen::VectorXd y0, r;
};
Reduced reduce(const TracerGalerkin& g) {
  const Eigen::MatrixXd Phi = m_orthonormal_basis(g.M);
  return {Phi.transpose() * g.A * Phi, Phi.transpose() * g.M.col(0), Phi.transpose() * g.r};
}

}  // namespace

double galerkin_diffusion(const TracerGalerkin& g) {
  const Reduced p = reduce(g);
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(p.K);
  if (!lu.isInvertible()) return std::numeric_limits<double>::quiet_NaN();
  const double D = 2.0 * g.theta / 3.0 * p.r.dot(lu.solve(p.y0));  // (1/3)∫₀^∞ C ds
  return std::isfinite(D) && D > 0.0 ? D : std::numeric_limits<double>::quiet_NaN();
}

std::optional<VelocityMemory> galerkin_memory(const TracerGalerkin& g) {
  // K = V Λ V⁻¹: C(s) = Σ_j 2θ (rᵀV)_j (V⁻¹y₀)_j e^(−λ_j s).
  const Reduced p = reduce(g);
  const Eigen::EigenSolver<Eigen::MatrixXd> es(p.K);
  if (es.info() != Eigen::Success) throw NumericalError("tracer diffusion Galerkin: eigen-decomposition failed (Eigen EigenSolver)");
  const Eigen::MatrixXcd V = es.eigenvectors();
  const Eigen::VectorXcd left = V.transpose() * p.r.cast<std::complex<double>>();
  const Eigen::VectorXcd right = V.fullPivLu().solve(p.y0.cast<std::complex<double>>());
  VelocityMemory m;
  for (Eigen::Index j = 0; j < V.cols(); ++j) {
    const std::complex<double> rate = es.eigenvalues()[j];
    if (!(rate.real() > 0.0)) return std::nullopt;  // a mode that does not decay: no diffusive solution
    m.weight.push_back(2.0 * g.theta * left[j] * right[j]), m.rate.push_back(rate);
  }
  return m;
}

// x₀ of collision_weighted_basis for species k (see the header).
double converged_basis_x0(const CollisionRates& rates, std::size_t k, const double* T) {
  const model::Mixture& mix = rates.mixture();
  double sum = 0.0, mean_speed = 0.0;  // the partners' mean speed √(8θ_i/π), weighted with n_i σ_ki² χ_ki
  for (std::size_t i = 0; i < mix.size(); ++i) {
    const double s = mix.sigma(k, i), w = mix[i].density * s * s * rates.chi(k, i);
    sum += w, mean_speed += w * std::sqrt(8.0 * T[i] / (std::numbers::pi * mix[i].mass));
  }
  return std::pow(mean_speed / sum, 2) * mix[k].mass / (2.0 * T[k]);
}

ConvergedDiffusion converged_tracer_diffusion(const CollisionRates& rates, std::size_t k, const double* T, const GalerkinOptions& opt,
                                              std::size_t size) {
  const double D1 = T[k] / (rates.mixture()[k].mass * rates.inv_tau_v_species(k, T));
  ConvergedDiffusion out;
  out.problem = tracer_galerkin(rates, k, T, collision_weighted_basis(size, converged_basis_x0(rates, k, T)), opt);
  out.D = galerkin_diffusion(out.problem);
  out.factor = out.D / D1;
  return out;
}

TracerGalerkin leading_block(const TracerGalerkin& g, std::size_t n) {
  if (n < 1 || n > std::size_t(g.M.rows())) throw std::invalid_argument("leading_block: 1 to the problem's size");
  const auto m = static_cast<Eigen::Index>(n);
  return {g.A.topLeftCorner(m, m), g.M.topLeftCorner(m, m), g.r.head(m), g.theta};
}

double converged_diffusion_change(const ConvergedDiffusion& c) {
  // collision_weighted_basis(size − 1) is the first size − 1 functions of collision_weighted_basis(size) (same x₀):
  // the smaller problem is the leading block of the same assembly.
  const std::size_t size = std::size_t(c.problem.M.rows());
  if (size < 3) throw std::invalid_argument("converged_diffusion_change: size must be >= 3");
  return std::abs(c.D - galerkin_diffusion(leading_block(c.problem, size - 1))) / c.D;
}

}  // namespace granmix::theory
