// Where a straight hull edge r(s) = a + s d, s ∈ [0, 1], crosses the incident wave surface summed
// component by component: the roots of g(s) = y(s) − ζ(x(s), t), found without sampling by the
// interval isolation of sea/crossing_isolation.hpp, with max|g''| on an interval bounded
// LOCALLY: the larger |g''| at its ends plus width/2 · |d_x|³ r Σ a_i k_i³ (capped by the global
// d_x² r Σ a_i k_i²). The global bounds alone (Σ a k, Σ a k²) grow with the component count while the
// surface's true slope and curvature grow with its square root, so they cut a long record's keel and
// deck into hundreds of pieces; the local bound needs the third-derivative bound only times the
// width. Cost per evaluation of g, g', g'': one phasor per wave component
// (sea/component_phasors.hpp: a sine and cosine, or two complex products by recurrence on a
// harmonic grid); the start intervals, two phasors per component and one complex product per
// component and sample. docs/hydrodynamics.md §7 ("Cost").
#pragma once

#include <Eigen/Dense>

#include "sea/crossing_isolation.hpp"
#include "sea/wave_field.hpp"

namespace ffrf::sea {

// The surface of `wave` at time t against the edge from `start` along `direction` (global frame).
WaterlineCrossings waterline_crossings(const WaveField& wave, double t, const Eigen::Vector2d& start,
                                       const Eigen::Vector2d& direction);

}  // namespace ffrf::sea
