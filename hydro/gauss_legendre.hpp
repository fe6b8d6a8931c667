// Gauss–Legendre quadrature nodes and weights on [−1, 1] by the Golub–Welsch method (the
// eigenvalues of the symmetric Jacobi matrix of the Legendre recurrence are the nodes, the first
// components of its normalised eigenvectors give the weights: Golub & Welsch 1969, Math. Comp. 23),
// and a composite rule on uniform panels. An n-point rule is exact for polynomials of degree 2n − 1.
#pragma once

#include <vector>

namespace ffrf::hydro {

struct GaussRule {
  std::vector<double> nodes, weights;  // on [−1, 1]
};

const GaussRule& gauss_legendre(int points);  // points in [1, 64]; cached, thread-safe

// ∫_a^b f dx with `panels` uniform panels of the `points`-point rule.
template <class F>
double integrate_panels(F&& f, double a, double b, int panels, int points = 8) {
  const GaussRule& rule = gauss_legendre(points);
  const double width = (b - a) / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double centre = a + (p + 0.5) * width;
    double panel = 0.0;
    for (std::size_t q = 0; q < rule.nodes.size(); ++q) panel += rule.weights[q] * f(centre + 0.5 * width * rule.nodes[q]);
    sum += 0.5 * width * panel;
  }
  return sum;
}

}  // namespace ffrf::hydro
