#pragma once
// A x = b by full-pivot LU with each row first divided by its largest |entry| (the solution is unchanged). The Sonine
// closures' rows carry their species' powers of λ_k = m_k/(2T_k): at a mass ratio of 1e3–1e4 they differ by 1e6–1e8,
// and Eigen's isInvertible threshold is relative to the largest pivot, so without the scaling a regular system of a
// heavy intruder would be refused as singular. A truly singular one throws NumericalError naming `what`.
#include <string>

#include <Eigen/Dense>

namespace granmix::theory {

Eigen::VectorXd solve_equilibrated(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const std::string& what);

}  // namespace granmix::theory
