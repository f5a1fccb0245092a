#pragma once
// Mean-squared displacement of species k (docs/physics.md §3):
//   eq17      v1 Eq. (17): 6∫₀ᵗ D_k(t₁)[1 − exp(−(τ_k(t)−τ_k(t₁))/τ̂_v,k(t₁))] dt₁, by adaptive
//             Gauss–Kronrod quadrature (GSL QAG, 21 points) in the solver's clock s₁ on the dense
//             CVODE solution; relative error max(1e-9, 10 rtol) requested (1e-6 required).
//   longtime  v1 Eq. (21): 6∫₀ᵗ D_k dt₁ (integrated with the temperatures).
//   vacf      the velocity-autocorrelation ODE (integrated with the temperatures).
//   closed    settled ratios (v2 Eq. 22, rebuilt): 6D_k(0){τ₀ ln(1+t/τ₀) − τ_v,k(0)[1 − (1+t/τ₀)^(−τ₀/τ_v,k(0))]}
//   total     v1 Eq. (16): Σ n_k ⟨R_k²⟩ / n.
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "theory/histories/temperature_history.hpp"

namespace granmix::theory {

enum class MsdMethod { eq17, vacf, longtime, closed };
MsdMethod parse_msd_method(const std::string& name);  // throws std::invalid_argument
const char* to_string(MsdMethod m);

// Needs a history integrated with reduced_time = true.
double msd_eq17(const TemperatureHistory& h, std::size_t k, double t);

// The same for many species at one time: each quadrature node's temperatures and τ_v⁻¹ (all N at once, the
// symmetric pair pass) are kept for the next species, whose quadrature meets the same nodes (GSL's rule and
// bisections on the same [0, s(t)]: 500 species at 16 times evaluate 660702 integrands at 1890 distinct nodes).
// The numbers are those of a quadrature that computes every node afresh, bit for bit (tests/theory/test_msd.cpp);
// msd_eq17 is one species of it. Not thread-safe (the kept nodes): one per thread; kept only for the last t asked.
class Eq17Msd {
 public:
  explicit Eq17Msd(const TemperatureHistory& h) : h_(h) {}
  double operator()(std::size_t k, double t) const;
  struct Node {
    std::vector<double> T, inv_tau;  // every species' T and τ_v⁻¹ (v1 Eq. A1) at a node
  };

 private:
  const TemperatureHistory& h_;
  mutable double t_ = -1.0;
  mutable std::unordered_map<double, Node> nodes_;  // quadrature node s₁ ↦ its Node
};

// Closed form with settled ratios; tau0 = ∞ (elastic gas) gives 6D[t − τ_v(1 − e^(−t/τ_v))].
double msd_closed(double D0, double tau_v0, double tau0, double t);

// Long-time closed form (v2 Eq. 23): 6 D_k(0) τ₀ ln(1 + t/τ₀).
double msd_closed_longtime(double D0, double tau0, double t);

// Total MSD (v1 Eq. 16) from partial MSDs.
double msd_total(const model::Mixture& mix, const std::vector<double>& partial);

}  // namespace granmix::theory
