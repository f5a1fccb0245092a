#pragma once
// Gauss rules for the tests' independent quadratures, by Golub–Welsch (the eigen-decomposition of the
// three-term recurrence's Jacobi matrix): Hermite (weight e^{−x²}), Laguerre (e^{−u}), Legendre on [0, 1].
// Written here, not taken from theory/, so that the tests do not share the library's rules.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace granmix::test {

struct Rule {
  std::vector<double> x, w;
};

inline Rule golub_welsch(int n, const std::function<double(int)>& diag, const std::function<double(int)>& off, double mu0) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) J(j, j) = diag(j);
  for (int j = 0; j + 1 < n; ++j) J(j, j + 1) = J(j + 1, j) = off(j);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(J);
  Rule r;
  for (int j = 0; j < n; ++j) {
    r.x.push_back(es.eigenvalues()(j));
    r.w.push_back(mu0 * es.eigenvectors()(0, j) * es.eigenvectors()(0, j));
  }
  return r;
}
inline Rule hermite(int n) {
  return golub_welsch(n, [](int) { return 0.0; }, [](int j) { return std::sqrt((j + 1) / 2.0); }, std::sqrt(std::numbers::pi));
}
inline Rule laguerre(int n) { return golub_welsch(n, [](int j) { return 2.0 * j + 1; }, [](int j) { return j + 1.0; }, 1.0); }
inline Rule legendre01(int n) {
  Rule r = golub_welsch(n, [](int) { return 0.0; }, [](int j) { return (j + 1) / std::sqrt(4.0 * (j + 1) * (j + 1) - 1); }, 2.0);
  for (std::size_t j = 0; j < r.x.size(); ++j) r.x[j] = 0.5 * (r.x[j] + 1), r.w[j] *= 0.5;
  return r;
}

}  // namespace granmix::test
