// The elastic-coordinate interface (docs/theory.md §2–3): one interface for nodal and modal
// coordinates, so the floating-frame body's equations are written once. A flexible body places a material point at
// r = R + A(θ)(ū0 + S(x) Φ η); an ElasticCoordinates type supplies everything the floating-frame
// body needs about η: its size, the inertia invariants projected on Φ, the stiffness ΦᵀKΦ, the
// geometric stiffness ΦᵀK_gΦ per unit axial force, the shape rows of a point, the map back
// to nodal DOFs, and the projection Φᵀ A Φ of any free-DOF matrix (e.g. a geometric stiffness).
// Each says the space it lives in (`Space`: linalg/space.hpp; planar today, so the first moment is a
// 2-vector, the second a scalar and the skew matrix one). nodal/ (Φ = I, sparse) and modal/ (dense,
// small) implement it; the body is written once as a
// template over this concept.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <concepts>

#include "linalg/space.hpp"

namespace ffrf::fem {

template <class C>
concept ElasticCoordinates = requires(const C& coords, double x, const Eigen::VectorXd& eta,
                                      const Eigen::SparseMatrix<double>& nodal_matrix) {
  { coords.size() } -> std::convertible_to<Eigen::Index>;
  { coords.mass() } -> std::convertible_to<double>;
  requires linalg::Space<typename C::Space>;  // the space the body lives in (linalg/space.hpp)
  { coords.first_moment() } -> std::convertible_to<typename C::Space::Vector>;
  { coords.second_moment() } -> std::convertible_to<typename C::Space::SecondMoment>;
  coords.shape_integral();   // 2×n  ∫ρ S Φ
  coords.u0_dot_shape();     // 1×n  ∫ρ ū0ᵀ S Φ
  coords.u0_cross_shape();   // 1×n  ∫ρ ū0ᵀ Ĩ S Φ
  coords.mass_ff();          // n×n  Φᵀ M_ff Φ
  coords.skew_ff();          // n×n  Φᵀ (∫ρ SᵀĨS) Φ
  coords.stiffness();        // n×n  Φᵀ K Φ
  coords.unit_geometric_stiffness();  // n×n  Φᵀ K_g(P = 1 N) Φ
  coords.displacement_rows(x);        // 2×n  S(x) Φ
  coords.rotation_row(x);             // 1×n  R(x) Φ
  { coords.to_nodal(eta) } -> std::convertible_to<Eigen::VectorXd>;  // q_n = Φ η
  { coords.project(nodal_matrix) } -> std::convertible_to<typename C::Matrix>;  // Φᵀ A Φ of a free-DOF matrix
};

}  // namespace ffrf::fem
