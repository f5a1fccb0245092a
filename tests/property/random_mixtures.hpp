#pragma once
// Random mixtures for the property tests: 1–50 species, masses 1e-3–1e3, diameters
// 0.1–10, densities 1e-6–0.1 (all log-uniform), ε uniform in (0, 1] with one case in ten elastic,
// one in five viscoelastic; a viscoelastic mixture keeps only its first few species (8 unless the
// test says less): each of its pair rates is two adaptive quadratures (collision_moments.cpp),
// settling the ratios costs N³ of them per Newton step (47 species: 62 s of CPU, 8 species 0.7 s),
// and a temperature history to 1e12 about 5000 right-hand sides of N(N+1)/2 pairs. Fixed seeds: case c is the same mixture on every machine (std::mt19937_64
// and our own transforms; the standard distributions are implementation-defined).
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "model/enskog.hpp"
#include "model/mixture.hpp"
#include "model/restitution.hpp"

namespace granmix::test {

struct RandomMixture {
  model::Mixture mixture{{model::Species{}}};
  model::Restitution law = model::Restitution::constant(1, 1.0);
  double eps = 1.0;  // constant law: ε of every pair
  bool viscoelastic = false;
  std::string describe() const {
    std::string s = std::to_string(mixture.size()) + " species, ";
    s += viscoelastic ? "viscoelastic" : "eps = " + std::to_string(eps);
    for (std::size_t k = 0; k < mixture.size() && k < 6; ++k)
      s += "; (m " + std::to_string(mixture[k].mass) + ", sigma " + std::to_string(mixture[k].diameter) + ", n " +
           std::to_string(mixture[k].density) + ")";
    return s;
  }
};

class MixtureSampler {
 public:
  explicit MixtureSampler(std::uint64_t seed, std::size_t max_viscoelastic_species = 8)
      : gen_(seed), max_viscoelastic_species_(max_viscoelastic_species) {}
  double uniform() { return double(gen_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double log_uniform(double lo, double hi) { return lo * std::pow(hi / lo, uniform()); }

  RandomMixture next(std::size_t max_species = 50) {
    // log-uniform species count: many small mixtures, some large (the runtime grows as N²)
    const auto N = std::size_t(std::floor(log_uniform(1.0, double(max_species) + 1.0)));
    std::vector<model::Species> s;
    for (std::size_t k = 0; k < N; ++k) s.push_back({log_uniform(1e-3, 1e3), log_uniform(0.1, 10.0), log_uniform(1e-6, 0.1)});
    RandomMixture r;
    r.mixture = model::Mixture(s);
    const double kind = uniform();
    if (kind < 0.1) {
      r.eps = 1.0;
      r.law = model::Restitution::constant(N, 1.0);
    } else if (kind < 0.3) {
      if (N > max_viscoelastic_species_) {
        s.resize(max_viscoelastic_species_);
        r.mixture = model::Mixture(s);
      }
      r.viscoelastic = true;
      r.law = model::Restitution::viscoelastic(r.mixture, log_uniform(1e-3, 0.3), model::ViscoelasticForm::pade);
    } else {
      r.eps = 1.0 - uniform();  // (0, 1]
      r.law = model::Restitution::constant(N, r.eps);
    }
    return r;
  }

 private:
  std::mt19937_64 gen_;
  std::size_t max_viscoelastic_species_;
};

}  // namespace granmix::test
