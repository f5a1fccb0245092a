#include "theory/numerics/equilibrated_solve.hpp"

#include "model/errors.hpp"

namespace granmix::theory {

Eigen::VectorXd solve_equilibrated(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::string& what) {
  const Eigen::VectorXd scale = A.cwiseAbs().rowwise().maxCoeff().cwiseInverse();
  if (!scale.allFinite()) throw NumericalError(what + ": the linear system is singular (a zero row)");
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(scale.asDiagonal() * A);
  if (!lu.isInvertible()) throw NumericalError(what + ": the linear system is singular (Eigen FullPivLU, rows equilibrated)");
  return lu.solve(scale.cwiseProduct(b));
}

}  // namespace granmix::theory
