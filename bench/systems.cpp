#include "systems.hpp"

#include <cmath>
#include <stdexcept>

#include "model/mixture_generators.hpp"

namespace granmix::bench {

namespace {

// A mixture of the given particle counts with n = 0.1 in total, m_k = masses, σ_k = sizes.
BenchSystem make(const std::string& name, const std::vector<std::size_t>& counts, const std::vector<double>& mass,
                 const std::vector<double>& sigma, double eps) {
  double N = 0.0;
  for (std::size_t c : counts) N += double(c);
  std::vector<model::Species> sp;
  for (std::size_t k = 0; k < counts.size(); ++k) sp.push_back({mass[k], sigma[k], 0.1 * double(counts[k]) / N});
  BenchSystem b{name, {}};
  b.setup.mixture = model::Mixture(sp);
  b.setup.law = model::Restitution::constant(sp.size(), eps);
  b.setup.counts = counts;
  b.setup.T0.assign(sp.size(), 1.0);
  return b;
}

}  // namespace

BenchSystem one_species(std::size_t n) { return make("one", {n}, {1.0}, {1.0}, 0.9); }

BenchSystem binary_1_100(std::size_t n) { return make("binary", {n / 2, n - n / 2}, {1.0, 100.0}, {1.0, std::cbrt(100.0)}, 0.5); }

BenchSystem ternary(std::size_t n) {
  return make("ternary", {n / 3, n / 3, n - 2 * (n / 3)}, {1.0, 10.0, 100.0}, {1.0, std::cbrt(10.0), std::cbrt(100.0)}, 0.9);
}

BenchSystem exponential_691(double n1) {
  model::Exponential e;
  e.n1_particles = n1;
  const model::Mixture mix = model::exponential_mixture(e);
  std::vector<std::size_t> counts;
  std::vector<double> mass, sigma;
  for (double c : model::exponential_counts(e)) counts.push_back(static_cast<std::size_t>(c));
  for (std::size_t k = 0; k < mix.size(); ++k) mass.push_back(mix[k].mass), sigma.push_back(mix[k].diameter);
  return make("exp691", counts, mass, sigma, 0.99);
}

BenchSystem polydisperse(const std::string& shape, std::size_t M, std::size_t N) {
  if (N < M) throw std::invalid_argument("bench: fewer particles than species");
  std::vector<double> w(M), mass(M), sigma(M);
  double total = 0.0;
  for (std::size_t k = 0; k < M; ++k) {
    const double x = double(k + 1);
    w[k] = shape == "powerlaw" ? std::pow(x, -3.0) : std::exp(-6.9 * double(k) / double(M));
    total += w[k], mass[k] = x, sigma[k] = std::cbrt(x);
  }
  std::vector<std::size_t> counts(M);
  for (std::size_t k = 0; k < M; ++k) counts[k] = 1 + static_cast<std::size_t>(std::floor(double(N - M) * w[k] / total));
  return make(shape + "-" + std::to_string(M), counts, mass, sigma, 0.99);
}

}  // namespace granmix::bench
