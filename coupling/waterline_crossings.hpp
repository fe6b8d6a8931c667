// Where a straight hull edge r(s) = a + s d, s ∈ [0, 1], crosses the incident wave surface: the roots
// of g(s) = y(s) − ζ(x(s), t), found without sampling. With the field's bounds on the surface's slope
// and curvature (|g'| ≤ |d_y| + |d_x| r Σ a_i k_i, |g''| ≤ d_x² r Σ a_i k_i²), [0, 1] is cut into
// intervals on which g is monotone (|g'(mid)| > half-width · max|g''|) or provably root-free
// (|g(l)| + |g(r)| > width · max|g'| with one sign); each monotone interval with a sign change holds
// exactly one root, found by Newton's method kept inside the bracket (bisection when a step leaves
// it) until its step is below 1e-9 (quadratic convergence: the root is then good to round-off). Cost per evaluation of g or g': one sine and cosine per wave component.
#pragma once

#include <Eigen/Dense>
#include <array>

#include "coupling/wave_field.hpp"

namespace ffrf::coupling {

// Up to max_crossings roots in increasing s; wet_at_start tells whether r(0) is below the surface
// (y < ζ, strictly). A tangency (g touching zero without changing sign) is no crossing.
struct WaterlineCrossings {
  static constexpr int max_crossings = 64;
  std::array<double, max_crossings> s{};
  int count = 0;
  bool wet_at_start = false;
  bool truncated = false;  // more crossings than max_crossings: the later ones are missing
};

// The surface of `wave` at time t against the edge from `start` along `direction` (global frame).
WaterlineCrossings waterline_crossings(const WaveField& wave, double t, const Eigen::Vector2d& start,
                                       const Eigen::Vector2d& direction);

}  // namespace ffrf::coupling
