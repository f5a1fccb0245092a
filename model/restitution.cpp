#include "restitution.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace granmix::model {

Restitution Restitution::constant(std::size_t species, double eps) {
  if (!(eps >= 0.0 && eps <= 1.0)) throw std::invalid_argument("restitution must lie in [0, 1]");
  // One value for every pair, no M×M matrix: 1e5 species would need 80 GB for it.
  Restitution r;
  r.kind_ = Kind::constant;
  r.size_ = species;
  r.uniform_ = eps;
  return r;
}

Restitution Restitution::constant_matrix(std::vector<std::vector<double>> eps) {
  const std::size_t N = eps.size();
  for (std::size_t k = 0; k < N; ++k) {
    if (eps[k].size() != N) throw std::invalid_argument("restitution matrix must be square");
    for (std::size_t i = 0; i < N; ++i) {
      if (!(eps[k][i] >= 0.0 && eps[k][i] <= 1.0))
        throw std::invalid_argument("restitution must lie in [0, 1]");
      if (eps[k][i] != eps[i][k]) throw std::invalid_argument("restitution matrix must be symmetric");
    }
  }
  Restitution r;
  r.kind_ = Kind::constant;
  r.size_ = N;
  r.eps_ = std::move(eps);
  return r;
}

Restitution Restitution::viscoelastic(const Mixture& mix, double akappa11, ViscoelasticForm form) {
  if (!(akappa11 >= 0.0) || !std::isfinite(akappa11))
    throw std::invalid_argument("viscoelastic Aκ^(2/5) must be finite and >= 0");
  const std::size_t N = mix.size();
  // κ_ki ∝ √σ_eff / m_eff (v1 Eq. 7), so Aκ_ki^(2/5) = Aκ_11^(2/5) (κ_ki/κ_11)^(2/5).
  auto kappa = [&](std::size_t k, std::size_t i) {
    return std::sqrt(mix.effective_diameter(k, i)) / mix.reduced_mass(k, i);
  };
  const double k11 = kappa(0, 0);
  Restitution r;
  r.kind_ = Kind::viscoelastic;
  r.size_ = N;
  r.form_ = form;
  r.akappa_.assign(N, std::vector<double>(N));
  for (std::size_t k = 0; k < N; ++k)
    for (std::size_t i = 0; i < N; ++i) r.akappa_[k][i] = akappa11 * std::pow(kappa(k, i) / k11, 0.4);
  return r;
}

double Restitution::eps_at(std::size_t k, std::size_t i, double normal_speed) const {
  if (kind_ == Kind::constant) return eps(k, i);
  // v1 Eq. (5): y = (Aκ^(2/5))^(1/2) |g·e|^(1/10).
  const double y = std::sqrt(akappa_[k][i]) * std::pow(std::abs(normal_speed), 0.1);
  return restitution(form_, y);
}

}  // namespace granmix::model
