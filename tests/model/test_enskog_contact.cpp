// Enskog contact values χ_ij of spheres of unequal sizes (model/enskog.cpp, MG Eq. 26), checked against formulas
// written here from the literature, not from model/enskog.cpp. χ_ij multiplies every pair rate of the dense scenes, in
// the theory and in the DSMC alike, so no comparison of the two can see an error in it: only these tests can.
//
// MG Eq. (26) with σ_ij = (σ_i + σ_j)/2 is the Boublík–Mansoori–Carnahan–Starling–Leland (BMCSL) contact value
//   χ_ij = 1/(1−ξ₃) + 3 z_ij ξ₂/(1−ξ₃)² + 2 z_ij² ξ₂²/(1−ξ₃)³,   z_ij = σ_iσ_j/(σ_i+σ_j),   ξ_l = (π/6) Σ_k n_k σ_k^l,
// since σ_iiσ_jj/σ_ij = 2 z_ij, so MG's (3/2) ξ (2z) = 3 z ξ₂ and (1/2) ξ² (2z)² = 2 z² ξ₂², with MG's ξ = ξ₂, ν = ξ₃.
// Four independent checks, each at size ratios 1:2, 1:4, 1:10 (binary and ternary), packing fractions 0.05 to 0.35,
// every pair ij:
//  1. the BMCSL form above, evaluated here from the moments ξ₂, ξ₃ (relative 1e-12);
//  2. the contact theorem: βp = n + (2π/3) Σ_ij n_i n_j σ_ij³ χ_ij with these χ_ij is the BMCSL equation of state
//     βp = (6/π) [ξ₀/(1−ξ₃) + 3ξ₁ξ₂/(1−ξ₃)² + (3−ξ₃)ξ₂³/(1−ξ₃)³] (Boublík 1970, Mansoori et al. 1971), an identity of
//     algebra (relative 1e-12);
//  3. exact statistical mechanics at low density: χ_ij = 1 + Σ_k n_k V_k(ij) + O(n²), V_k(ij) the volume of the lens
//     where spheres of radii σ_ik and σ_jk about two centres σ_ij apart overlap (the density expansion of the mixture's
//     pressure through its third virial coefficient), with no reference to BMCSL (relative 1e-6, Richardson-extrapolated);
//  4. limits: equal sizes give the one-component Carnahan–Starling (1 − η/2)/(1 − η)³ for every pair, and a point-like
//     species at contact with any sphere gives the exact scaled-particle value 1/(1 − η).
// Discrimination: a 2% error in χ_12 alone (the mutant chi-unequal-2 of tests/mutants/mutants.toml) moves check 1 by
// 2e-2 and the pressure of check 2 by 3.6e-4 to 8e-3 of its value at these compositions (the smallest: sizes 1:10,
// 70% large, η = 0.05), ten orders of magnitude above the tolerances; check 3 sees χ_12 → 1.02 at zero density.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "model/enskog.hpp"

using namespace granmix::model;

namespace {

constexpr double pi = std::numbers::pi;

struct Composition {
  std::string name;
  std::vector<double> sigma;  // diameters
  std::vector<double> x;      // number fractions
};

const std::vector<Composition> compositions = {
    {"1:2 equimolar", {1.0, 2.0}, {0.5, 0.5}},
    {"1:4 with 5% large", {1.0, 4.0}, {0.95, 0.05}},
    {"1:10 with 0.1% large", {1.0, 10.0}, {0.999, 0.001}},
    {"1:10 with 70% large", {1.0, 10.0}, {0.3, 0.7}},
    {"1:2:4 ternary", {1.0, 2.0, 4.0}, {0.6, 0.3, 0.1}},
    {"1:4:10 ternary", {1.0, 4.0, 10.0}, {0.9, 0.09, 0.01}},
};
const std::vector<double> packings = {0.05, 0.15, 0.25, 0.35};

// Number densities n_k = x_k n with the total n that gives packing fraction eta.
std::vector<double> densities(const Composition& c, double eta) {
  double v = 0.0;
  for (std::size_t k = 0; k < c.x.size(); ++k) v += c.x[k] * c.sigma[k] * c.sigma[k] * c.sigma[k];
  std::vector<double> n;
  for (double x : c.x) n.push_back(x * eta / (pi / 6.0 * v));
  return n;
}

Mixture mixture_of(const std::vector<double>& sigma, const std::vector<double>& n) {
  std::vector<Species> s;
  for (std::size_t k = 0; k < n.size(); ++k) s.push_back({1.0 + double(k), sigma[k], n[k]});  // masses play no part
  return Mixture(s);
}

// ξ_l = (π/6) Σ_k n_k σ_k^l.
double moment(const std::vector<double>& sigma, const std::vector<double>& n, int l) {
  double m = 0.0;
  for (std::size_t k = 0; k < n.size(); ++k) m += n[k] * std::pow(sigma[k], l);
  return pi / 6.0 * m;
}

double bmcsl_contact(const std::vector<double>& sigma, const std::vector<double>& n, std::size_t i, std::size_t j) {
  const double xi2 = moment(sigma, n, 2), xi3 = moment(sigma, n, 3), z = sigma[i] * sigma[j] / (sigma[i] + sigma[j]);
  const double g = 1.0 - xi3;
  return 1.0 / g + 3.0 * z * xi2 / (g * g) + 2.0 * z * z * xi2 * xi2 / (g * g * g);
}

// Volume of the intersection of spheres of radii a and b whose centres are d apart (|a − b| ≤ d ≤ a + b).
double lens_volume(double a, double b, double d) {
  const double h = a + b - d;
  return pi * h * h * (d * d + 2.0 * d * (a + b) - 3.0 * (a - b) * (a - b)) / (12.0 * d);
}

double rel(double a, double b) { return std::abs(a / b - 1.0); }

}  // namespace

TEST_CASE("Enskog chi_ij of unequal sizes equals the BMCSL contact values recomputed from xi_2 and xi_3 - every pair",
          "[model]") {
  for (const Composition& c : compositions)
    for (double eta : packings) {
      const std::vector<double> n = densities(c, eta);
      const Mixture mix = mixture_of(c.sigma, n);
      REQUIRE(packing_fraction(mix) == Approx(eta).epsilon(1e-14));
      const auto chi = enskog_contact_values(mix);
      for (std::size_t i = 0; i < n.size(); ++i)
        for (std::size_t j = 0; j < n.size(); ++j) {
          INFO(c.name << ", eta = " << eta << ", chi_" << i + 1 << j + 1 << " = " << chi[i][j] << ", BMCSL "
                      << bmcsl_contact(c.sigma, n, i, j));
          CHECK(rel(chi[i][j], bmcsl_contact(c.sigma, n, i, j)) <= 1e-12);
          CHECK(chi[i][j] == chi[j][i]);
        }
    }
}

TEST_CASE("Enskog chi_ij of unequal sizes give the BMCSL equation of state through the contact theorem", "[model]") {
  for (const Composition& c : compositions)
    for (double eta : packings) {
      const std::vector<double> n = densities(c, eta);
      const auto chi = enskog_contact_values(mixture_of(c.sigma, n));
      double p_contact = 0.0;  // βp = n + (2π/3) Σ_ij n_i n_j σ_ij³ χ_ij
      for (std::size_t i = 0; i < n.size(); ++i) {
        p_contact += n[i];
        for (std::size_t j = 0; j < n.size(); ++j)
          p_contact += 2.0 * pi / 3.0 * n[i] * n[j] * std::pow((c.sigma[i] + c.sigma[j]) / 2.0, 3) * chi[i][j];
      }
      const double x0 = moment(c.sigma, n, 0), x1 = moment(c.sigma, n, 1), x2 = moment(c.sigma, n, 2),
                   x3 = moment(c.sigma, n, 3), g = 1.0 - x3;
      const double p_bmcsl = 6.0 / pi * (x0 / g + 3.0 * x1 * x2 / (g * g) + (3.0 - x3) * x2 * x2 * x2 / (g * g * g));
      INFO(c.name << ", eta = " << eta << ": beta p from the contact values " << p_contact << ", BMCSL " << p_bmcsl);
      CHECK(rel(p_contact, p_bmcsl) <= 1e-12);
    }
}

TEST_CASE("Enskog chi_ij is exact to first order in density: the lens volumes of the third virial coefficient", "[model]") {
  // (χ(λn) − 1)/λ = a₁ + a₂λ + O(λ²); 2 f(λ/2) − f(λ) removes the a₂ term. At η = 1e-4 the rest is ~1e-8 of a₁.
  for (const Composition& c : compositions) {
    const std::vector<double> n = densities(c, 1e-4);
    auto f = [&](double lambda, std::size_t i, std::size_t j) {
      std::vector<double> m = n;
      for (double& v : m) v *= lambda;
      return (enskog_contact_values(mixture_of(c.sigma, m))[i][j] - 1.0) / lambda;
    };
    for (std::size_t i = 0; i < n.size(); ++i)
      for (std::size_t j = 0; j < n.size(); ++j) {
        const double sij = (c.sigma[i] + c.sigma[j]) / 2.0;
        double a1 = 0.0;  // Σ_k n_k V_k(ij)
        for (std::size_t k = 0; k < n.size(); ++k)
          a1 += n[k] * lens_volume((c.sigma[i] + c.sigma[k]) / 2.0, (c.sigma[j] + c.sigma[k]) / 2.0, sij);
        const double extrapolated = 2.0 * f(0.5, i, j) - f(1.0, i, j);
        INFO(c.name << ", chi_" << i + 1 << j + 1 << ": first-order coefficient " << extrapolated << ", lens volumes " << a1);
        CHECK(rel(extrapolated, a1) <= 1e-6);
      }
  }
}

TEST_CASE("Enskog chi_ij limits: equal sizes give Carnahan-Starling for every pair - a point-like species 1/(1 - eta)",
          "[model]") {
  for (double eta : packings) {
    INFO("eta = " << eta);
    const Composition equal{"equal sizes", {1.3, 1.3, 1.3}, {0.2, 0.5, 0.3}};
    const auto chi = enskog_contact_values(mixture_of(equal.sigma, densities(equal, eta)));
    const double cs = (1.0 - eta / 2.0) / std::pow(1.0 - eta, 3);
    for (const auto& row : chi)
      for (double v : row) CHECK(rel(v, cs) <= 1e-13);
    // A species of diameter 1e-9 (z_ij ≈ 1e-9 σ_i: its terms in ξ₂ and z vanish to ~1e-9) among spheres 1 and 10.
    const Composition point{"point-like", {1.0, 10.0, 1e-9}, {0.5, 0.2, 0.3}};
    const auto chp = enskog_contact_values(mixture_of(point.sigma, densities(point, eta)));
    for (std::size_t i = 0; i < 3; ++i) CHECK(rel(chp[i][2], 1.0 / (1.0 - eta)) <= 1e-7);
  }
}
