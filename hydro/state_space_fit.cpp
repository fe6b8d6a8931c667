// Realization (Kung / ERA) fit of the radiation kernel (see state_space_fit.hpp).
#include "hydro/state_space_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include "linalg/dense_solvers.hpp"

namespace ffrf::hydro {

namespace {

using Eigen::MatrixXd;

struct Candidate {
  RadiationStateSpace model;
  bool valid = false;
};

PlanarVector kernel_scales(const RetardationFunction& kernel) {
  PlanarVector s = PlanarVector::Ones();
  for (int i = 0; i < kPlanarDofs; ++i) {
    double peak = 0.0;
    for (const auto& k : kernel.kernel) peak = std::max(peak, std::abs(k(i, i)));
    if (peak > 0.0) s(i) = 1.0 / std::sqrt(peak);
  }
  return s;
}

double impulse_error(const RadiationStateSpace& m, const RetardationFunction& kernel, const PlanarVector& scale) {
  // e^{A dt} once, then the recursion e^{A (k+1) dt} B = e^{A dt} e^{A k dt} B.
  const Eigen::EigenSolver<MatrixXd> eig(m.a);
  const Eigen::VectorXcd step = (eig.eigenvalues() * kernel.time_step).array().exp();
  const Eigen::MatrixXcd v = eig.eigenvectors();
  const Eigen::MatrixXcd v_inv = v.inverse();
  Eigen::MatrixXcd state = v_inv * m.b.cast<std::complex<double>>();
  const Eigen::MatrixXcd output = m.c.cast<std::complex<double>>() * v;
  double error = 0.0, norm = 0.0;
  const PlanarMatrix s = scale.asDiagonal();
  for (const auto& k : kernel.kernel) {
    const PlanarMatrix fitted = (output * state).real();
    error += (s * (k - fitted) * s).squaredNorm();
    norm += (s * k * s).squaredNorm();
    state = step.asDiagonal() * state;
  }
  return norm > 0.0 ? std::sqrt(error / norm) : 0.0;
}

double passivity_margin(const RadiationStateSpace& m, double omega_max) {
  double lowest = std::numeric_limits<double>::infinity(), highest = 0.0;
  for (int k = 0; k <= 2000; ++k) {
    const double omega = omega_max * k / 2000.0;
    const PlanarMatrix re = frequency_response(m, omega).real();
    const Eigen::SelfAdjointEigenSolver<PlanarMatrix> sym(0.5 * (re + re.transpose()));
    lowest = std::min(lowest, sym.eigenvalues()(0));
    highest = std::max(highest, sym.eigenvalues()(2));
  }
  return highest > 0.0 ? lowest / highest : lowest;
}

Candidate realise(const MatrixXd& u, const Eigen::VectorXd& sigma, const MatrixXd& v, const MatrixXd& shifted, int order,
                  double delta, const PlanarVector& scale) {
  Candidate c;
  const Eigen::VectorXd root = sigma.head(order).cwiseSqrt(), inv_root = root.cwiseInverse();
  const MatrixXd a_d = inv_root.asDiagonal() * (u.leftCols(order).transpose() * shifted * v.leftCols(order)) * inv_root.asDiagonal();
  const MatrixXd b_d = (root.asDiagonal() * v.leftCols(order).transpose()).leftCols(kPlanarDofs);
  const MatrixXd c_d = (u.leftCols(order) * root.asDiagonal()).topRows(kPlanarDofs);
  const Eigen::EigenSolver<MatrixXd> eig(a_d);
  if (eig.info() != Eigen::Success) return c;
  const Eigen::VectorXcd lambda = eig.eigenvalues();
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    // |λ_d| ≥ 1: unstable; a negative real λ_d has no real logarithm (an oscillation at the Nyquist
    // frequency of the Hankel sampling): both orders are rejected.
    if (std::abs(lambda(i)) >= 1.0) return c;
    if (std::abs(lambda(i).imag()) <= 1e-12 * std::abs(lambda(i)) && lambda(i).real() <= 0.0) return c;
  }
  const Eigen::MatrixXcd vectors = eig.eigenvectors();
  const Eigen::MatrixXcd log_a = vectors * (lambda.array().log() / delta).matrix().asDiagonal() * vectors.inverse();
  if (log_a.imag().norm() > 1e-8 * log_a.real().norm()) return c;
  c.model.a = log_a.real();
  c.model.b = b_d * scale.asDiagonal().inverse();
  c.model.c = scale.asDiagonal().inverse() * c_d;
  c.model.order = order;
  c.model.fit_step = delta;
  c.model.slowest_decay = (lambda.array().log() / delta).real().maxCoeff();
  c.valid = true;
  return c;
}

}  // namespace

RadiationStateSpace fit_state_space(const RetardationFunction& kernel, const StateSpaceOptions& options) {
  if (kernel.kernel.size() < 8)
    throw std::invalid_argument(fmt::format("state-space fit: {} kernel samples; valid: at least 8", kernel.kernel.size()));
  if (!(options.tolerance > 0.0) || options.max_order < 1 || options.hankel_samples < 8)
    throw std::invalid_argument(fmt::format(
        "state-space fit: tolerance {} (valid > 0), max order {} (valid >= 1), Hankel samples {} (valid >= 8)",
        options.tolerance, options.max_order, options.hankel_samples));
  const PlanarVector scale = kernel_scales(kernel);
  const PlanarMatrix s = scale.asDiagonal();
  const std::size_t n = kernel.kernel.size();
  const std::size_t stride = std::max<std::size_t>(1, (n - 1) / static_cast<std::size_t>(options.hankel_samples));
  const std::size_t count = (n - 1) / stride + 1;  // samples h_0 .. h_{count−1}
  const auto rows = static_cast<Eigen::Index>((count - 1) / 2), cols = static_cast<Eigen::Index>(count - 1) - rows;
  MatrixXd h0(3 * rows, 3 * cols), h1(3 * rows, 3 * cols);
  for (Eigen::Index i = 0; i < rows; ++i)
    for (Eigen::Index j = 0; j < cols; ++j) {
      const auto k = static_cast<std::size_t>(i + j) * stride;
      h0.block<3, 3>(3 * i, 3 * j) = s * kernel.kernel[k] * s;
      h1.block<3, 3>(3 * i, 3 * j) = s * kernel.kernel[k + stride] * s;
    }
  const Eigen::BDCSVD<MatrixXd> svd(h0, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const double delta = static_cast<double>(stride) * kernel.time_step;
  const int top = std::min<int>(options.max_order, static_cast<int>(svd.nonzeroSingularValues()));
  double best = std::numeric_limits<double>::infinity();
  for (int order = 1; order <= top; ++order) {
    Candidate c = realise(svd.matrixU(), svd.singularValues(), svd.matrixV(), h1, order, delta, scale);
    if (!c.valid) continue;
    c.model.impulse_error = impulse_error(c.model, kernel, scale);
    best = std::min(best, c.model.impulse_error);
    if (c.model.impulse_error <= options.tolerance) {
      c.model.passivity_margin = passivity_margin(c.model, std::numbers::pi / kernel.time_step);
      return c.model;
    }
  }
  throw std::runtime_error(fmt::format(
      "state-space fit: no stable model up to order {} reaches the impulse-response error {} (best {:.3g}); raise the "
      "maximum order or the tolerance, or lengthen the kernel's truncation time", top, options.tolerance, best));
}

PlanarMatrix impulse_response(const RadiationStateSpace& m, double t) {
  const Eigen::EigenSolver<MatrixXd> eig(m.a);
  const Eigen::MatrixXcd v = eig.eigenvectors();
  const Eigen::VectorXcd decay = (eig.eigenvalues() * t).array().exp();
  return (m.c.cast<std::complex<double>>() * v * decay.asDiagonal() * v.inverse() * m.b.cast<std::complex<double>>()).real();
}

Eigen::Matrix3cd frequency_response(const RadiationStateSpace& m, double omega) {
  const Eigen::MatrixXcd resolvent =
      std::complex<double>(0.0, omega) * Eigen::MatrixXcd::Identity(m.order, m.order) - m.a.cast<std::complex<double>>();
  return m.c.cast<std::complex<double>>() * resolvent.partialPivLu().solve(m.b.cast<std::complex<double>>());
}

}  // namespace ffrf::hydro
