#include "collision_rates.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace granmix::theory {

CollisionRates::CollisionRates(model::Mixture mix, model::Restitution law, std::vector<std::vector<double>> chi,
                               MomentMethod method)
    : mix_(std::move(mix)), law_(std::move(law)), chi_(std::move(chi)), method_(method) {
  const std::size_t N = mix_.size();
  // The rates are sums over all N² pairs (v1 Eqs. 20, 23) with a table of pair constants: refuse
  // what would not fit rather than fail in the allocator or run for hours.
  if (double(N) * double(N) * sizeof(Pair) > max_pair_table_bytes)
    throw std::invalid_argument(fmt::format("theory: {} species need a pair table of {:.1f} GB (N² × {} bytes); the limit is {:.0f} GB, "
                                            "about {} species", N, double(N) * double(N) * sizeof(Pair) / 1e9, sizeof(Pair),
                                            max_pair_table_bytes / 1e9, std::size_t(std::sqrt(max_pair_table_bytes / sizeof(Pair)))));
  if (law_.size() != N || chi_.size() != N)
    throw std::invalid_argument("collision rates: restitution and χ must have one row per species");
  if (method_ == MomentMethod::automatic)
    method_ = (law_.is_viscoelastic() && law_.form() != model::ViscoelasticForm::series) ? MomentMethod::quadrature
                                                                                         : MomentMethod::series;
  const double c = 4.0 / 3.0 * std::sqrt(2.0 * std::numbers::pi);
  pairs_.resize(N * N);
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t i = 0; i < N; ++i) {
      const double s = mix_.sigma(k, i);
      const double mk = mix_[k].mass, mi = mix_[i].mass;
      pairs_[k * N + i] = {c * mix_[i].density * s * s * chi_[k][i], mi / (mi + mk), mk / (mi + mk), 1.0 / mk, 1.0 / mi,
                           law_.is_viscoelastic() ? CollisionMoments{} : constant_moments(law_.eps(k, i))};
    }
}

CollisionMoments CollisionRates::moments(std::size_t k, std::size_t i, double V) const {
  if (!law_.is_viscoelastic()) return constant_moments(law_.eps(k, i));
  const double a = viscoelastic_scale(law_.akappa(k, i), V);
  return method_ == MomentMethod::series ? series_moments(a) : quadrature_moments(a, law_.form());
}

double CollisionRates::xi(std::size_t k, std::size_t i, double Tk, double Ti) const {
  const Pair& p = pair(k, i);
  return xi_formula(p, std::sqrt(Tk * p.inv_mk + Ti * p.inv_mi), Tk, Ti, moments(k, i, Tk * p.inv_mk + Ti * p.inv_mi));
}

double CollisionRates::inv_tau_v(std::size_t k, std::size_t i, double Tk, double Ti) const {
  const Pair& p = pair(k, i);
  const double V = Tk * p.inv_mk + Ti * p.inv_mi;
  return inv_tau_formula(p, std::sqrt(V), Tk, Ti, moments(k, i, V));
}

double CollisionRates::xi_species(std::size_t k, const double* T) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < mix_.size(); ++i) sum += xi(k, i, T[k], T[i]);
  return sum;
}

double CollisionRates::inv_tau_v_species(std::size_t k, const double* T) const {
  double sum = 0.0;
  for (std::size_t i = 0; i < mix_.size(); ++i) sum += inv_tau_v(k, i, T[k], T[i]);
  return sum;
}

template <class F>
void CollisionRates::symmetric_sum(const double* T, double* out, F f) const {
  const std::size_t N = mix_.size();
  for (std::size_t k = 0; k < N; ++k) out[k] = 0.0;
  for (std::size_t k = 0; k < N; ++k) {
    const double Tk = T[k];
    for (std::size_t i = k; i < N; ++i) {
      const Pair& a = pairs_[k * N + i];
      const double Ti = T[i], sqrtV = std::sqrt(Tk * a.inv_mk + Ti * a.inv_mi);
      out[k] += f(a, sqrtV, Tk, Ti, a.W);
      if (i != k) {
        const Pair& b = pairs_[i * N + k];
        out[i] += f(b, sqrtV, Ti, Tk, b.W);
      }
    }
  }
}

void CollisionRates::xi_all(const double* T, double* out) const {
  if (law_.is_viscoelastic())
    for (std::size_t k = 0; k < mix_.size(); ++k) out[k] = xi_species(k, T);
  else
    symmetric_sum(T, out, xi_formula);
}

void CollisionRates::inv_tau_v_all(const double* T, double* out) const {
  if (law_.is_viscoelastic())
    for (std::size_t k = 0; k < mix_.size(); ++k) out[k] = inv_tau_v_species(k, T);
  else
    symmetric_sum(T, out, inv_tau_formula);
}

double CollisionRates::diffusion(std::size_t k, const double* T) const {
  return T[k] / (inv_tau_v_species(k, T) * mix_[k].mass);
}

}  // namespace granmix::theory
