// Where a straight hull edge r(s) = a + s d, s ∈ [0, 1], crosses the incident wave surface: the roots
// of g(s) = y(s) − ζ(x(s), t), found without sampling. [0, 1] is cut into intervals on which g is
// monotone (|g'| at an end > width · max|g''|) or provably root-free (g keeps its sign and
// min|g(ends)| > max|g''| · width²/8, the chord's error bound; or |g(l)| + |g(r)| > width · max|g'|),
// with max|g''| on an interval bounded LOCALLY: the larger |g''| at its ends plus width/2 · |d_x|³ r Σ a_i k_i³
// (capped by the global d_x² r Σ a_i k_i²). The global bounds alone (Σ a k, Σ a k²) grow with the
// component count while the surface's true slope and curvature grow with its square root, so they cut a
// long record's keel and deck into hundreds of pieces; the local bound needs the third-derivative
// bound only times the width. Each monotone interval with a sign change holds exactly one root,
// found by Newton's method kept inside the bracket (bisection when a step leaves it) until its step is
// below 1e-9 (quadratic convergence: the root is then good to round-off). Cost per evaluation of g,
// g', g'': one phasor per wave component (coupling/component_phasors.hpp: a sine and cosine, or two
// complex products by recurrence on a harmonic grid); the start intervals, two phasors per component
// and one complex product per component and sample. docs/hydrodynamics.md §7 ("Cost").
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
