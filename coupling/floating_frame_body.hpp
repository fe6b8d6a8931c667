// The planar floating-frame flexible body (paper §3, eqs. 6–22), written once over the elastic-
// coordinate interface (fem/elastic_coordinates.hpp): a point is r = R + A(θ)(ū0 + SΦη), the
// body coordinates are q = (R_x, R_y, θ, η). With the inertia invariants m, s0, J0, S̄, d, c, M_ff,
// S̃ (fem/shape_integrals.hpp) and ū_c = s0 + S̄η the mass matrix (eq. 19.d) is
//   M_RR = m I,  M_Rθ = A Ĩ ū_c,  M_Rf = A S̄,  M_θθ = J0 + 2dη + ηᵀM_ffη,
//   M_θf = −(c + ηᵀS̃),  M_ff,
// and the quadratic velocity vector Q_v = −Ṁq̇ + ∂T/∂q (eq. 20.c) is
//   Q_v,R = θ̇² A ū_c − 2θ̇ A Ĩ S̄ η̇,  Q_v,θ = −2θ̇ (d + ηᵀM_ff) η̇,  Q_v,f = θ̇² (dᵀ + M_ff η) − 2θ̇ S̃ η̇.
// Point forces by virtual work (eq. 13), gravity from V = −gᵀ∫ρr, elastic force −Kη (eq. 16)
// and stiffness-proportional structural damping −βKη̇. Optional geometric (stress) stiffening adds
// −(K_σ + θ̇² K_c)η: K_σ the geometric stiffness of a constant reference axial force (static
// prestress), K_c that of the centrifugal axial force per unit θ̇² (docs/theory.md §9, §11). Derivation: docs/theory.md §2; checked
// against the independent sympy derivation tests/coupling/one_element_reference.hpp.
// A rigid body is the same body with zero elastic coordinates.
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "coupling/planar.hpp"
#include "fem/elastic_coordinates.hpp"

namespace ffrf::coupling {

// A material point of the body: undeformed position ū0 and its shape rows S(x)Φ.
struct BodyPoint {
  Eigen::Vector2d undeformed = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, Eigen::Dynamic> shape;
};

template <fem::ElasticCoordinates Coords>
class FloatingFrameBody {
 public:
  using ElasticMatrix = typename Coords::Matrix;
  using Vector = Eigen::VectorXd;
  using ConstRef = Eigen::Ref<const Eigen::VectorXd>;
  using Ref = Eigen::Ref<Eigen::VectorXd>;

  // stiffness_damping β [s]: structural damping force −βKη̇.
  FloatingFrameBody(Coords coords, double stiffness_damping)
      : coords_(std::move(coords)), beta_(stiffness_damping), n_(static_cast<Eigen::Index>(coords_.size())),
        work_a_(n_), work_b_(n_) {}

  Eigen::Index elastic_size() const { return n_; }
  Eigen::Index size() const { return 3 + n_; }
  const Coords& coords() const { return coords_; }
  double stiffness_damping() const { return beta_; }

  BodyPoint point(double x) const {
    BodyPoint p;
    p.undeformed = Eigen::Vector2d(x, 0.0);
    p.shape = Eigen::MatrixXd(coords_.displacement_rows(x));
    return p;
  }

  Eigen::Vector2d local_position(ConstRef q, const BodyPoint& p) const {
    return p.undeformed + p.shape * q.tail(n_);
  }
  Eigen::Vector2d position(ConstRef q, const BodyPoint& p) const {
    return q.head<2>() + rotation(q(2)) * local_position(q, p);
  }
  Eigen::Vector2d velocity(ConstRef q, ConstRef v, const BodyPoint& p) const {
    const Eigen::Matrix2d a = rotation(q(2));
    return v.head<2>() + v(2) * (a * perp(local_position(q, p))) + a * (p.shape * v.tail(n_));
  }

  // Mass matrix blocks: reference (3×3 over R, θ) and reference–elastic coupling (3×n);
  // the elastic block is the constant coords().mass_ff().
  void mass_blocks(ConstRef q, Eigen::Matrix3d& reference, Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling) const {
    const auto eta = q.tail(n_);
    const Eigen::Matrix2d a = rotation(q(2));
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * eta;  // ∫ρū
    work_a_.noalias() = coords_.mass_ff() * eta;
    reference.setZero();
    reference(0, 0) = reference(1, 1) = coords_.mass();
    reference.block<2, 1>(0, 2) = a * perp(centroid);
    reference.block<1, 2>(2, 0) = reference.block<2, 1>(0, 2).transpose();
    reference(2, 2) = coords_.second_moment() + 2.0 * coords_.u0_dot_shape().dot(eta) + eta.dot(work_a_);
    coupling.resize(3, n_);
    coupling.template topRows<2>().noalias() = a * coords_.shape_integral();
    work_b_.noalias() = coords_.skew_ff().transpose() * eta;  // (ηᵀS̃)ᵀ
    coupling.row(2) = -(coords_.u0_cross_shape() + work_b_.transpose());
  }

  // Dense full mass matrix (3 + n)² — for tests, energy and small systems.
  Eigen::MatrixXd mass_matrix(ConstRef q) const {
    Eigen::Matrix3d reference;
    Eigen::Matrix<double, 3, Eigen::Dynamic> coupling;
    mass_blocks(q, reference, coupling);
    Eigen::MatrixXd m(size(), size());
    m.topLeftCorner<3, 3>() = reference;
    m.topRightCorner(3, n_) = coupling;
    m.bottomLeftCorner(n_, 3) = coupling.transpose();
    m.bottomRightCorner(n_, n_) = Eigen::MatrixXd(coords_.mass_ff());
    return m;
  }

  // Quadratic velocity vector Q_v (assigned).
  void quadratic_velocity(ConstRef q, ConstRef v, Ref out) const {
    const auto eta = q.tail(n_);
    const auto eta_dot = v.tail(n_);
    const double w = v(2);
    const Eigen::Matrix2d a = rotation(q(2));
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * eta;
    const Eigen::Vector2d centroid_rate = coords_.shape_integral() * eta_dot;
    out.head<2>() = w * w * (a * centroid) - 2.0 * w * (a * perp(centroid_rate));
    work_a_.noalias() = coords_.mass_ff() * eta;  // M_ff η
    out(2) = -2.0 * w * (coords_.u0_dot_shape().dot(eta_dot) + work_a_.dot(eta_dot));
    work_b_.noalias() = coords_.skew_ff() * eta_dot;  // S̃ η̇
    out.tail(n_) = w * w * (coords_.u0_dot_shape().transpose() + work_a_) - 2.0 * w * work_b_;
  }

  // Adds the generalized force of a global-frame force F applied at a point (paper eq. 13).
  void add_point_force(ConstRef q, const BodyPoint& p, const Eigen::Vector2d& force, Ref generalized) const {
    const Eigen::Matrix2d a = rotation(q(2));
    generalized.head<2>() += force;
    generalized(2) += force.dot(a * perp(local_position(q, p)));
    generalized.tail(n_).noalias() += p.shape.transpose() * (a.transpose() * force);
  }

  // Adds the generalized gravity force for the acceleration of gravity g (global frame).
  void add_gravity(ConstRef q, const Eigen::Vector2d& gravity, Ref generalized) const {
    const auto eta = q.tail(n_);
    const Eigen::Matrix2d a = rotation(q(2));
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * eta;
    generalized.head<2>() += coords_.mass() * gravity;
    generalized(2) += gravity.dot(a * perp(centroid));
    generalized.tail(n_).noalias() += coords_.shape_integral().transpose() * (a.transpose() * gravity);
  }

  // Geometric stiffening: K_σ (constant prestress) and K_c (per unit θ̇², centrifugal); both in the
  // coordinates' own matrix type (Coords::project of the nodal-space matrices).
  void set_prestress_stiffness(ElasticMatrix k) { prestress_ = std::move(k); }
  void set_centrifugal_stiffness(ElasticMatrix k) { centrifugal_ = std::move(k); }
  bool has_prestress() const { return prestress_.size() > 0; }
  bool has_centrifugal_stiffening() const { return centrifugal_.size() > 0; }

  // Adds −Kη − βKη̇ − K_σ η − θ̇² K_c η.
  void add_elastic_force(ConstRef q, ConstRef v, Ref generalized) const {
    work_a_ = q.tail(n_) + beta_ * v.tail(n_);
    generalized.tail(n_).noalias() -= coords_.stiffness() * work_a_;
    if (has_prestress()) generalized.tail(n_).noalias() -= prestress_ * q.tail(n_);
    if (has_centrifugal_stiffening()) {
      work_b_.noalias() = centrifugal_ * q.tail(n_);
      generalized.tail(n_) -= (v(2) * v(2)) * work_b_;
    }
  }

  double kinetic_energy(ConstRef q, ConstRef v) const {
    Eigen::Matrix3d reference;
    Eigen::Matrix<double, 3, Eigen::Dynamic> coupling;
    mass_blocks(q, reference, coupling);
    const auto eta_dot = v.tail(n_);
    const Eigen::Vector3d vr = v.head<3>();
    work_a_.noalias() = coords_.mass_ff() * eta_dot;
    return 0.5 * vr.dot(reference * vr) + vr.dot(coupling * eta_dot) + 0.5 * eta_dot.dot(work_a_);
  }
  // ½ηᵀ(K + K_σ)η: elastic energy plus the second-order work of the constant prestress.
  double strain_energy(ConstRef q) const {
    const auto eta = q.tail(n_);
    work_a_.noalias() = coords_.stiffness() * eta;
    if (has_prestress()) work_a_.noalias() += prestress_ * eta;
    return 0.5 * eta.dot(work_a_);
  }
  // V = −gᵀ ∫ρ r = −gᵀ (m R + A ∫ρū).
  double gravity_potential(ConstRef q, const Eigen::Vector2d& gravity) const {
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * q.tail(n_);
    return -gravity.dot(coords_.mass() * q.head<2>() + rotation(q(2)) * centroid);
  }

 private:
  Coords coords_;
  double beta_;
  ElasticMatrix prestress_;    // empty: no static stiffening
  ElasticMatrix centrifugal_;  // empty: no centrifugal stiffening
  Eigen::Index n_;
  mutable Vector work_a_;  // workspace, sized once: the hot path allocates nothing
  mutable Vector work_b_;
};

}  // namespace ffrf::coupling
