// Golub–Welsch Gauss–Legendre rules (see gauss_legendre.hpp).
#include "hydro/gauss_legendre.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include "linalg/dense_solvers.hpp"

namespace ffrf::hydro {

namespace {
GaussRule make_rule(int points) {
  // Jacobi matrix of the monic Legendre recurrence: off-diagonal β_k = k / sqrt(4k² − 1).
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(points, points);
  for (int k = 1; k < points; ++k) {
    const double beta = k / std::sqrt(4.0 * k * k - 1.0);
    jacobi(k, k - 1) = beta;
    jacobi(k - 1, k) = beta;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  GaussRule rule;
  for (int i = 0; i < points; ++i) {
    rule.nodes.push_back(solver.eigenvalues()(i));
    const double first = solver.eigenvectors()(0, i);
    rule.weights.push_back(2.0 * first * first);  // μ0 = ∫_{−1}^{1} dx = 2
  }
  return rule;
}
}  // namespace

const GaussRule& gauss_legendre(int points) {
  if (points < 1 || points > 64)
    throw std::invalid_argument("gauss_legendre: points = " + std::to_string(points) + ", valid range 1..64");
  static std::array<GaussRule, 65> rules;
  static std::array<std::once_flag, 65> made;
  std::call_once(made[static_cast<std::size_t>(points)], [&] { rules[static_cast<std::size_t>(points)] = make_rule(points); });
  return rules[static_cast<std::size_t>(points)];
}

}  // namespace ffrf::hydro
