// The hydrostatic + Froude–Krylov load of sea/hull_pressure.hpp with the incident wave read
// from a record of the sea (sea/incident_wave_record.hpp) instead of summed component by
// component: the same wetted boundary (edges clipped at the wave surface, split at still water),
// the same exact hydrostatics (−ρ g y). Waterline crossings: on a side steeper than the surface by
// Newton's method on the recorded ζ (one crossing at most), on the keel and the deck by the same
// interval isolation as the exact path (sea/crossing_isolation.hpp) on the recorded ζ, ∂ζ/∂x,
// ∂²ζ/∂x² with the record's bounds. The wave's part of each wetted piece: below still water from the
// recorded antiderivatives at the piece's ends (∫F = ΔG/w, ∫uF = h G1/w − ΔH/w²); on the crest
// extension from the antiderivatives of ζ along still water (Gauss–Legendre on ζ when the piece
// spans less than a metre in x). Cost: a few polynomial evaluations per edge, independent of the
// sea's component count.
// A submerged piece's end outside every disc (a keel that has come out of the water between its
// corners) takes G and H there from the component sums, for that point alone. The record answers
// only where it can certify the answer; otherwise std::nullopt and the caller takes the exact sums:
// t outside the record, an edge outside the record's x range, more crossings on one edge than the
// crossing list holds.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "sea/hull_pressure.hpp"
#include "sea/incident_wave_record.hpp"

namespace ffrf::sea {

// How far the hull may move from its pose at zero surge: the record's patches and bounds cover it.
struct HullMotionRange {
  double surge = 6.0;   // [m] ± about x_G1 = 0
  double heave = 2.0;   // [m] ± about the given G1 height
  double pitch = 0.05;  // [rad] ± about level
};

// One disc per side (stern, bow) holding every point a pressure integration can ask the record
// for over the motion range: the keel corner, the side where it crosses still water, and x of the
// side above it at y = 0 (the crest extension). x range: the whole hull over the range.
std::vector<WavePatch> box_hull_patches(const BoxHullSection& hull, double g1_height, const HullMotionRange& range);
void box_hull_x_range(const BoxHullSection& hull, double g1_height, const HullMotionRange& range, double& x_min,
                      double& x_max);

// `wave` is the field the record was made of (G and H by its sums at a submerged piece's end outside
// the discs); `ramp` is its r(t); `workspace` is filled here (sized once, reused).
std::optional<HullLoad> recorded_hull_pressure_load(const BoxHullSection& hull, const IncidentWaveRecord& record,
                                                    const WaveField& wave, WavePolynomials& workspace, double ramp, double water_density,
                                                    double gravity, const Eigen::Vector2d& g1_position, double pitch,
                                                    double t);

}  // namespace ffrf::sea
