// Planar kinematics helpers: the rotation A(θ) and the skew operator Ĩ = [[0, −1], [1, 0]]
// (Ĩ v is v turned by +90°, so dA/dθ = A Ĩ); the planar cross product.
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace ffrf::multibody {

inline Eigen::Matrix2d rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d a;
  a << c, -s, s, c;
  return a;
}

inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }  // Ĩ v

inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace ffrf::multibody
