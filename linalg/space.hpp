// The space a model lives in, as a type: what a position, an orientation and a rigid body's or a
// beam node's degrees of freedom are. ffrf's models are planar today (`Planar`: 2-vectors, one
// angle, 3 DOFs per rigid body — surge, heave, pitch — and per beam node — axial, transverse, small
// rotation); the spatial model (3-vectors, a singularity-free rotation, 6 DOFs per body and per
// node with torsion) is a second implementation of the same trait. fem/ (elements and meshes), the
// elastic-coordinates concept (fem/elastic_coordinates.hpp), the floating-frame body and hydro/'s
// rigid-body coefficients say which space they live in through it.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <concepts>

namespace ffrf::linalg {

struct Planar {
  static constexpr int dimension = 2;       // components of a position
  static constexpr int rotation_dofs = 1;   // an angle θ, counter-clockwise
  static constexpr int body_dofs = 3;       // a rigid body's pose (x, y, θ)
  static constexpr int node_dofs = 3;       // a beam node's (u, v, φ)
  using Vector = Eigen::Vector2d;           // positions, first moments
  using Rotation = Eigen::Matrix2d;         // A(θ)
  using Pose = Eigen::Vector3d;             // (x, y, θ)
  using SecondMoment = double;              // ∫ρ ūᵀū: a polar moment about the one rotation axis
  using RotaryInertia = double;             // a rigid body's about its centre of mass and the plane's normal

  static Rotation rotation(double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    Rotation a;
    a << c, -s, s, c;
    return a;
  }
  // Ĩ v: v turned by +90° (dA/dθ = A Ĩ).
  static Vector perp(const Vector& v) { return {-v.y(), v.x()}; }
  // a × b, the out-of-plane component.
  static double cross(const Vector& a, const Vector& b) { return a.x() * b.y() - a.y() * b.x(); }
};

template <class S>
concept Space = requires {
  { S::dimension } -> std::convertible_to<int>;
  { S::rotation_dofs } -> std::convertible_to<int>;
  { S::body_dofs } -> std::convertible_to<int>;
  { S::node_dofs } -> std::convertible_to<int>;
  typename S::Vector;
  typename S::Rotation;
  typename S::Pose;
  typename S::SecondMoment;
  typename S::RotaryInertia;
} && S::body_dofs == S::dimension + S::rotation_dofs;

static_assert(Space<Planar>);

}  // namespace ffrf::linalg
