#include "theory/sonine/sonine_hcs.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "theory/numerics/bracketed_root.hpp"
#include "theory/rates/collision_rates.hpp"
#include "model/errors.hpp"
#include "model/gsl_setup.hpp"
#include "theory/rates/settled_ratios.hpp"
#include "theory/sonine/sonine_moment_cooling.hpp"
#include "theory/sonine/sonine_polynomials.hpp"
#include "theory/sonine/sonine_system.hpp"

namespace granmix::theory {

namespace {

struct Problem {
  const model::Mixture& mix;
  const model::Restitution& alpha;
  const std::vector<std::vector<double>>& chi;
  bool maxwell;
  std::size_t N;
  double sref2;  // σ_ref² = σ_12² (σ_11² for one species)
  double m1, m2;
  SonineSystem system;
  // Order 3: the moment closure in the mixture's own units (T = 1 the mean temperature), null at order 2.
  std::unique_ptr<CollisionRates> rates;
  std::unique_ptr<SonineMomentCooling> moments;
};

// Everything at given temperatures T_k (Σ x_k T_k = 1): λ, c (a₃ at order 3), cooling rates ζ_k.
struct Evaluation {
  std::vector<double> lambda, c, a3, a4, zeta;
};

Evaluation evaluate(Problem& p, const std::vector<double>& T) {
  const std::size_t N = p.N;
  Evaluation e;
  const double v0sq = 2.0 * (p.m1 + p.m2) / (p.m1 * p.m2);  // T = 1
  for (std::size_t k = 0; k < N; ++k) e.lambda.push_back(p.mix[k].mass * v0sq / (2.0 * T[k]));
  if (p.moments) {  // order 3: the steady a's at these temperatures, ζ_k in units of ν_ref = n σ_ref² v0
    const std::vector<double> z = p.moments->steady_state(T.data());
    e.c.assign(z.begin(), z.begin() + std::ptrdiff_t(N)), e.a3.assign(z.begin() + std::ptrdiff_t(N), z.begin() + std::ptrdiff_t(2 * N));
    e.a4.assign(z.begin() + std::ptrdiff_t(2 * N), z.end());  // order 4
    e.zeta.resize(N);
    p.moments->rates(T.data(), z.data(), e.zeta.data(), nullptr);
    const double nu_ref = p.mix.total_density() * p.sref2 * std::sqrt(v0sq);
    for (double& x : e.zeta) x /= nu_ref;
    return e;
  }
  p.system.assemble(e.lambda.data());
  e.c.assign(N, 0.0);
  if (!p.maxwell) p.system.solve_cumulants(e.c.data());
  e.zeta.resize(N);
  p.system.cooling(e.c.data(), e.zeta.data());  // MG Eq. (45) sides
  return e;
}

// Temperatures from log ratios x_k = ln(T_k/T_1), normalised to Σ x_k T_k = 1.
std::vector<double> temperatures(const Problem& p, const double* x) {
  std::vector<double> T(p.N);
  double mean = 0.0;
  for (std::size_t k = 0; k < p.N; ++k) T[k] = std::exp(x[k]), mean += p.mix.fraction(k) * T[k];
  for (double& v : T) v /= mean;
  return T;
}

double relative_difference(double a, double b) { return (a - b) / (std::abs(a) + std::abs(b) + 1e-300); }

std::vector<double> solve_binary(Problem& p) {
  auto f = [&](double x) {
    const double xs[2] = {x, 0.0};  // x = ln γ = ln(T_1/T_2)
    const Evaluation e = evaluate(p, temperatures(p, xs));
    return relative_difference(e.zeta[0], e.zeta[1]);
  };
  const double x = bracketed_root(f, "Sonine temperature ratio: ζ_1 = ζ_2 in ln γ (MG Eq. 45)").x;
  const double xs[2] = {x, 0.0};
  return temperatures(p, xs);
}

std::vector<double> solve_many(Problem& p) {
  model::use_gsl_return_codes();
  // Start: the Maxwellian ratios of v1 Eq. (A2), which equal MG's c = 0 level (docs/physics.md §6).
  const CollisionRates rates(p.mix, p.alpha, p.chi);
  const std::vector<double> start = settled_ratios(rates);
  const std::size_t n = p.N - 1;
  const model::GslPtr<gsl_vector, gsl_vector_free> x(gsl_vector_alloc(n));
  if (x == nullptr) throw NumericalError("gsl_vector_alloc failed");
  for (std::size_t k = 0; k < n; ++k) gsl_vector_set(x.get(), k, std::log(start[k + 1]));
  struct Callback {
    Problem& p;
    model::GslCallbackGuard guard;
  } cb{p, {}};
  auto residual = [](const gsl_vector* xv, void* params, gsl_vector* out) -> int {
    auto& c = *static_cast<Callback*>(params);
    return c.guard.run(int(GSL_EBADFUNC), [&] {
      std::vector<double> xs(c.p.N, 0.0);
      for (std::size_t k = 1; k < c.p.N; ++k) xs[k] = gsl_vector_get(xv, k - 1);
      const Evaluation e = evaluate(c.p, temperatures(c.p, xs.data()));
      for (std::size_t k = 1; k < c.p.N; ++k) gsl_vector_set(out, k - 1, relative_difference(e.zeta[k], e.zeta[0]));
      return int(GSL_SUCCESS);
    });
  };
  gsl_multiroot_function F{residual, n, &cb};
  const model::GslPtr<gsl_multiroot_fsolver, gsl_multiroot_fsolver_free> s(
      gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, n));
  if (s == nullptr) throw NumericalError("gsl_multiroot_fsolver_alloc failed");
  int status = gsl_multiroot_fsolver_set(s.get(), &F, x.get());
  for (int it = 0; status == GSL_SUCCESS && it < 200; ++it) {
    status = gsl_multiroot_fsolver_iterate(s.get());
    if (status != GSL_SUCCESS) break;
    status = gsl_multiroot_test_residual(s->f, 1e-14);  // relative ζ differences at rounding level
    if (status == GSL_SUCCESS) break;
    if (status == GSL_CONTINUE) status = GSL_SUCCESS;
  }
  cb.guard.rethrow();
  std::vector<double> xs(p.N, 0.0);
  for (std::size_t k = 1; k < p.N; ++k) xs[k] = gsl_vector_get(s->x, k - 1);
  const double worst = gsl_vector_max(s->f) > -gsl_vector_min(s->f) ? gsl_vector_max(s->f) : -gsl_vector_min(s->f);
  if (worst > 1e-10)
    throw NumericalError(std::string("Sonine temperature ratios (gsl_multiroot hybrids): ") + gsl_strerror(status) +
                         ", max relative ζ difference " + std::to_string(worst));
  return temperatures(p, xs.data());
}

}  // namespace

SonineHcs sonine_hcs(const model::Mixture& mix, const model::Restitution& alpha, const std::vector<std::vector<double>>& chi,
                     bool maxwell, SonineSolver solver, int order) {
  if (alpha.is_viscoelastic()) throw std::invalid_argument("Sonine HCS: needs constant restitution coefficients");
  if (order < 2 || order > 4 || (maxwell && order != 2)) throw std::invalid_argument("Sonine HCS: order 2, 3 or 4 (Maxwellian: 2)");
  const std::size_t N = mix.size();
  const double sref2 = std::pow(mix.sigma(0, N > 1 ? 1 : 0), 2);
  Problem p{mix, alpha, chi, maxwell, N, sref2, mix[0].mass, mix[N > 1 ? 1 : 0].mass, SonineSystem(mix, alpha, chi, sref2), nullptr, nullptr};
  if (order >= 3) {
    p.rates = std::make_unique<CollisionRates>(mix, alpha, chi);
    p.moments = std::make_unique<SonineMomentCooling>(*p.rates, order);
  }
  // An elastic mixture settles at equal temperatures (detailed balance, for any masses and sizes): every ζ_k is 0
  // there, so the relative ζ differences the root finders zero are 0/0 (v1 Fig. 7's ε = 1 with four species: hybrids
  // did not converge).
  bool elastic = true;
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t i = k; i < N; ++i) elastic = elastic && alpha.eps(k, i) == 1.0;
  SonineHcs out;
  if (N == 1 || elastic)
    out.T.assign(N, 1.0);
  else
    out.T = (N == 2 && solver == SonineSolver::automatic) ? solve_binary(p) : solve_many(p);
  const Evaluation e = evaluate(p, out.T);
  out.c = e.c, out.a3 = e.a3, out.a4 = e.a4, out.lambda = e.lambda, out.zeta_star = e.zeta[0];
  for (std::size_t k = 0; k < N; ++k) {
    double b = 0.0;
    for (std::size_t j = 0; j < N; ++j) b += mix.fraction(j) * chi[k][j] * std::pow(mix.sigma(k, j), 2) / p.sref2;
    out.beta.push_back(std::numbers::pi * b);  // MG Eq. (20)
  }
  return out;
}

double maxwellian_phi(double lambda, double v) { return std::pow(lambda / std::numbers::pi, 1.5) * std::exp(-lambda * v * v); }

double SonineHcs::delta(std::size_t k, double v) const {
  const double x = lambda[k] * v * v;
  if (a3.empty() || c[k] == 0.0) return sonine_S2(x);  // MG Eq. (28)
  const double d = sonine_S2(x) + 2.0 * a3[k] / c[k] * sonine_S3(x);  // order 3: + (a₃/a₂) S₃
  return a4.empty() ? d : d + 2.0 * a4[k] / c[k] * sonine_S4(x);     // order 4: + (a₄/a₂) S₄
}

double SonineHcs::phi(std::size_t k, double v) const {
  return maxwellian_phi(lambda[k], v) * (1.0 + 0.5 * c[k] * delta(k, v));  // MG Eq. (27)
}

double SonineHcs::G(std::size_t k, double v) const { return std::exp(tail_exponent(k) * v) * phi(k, v); }  // MG Eq. (30)

}  // namespace granmix::theory
