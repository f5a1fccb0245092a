#pragma once
// Restitution law of every species pair: constant (scalar or per-pair matrix ε_ki) or
// viscoelastic (v1 Eq. 5), with Aκ^(2/5) given for the 1–1 pair and scaled per pair through
// κ_ki ∝ √σ_eff / m_eff (v1 Eq. 7; docs/physics.md §5).
#include <cstddef>
#include <vector>

#include "mixture.hpp"
#include "viscoelastic.hpp"

namespace granmix::model {

class Restitution {
 public:
  enum class Kind { constant, viscoelastic };

  static Restitution constant(std::size_t species, double eps);
  static Restitution constant_matrix(std::vector<std::vector<double>> eps);  // symmetric, 0 <= ε <= 1
  static Restitution viscoelastic(const Mixture& mix, double akappa11, ViscoelasticForm form);

  Kind kind() const { return kind_; }
  std::size_t size() const { return size_; }
  bool is_viscoelastic() const { return kind_ == Kind::viscoelastic; }
  ViscoelasticForm form() const { return form_; }

  // Constant law: ε_ki.
  double eps(std::size_t k, std::size_t i) const { return uniform_ >= 0.0 ? uniform_ : eps_[k][i]; }
  // Viscoelastic law: Aκ_ki^(2/5), so that y = (Aκ_ki^(2/5))^(1/2) |g·e|^(1/10).
  double akappa(std::size_t k, std::size_t i) const { return akappa_[k][i]; }
  // ε for a pair at normal impact speed |g·e| (either law).
  double eps_at(std::size_t k, std::size_t i, double normal_speed) const;

 private:
  Kind kind_ = Kind::constant;
  std::size_t size_ = 0;
  double uniform_ = -1.0;                 // constant(): the ε of every pair (then eps_ is empty)
  std::vector<std::vector<double>> eps_;  // constant_matrix(): ε_ki
  std::vector<std::vector<double>> akappa_;
  ViscoelasticForm form_ = ViscoelasticForm::exact;
};

}  // namespace granmix::model
