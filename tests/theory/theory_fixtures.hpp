#pragma once
// Mixtures of the papers used by several theory tests.
#include <cmath>
#include <numbers>

#include <omp.h>

#include "model/enskog.hpp"
#include "model/mixture_generators.hpp"
#include "theory/rates/collision_rates.hpp"

namespace granmix::test {

// f() on `threads` OpenMP threads, the previous count restored (the tests that the numbers do not depend on it).
template <class F>
auto with_threads(int threads, F&& f) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  auto out = f();
  omp_set_num_threads(before);
  return out;
}

inline theory::CollisionRates constant_rates(std::vector<model::Species> s, double eps) {
  model::Mixture mix(std::move(s));
  const std::size_t N = mix.size();
  return theory::CollisionRates(mix, model::Restitution::constant(N, eps), model::dilute_contact_values(N));
}

inline theory::CollisionRates viscoelastic_rates(std::vector<model::Species> s, double akappa,
                                                 model::ViscoelasticForm form = model::ViscoelasticForm::exact) {
  model::Mixture mix(std::move(s));
  const std::size_t N = mix.size();
  auto law = model::Restitution::viscoelastic(mix, akappa, form);
  return theory::CollisionRates(mix, law, model::dilute_contact_values(N));
}

// v1 Fig. 2: m = 1, 100; σ = 1, 100^(1/3); n = 0.1, 0.1.
inline std::vector<model::Species> bo_binary() { return {{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}}; }
// v1 Fig. 6: m = 1, 100, 500 of one material.
inline std::vector<model::Species> bo_ternary() {
  return {{1, 1, 0.1}, {100, std::cbrt(100.0), 0.1}, {500, std::cbrt(500.0), 0.1}};
}
// v1 Fig. 7: m = 1..4, σ = k^(1/3).
inline std::vector<model::Species> bo_four() {
  std::vector<model::Species> s;
  for (int k = 1; k <= 4; ++k) s.push_back({double(k), std::cbrt(double(k)), 0.1});
  return s;
}
inline model::Mixture power_law(std::size_t species, double theta = 3) {
  model::PowerLaw p;
  p.n1 = 0.1, p.theta = theta, p.n1_particles = 1e30, p.max_species = species;
  return model::power_law_mixture(p);
}

// v1 Eqs. (A1), (A2) exactly as printed (g2 = χ): τ_v,ki⁻¹ and ξ_ki.
inline double printed_A2(double ni, double s, double chi, double Tk, double Ti, double mk, double mi, double e) {
  const double V = (Tk * mi + Ti * mk) / (mi * mk), pi = std::numbers::pi;
  return 8.0 / 3.0 * std::sqrt(2 * pi) * ni * s * s * chi * std::sqrt(V) * (1 + e) * (mi / (mi + mk)) *
         (1 - 0.5 * (1 + e) * (Ti * mk + Tk * mi) / (Tk * (mi + mk)));
}
inline double printed_A1(double ni, double s, double chi, double Tk, double Ti, double mk, double mi, double e) {
  const double pi = std::numbers::pi;
  return 8 * std::sqrt(2 * pi) / 3 * ni * s * s * chi * (mi / (mi + mk)) * (Tk * mi + Ti * mk) / (Tk * (mi + mk)) *
         std::sqrt((Tk * mi + Ti * mk) / (mi * mk)) * (1 + e) * (1 + e) / 4;
}

}  // namespace granmix::test
