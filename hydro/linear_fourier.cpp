// Piecewise-linear Fourier integrals (see linear_fourier.hpp).
#include "hydro/linear_fourier.hpp"

#include <cmath>

namespace ffrf::hydro {

namespace {
// E0, E1 with ∫₀¹ s^m e^{iθs} ds = Σ_k (iθ)^k / (k! (m + k + 1)) for small θ.
void moments(double theta, std::complex<double>& e0, std::complex<double>& e1) {
  const std::complex<double> i_theta(0.0, theta);
  if (std::abs(theta) < 0.25) {
    std::complex<double> term(1.0, 0.0);  // (iθ)^k / k!
    e0 = e1 = 0.0;
    for (int k = 0; k < 16; ++k) {
      e0 += term / static_cast<double>(k + 1);
      e1 += term / static_cast<double>(k + 2);
      term *= i_theta / static_cast<double>(k + 1);
    }
    return;
  }
  const std::complex<double> e = std::exp(i_theta);
  e0 = (e - 1.0) / i_theta;
  e1 = e / i_theta + (e - 1.0) / (theta * theta);
}
}  // namespace

std::complex<double> linear_fourier_integral(const double* x, const double* f, std::size_t n, double t, std::size_t stride) {
  std::complex<double> sum = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double h = x[k + 1] - x[k];
    std::complex<double> e0, e1;
    moments(t * h, e0, e1);
    const double fa = f[k * stride], fb = f[(k + 1) * stride];
    sum += h * std::polar(1.0, t * x[k]) * (fa * (e0 - e1) + fb * e1);
  }
  return sum;
}

}  // namespace ffrf::hydro
