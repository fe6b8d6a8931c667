// Planar kinematics helpers of the crane's bodies, from its space (linalg/space.hpp): the rotation
// A(θ), the skew operator Ĩ = [[0, −1], [1, 0]] (Ĩ v is v turned by +90°, so dA/dθ = A Ĩ) and the
// planar cross product.
#pragma once

#include <Eigen/Dense>

#include "linalg/space.hpp"

namespace ffrf::multibody {

inline Eigen::Matrix2d rotation(double theta) { return linalg::Planar::rotation(theta); }
inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return linalg::Planar::perp(v); }  // Ĩ v
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return linalg::Planar::cross(a, b); }

}  // namespace ffrf::multibody
