// The box hull section's boundary as four straight edges, and what every pressure integration over
// it shares: the edges placed at a pose, the hydrostatic part of a piece's pressure integrals, and a
// wetted piece's contribution to the edge's moments, then to the load (sea/hull_pressure.hpp).
// The edges run counter-clockwise (keel aft → keel fore → deck fore → deck aft), r(s) = a + s d,
// s ∈ [0, 1]; the outward normal is (d_y, −d_x)/|d|. Pressures are divided by ρg.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "sea/hull_pressure.hpp"

namespace ffrf::sea {

struct HullEdge {
  Eigen::Vector2d a, d;
  double length;
};

// ∫ p/(ρg) du and ∫ p/(ρg) u du over a piece [0, h] of the edge parameter, u from the piece's start.
struct PieceIntegrals {
  double j0 = 0.0;
  double j1 = 0.0;
};

// Running moments of one edge: ∫ p/(ρg) ds and ∫ p/(ρg) (r − r_G1) ds / |d|, and the wetted length.
struct EdgeMoments {
  double p0 = 0.0;
  Eigen::Vector2d p1 = Eigen::Vector2d::Zero();
  double wetted_length = 0.0;
};

inline std::array<HullEdge, 4> hull_edges(const BoxHullSection& hull, const Eigen::Vector2d& g1, double pitch) {
  const double c = std::cos(pitch), s = std::sin(pitch);
  const auto place = [&](double x, double y) { return Eigen::Vector2d(g1.x() + c * x - s * y, g1.y() + s * x + c * y); };
  const std::array<Eigen::Vector2d, 4> corner = {place(hull.aft_x, hull.keel_y), place(hull.fore_x, hull.keel_y),
                                                 place(hull.fore_x, hull.deck_y), place(hull.aft_x, hull.deck_y)};
  std::array<HullEdge, 4> edges;
  for (std::size_t e = 0; e < corner.size(); ++e) {
    const Eigen::Vector2d d = corner[(e + 1) % corner.size()] - corner[e];
    edges[e] = {corner[e], d, d.norm()};
  }
  return edges;
}

// The hydrostatic part −y of p/(ρg) on the piece [s0, s0 + h].
inline PieceIntegrals hydrostatic_piece(const HullEdge& edge, double s0, double h) {
  const double y0 = edge.a.y() + s0 * edge.d.y();
  return {-(y0 * h + 0.5 * edge.d.y() * h * h), -(0.5 * y0 * h * h + edge.d.y() * h * h * h / 3.0)};
}

// Adds the piece starting at s0 to the edge's moments.
inline void add_piece(const HullEdge& edge, const Eigen::Vector2d& g1, double s0, const PieceIntegrals& piece, EdgeMoments& acc) {
  acc.p0 += piece.j0;
  acc.p1 += piece.j0 * (edge.a + s0 * edge.d - g1) + piece.j1 * edge.d;
}

// F = −B ∮ p n ds, M = −B ∮ p (r − r_G1) × n ds from one edge's moments.
inline void add_edge_load(const BoxHullSection& hull, const HullEdge& edge, const EdgeMoments& m, double rho_g, HullLoad& load) {
  if (m.wetted_length == 0.0) return;
  const Eigen::Vector2d n = Eigen::Vector2d(edge.d.y(), -edge.d.x()) / edge.length;
  const double p0 = rho_g * edge.length * m.p0;
  const Eigen::Vector2d p1 = rho_g * edge.length * m.p1;
  load.force -= hull.width * p0 * n;
  load.moment -= hull.width * (p1.x() * n.y() - p1.y() * n.x());
  load.wetted_length += m.wetted_length;
}

}  // namespace ffrf::sea
