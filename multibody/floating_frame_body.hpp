// The planar floating-frame flexible body (paper §3, eqs. 6–22), written once over the elastic-
// coordinate interface (fem/elastic_coordinates.hpp): a point is r = R + A(θ)(ū0 + SΦη), the
// body coordinates are q = (R_x, R_y, θ, η). With the inertia invariants m, s0, J0, S̄, d, c, M_ff,
// S̃ (fem/shape_integrals.hpp) and ū_c = s0 + S̄η the mass matrix (eq. 19.d) is
//   M_RR = m I,  M_Rθ = A Ĩ ū_c,  M_Rf = A S̄,  M_θθ = J0 + 2dη + ηᵀM_ffη,
//   M_θf = −(c + ηᵀS̃),  M_ff,
// and the quadratic velocity vector Q_v = −Ṁq̇ + ∂T/∂q (eq. 20.c) is
//   Q_v,R = θ̇² A ū_c − 2θ̇ A Ĩ S̄ η̇,  Q_v,θ = −2θ̇ (d + ηᵀM_ff) η̇,  Q_v,f = θ̇² (dᵀ + M_ff η) − 2θ̇ S̃ η̇.
// Point forces by virtual work (eq. 13), gravity from V = −gᵀ∫ρr, elastic force −Kη (eq. 16)
// and Rayleigh structural damping of the elastic motion −(αM_ff + βK)η̇ (α = 0: stiffness-proportional). Optional geometric (stress) stiffening adds
// −(K_σ + θ̇² K_c)η: K_σ the geometric stiffness of a constant reference axial force (static
// prestress), K_c that of the centrifugal axial force per unit θ̇² (docs/theory.md §9, §11). Derivation: docs/theory.md §2; checked
// against the independent sympy derivation tests/coupling/one_element_reference.hpp.
// The derivatives of these terms with respect to the elastic coordinates (for the Newton matrices) are
// written out in add_elastic_derivatives; docs/theory.md §12 derives them.
// A rigid body is the same body with zero elastic coordinates.
// The body is immutable once built (threads share it: a sweep runs one model on several threads): every evaluation that needs
// scratch vectors takes a BodyWorkspace, which each user (one CraneEquations instance) owns; the
// overloads without one allocate their own (tests, energies, anything off the hot path).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <type_traits>

#include "solve/bordered_band_matrix.hpp"
#include "multibody/planar.hpp"
#include "fem/elastic_coordinates.hpp"

namespace ffrf::multibody {

// A material point of the body: undeformed position ū0 and its shape rows S(x)Φ.
struct BodyPoint {
  Eigen::Vector2d undeformed = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, Eigen::Dynamic> shape;
};

// Scratch vectors of the body's evaluations (M_ff η, S̃ η̇, ...), sized once: the hot path allocates
// nothing. One per evaluating object, never shared between threads.
struct BodyWorkspace {
  explicit BodyWorkspace(Eigen::Index elastic_size = 0) : first(elastic_size), second(elastic_size) {}
  Eigen::VectorXd first, second;
};

template <fem::ElasticCoordinates Coords>
class FloatingFrameBody {
 public:
  // The planar body (frame pose (R, θ), q(2) the angle); a spatial body is a second class for the
  // spatial space's coordinates.
  using Space = typename Coords::Space;
  static_assert(std::is_same_v<Space, linalg::Planar>, "FloatingFrameBody is the planar floating frame");

  using ElasticMatrix = typename Coords::Matrix;
  using Vector = Eigen::VectorXd;
  using ConstRef = Eigen::Ref<const Eigen::VectorXd>;
  using Ref = Eigen::Ref<Eigen::VectorXd>;

  // stiffness_damping β [s], mass_damping α [1/s]: structural damping force −(αM_ff + βK)η̇ on the
  // elastic coordinates (the motion relative to the frame: a rigid motion is not damped).
  FloatingFrameBody(Coords coords, double stiffness_damping, double mass_damping = 0.0)
      : coords_(std::move(coords)), beta_(stiffness_damping), alpha_(mass_damping), n_(static_cast<Eigen::Index>(coords_.size())) {}
  BodyWorkspace workspace() const { return BodyWorkspace(n_); }

  Eigen::Index elastic_size() const { return n_; }
  Eigen::Index size() const { return 3 + n_; }
  const Coords& coords() const { return coords_; }
  double stiffness_damping() const { return beta_; }
  double mass_damping() const { return alpha_; }

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

  // A point's motion with A(θ) and its deformed local position computed once (the wire's hot path):
  // lever = A(ū0 + Sη) from R, position = R + lever, velocity = Ṙ + θ̇ Ĩ lever + A S η̇.
  struct PointMotion {
    Eigen::Matrix2d rotation;
    Eigen::Vector2d lever, position, velocity;
  };
  PointMotion point_motion(ConstRef q, ConstRef v, const BodyPoint& p) const {
    PointMotion m;
    m.rotation = rotation(q(2));
    m.lever = m.rotation * local_position(q, p);
    m.position = q.head<2>() + m.lever;
    m.velocity = v.head<2>() + v(2) * perp(m.lever) + m.rotation * (p.shape * v.tail(n_));
    return m;
  }
  // add_point_force with the point's motion at hand.
  void add_point_force(const PointMotion& m, const BodyPoint& p, const Eigen::Vector2d& force, Ref generalized) const {
    generalized.head<2>() += force;
    generalized(2) += force.dot(perp(m.lever));
    generalized.tail(n_).noalias() += p.shape.transpose() * (m.rotation.transpose() * force);
  }

  // Mass matrix blocks: reference (3×3 over R, θ) and reference–elastic coupling (3×n);
  // the elastic block is the constant coords().mass_ff().
  void mass_blocks(ConstRef q, Eigen::Matrix3d& reference, Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling,
                   BodyWorkspace& work) const {
    const auto eta = q.tail(n_);
    const Eigen::Matrix2d a = rotation(q(2));
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * eta;  // ∫ρū
    work.first.noalias() = coords_.mass_ff() * eta;
    assemble_mass_blocks(eta, a, a * perp(centroid), reference, coupling, work);
  }
  void mass_blocks(ConstRef q, Eigen::Matrix3d& reference, Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling) const {
    BodyWorkspace work(n_);
    mass_blocks(q, reference, coupling, work);
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
    BodyWorkspace work(n_);
    quadratic_velocity(q, v, out, work);
  }
  void quadratic_velocity(ConstRef q, ConstRef v, Ref out, BodyWorkspace& work) const {
    const auto eta = q.tail(n_);
    const auto eta_dot = v.tail(n_);
    const double w = v(2);
    const Eigen::Matrix2d a = rotation(q(2));
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * eta;
    const Eigen::Vector2d centroid_rate = coords_.shape_integral() * eta_dot;
    out.head<2>() = w * w * (a * centroid) - 2.0 * w * (a * perp(centroid_rate));
    work.first.noalias() = coords_.mass_ff() * eta;  // M_ff η
    out(2) = -2.0 * w * (coords_.u0_dot_shape().dot(eta_dot) + work.first.dot(eta_dot));
    work.second.noalias() = coords_.skew_ff() * eta_dot;  // S̃ η̇
    out.tail(n_) = w * w * (coords_.u0_dot_shape().transpose() + work.first) - 2.0 * w * work.second;
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
  const ElasticMatrix& prestress_stiffness() const { return prestress_; }
  const ElasticMatrix& centrifugal_stiffness() const { return centrifugal_; }

  // Adds −Kη − βKη̇ − αM_ff η̇ − K_σ η − θ̇² K_c η.
  void add_elastic_force(ConstRef q, ConstRef v, Ref generalized) const {
    BodyWorkspace work(n_);
    add_elastic_force(q, v, generalized, work);
  }
  void add_elastic_force(ConstRef q, ConstRef v, Ref generalized, BodyWorkspace& work) const {
    work.first = q.tail(n_) + beta_ * v.tail(n_);
    generalized.tail(n_).noalias() -= coords_.stiffness() * work.first;
    if (alpha_ != 0.0) generalized.tail(n_).noalias() -= alpha_ * (coords_.mass_ff() * v.tail(n_));
    if (has_prestress()) generalized.tail(n_).noalias() -= prestress_ * q.tail(n_);
    if (has_centrifugal_stiffening()) {
      work.second.noalias() = centrifugal_ * q.tail(n_);
      generalized.tail(n_) -= (v(2) * v(2)) * work.second;
    }
  }

  // The body's own loads Q_v + Q_gravity + Q_elastic (assigned to `force`) and its mass blocks at
  // (q, v) in one pass, the products M_ff η, S̄η, S̄η̇, S̃ᵀη and A computed once: the hot path of the
  // equations of motion. The same as quadratic_velocity + add_gravity + add_elastic_force + mass_blocks.
  void loads_and_mass_blocks(ConstRef q, ConstRef v, const Eigen::Vector2d& gravity, Ref force, Eigen::Matrix3d& reference,
                             Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling) const {
    BodyWorkspace work(n_);
    loads_and_mass_blocks(q, v, gravity, force, reference, coupling, work);
  }
  void loads_and_mass_blocks(ConstRef q, ConstRef v, const Eigen::Vector2d& gravity, Ref force, Eigen::Matrix3d& reference,
                             Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling, BodyWorkspace& work) const {
    const auto eta = q.tail(n_);
    const auto eta_dot = v.tail(n_);
    const double w = v(2);
    const Eigen::Matrix2d a = rotation(q(2));
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * eta;  // ∫ρū
    const Eigen::Vector2d centroid_rate = coords_.shape_integral() * eta_dot;
    work.first.noalias() = coords_.mass_ff() * eta;      // M_ff η
    work.second.noalias() = coords_.skew_ff() * eta_dot;  // S̃ η̇
    const Eigen::Vector2d a_centroid = a * centroid;
    force.template head<2>() = w * w * a_centroid - 2.0 * w * (a * perp(centroid_rate)) + coords_.mass() * gravity;
    force(2) = -2.0 * w * (coords_.u0_dot_shape().dot(eta_dot) + work.first.dot(eta_dot)) + gravity.dot(perp(a_centroid));
    force.tail(n_) = w * w * (coords_.u0_dot_shape().transpose() + work.first) - 2.0 * w * work.second;
    force.tail(n_).noalias() += coords_.shape_integral().transpose() * (a.transpose() * gravity);
    assemble_mass_blocks(eta, a, perp(a_centroid), reference, coupling, work);
    work.first = eta + beta_ * eta_dot;
    force.tail(n_).noalias() -= coords_.stiffness() * work.first;
    if (alpha_ != 0.0) {
      work.second.noalias() = coords_.mass_ff() * eta_dot;
      force.tail(n_).noalias() -= alpha_ * work.second;
    }
    if (has_prestress()) force.tail(n_).noalias() -= prestress_ * eta;
    if (has_centrifugal_stiffening()) {
      work.second.noalias() = centrifugal_ * eta;
      force.tail(n_) -= (w * w) * work.second;
    }
  }

  // Kinetic energy ½ vᵀ M v from mass blocks already at hand (as loads_and_mass_blocks fills them).
  double kinetic_energy(ConstRef v, const Eigen::Matrix3d& reference, const Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling) const {
    BodyWorkspace work(n_);
    return kinetic_energy(v, reference, coupling, work);
  }
  double kinetic_energy(ConstRef v, const Eigen::Matrix3d& reference, const Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling,
                        BodyWorkspace& work) const {
    const auto eta_dot = v.tail(n_);
    const Eigen::Vector3d vr = v.head<3>();
    work.first.noalias() = coords_.mass_ff() * eta_dot;
    return 0.5 * vr.dot(reference * vr) + vr.dot(coupling * eta_dot) + 0.5 * eta_dot.dot(work.first);
  }

  // Elastic columns of the body's linearization: with F = Q_v + Q_gravity + Q_elastic − M(q) a (the
  // body's own forces and inertia; point forces excluded) at (q, v) and accelerations a (3 + n),
  // fills the reference rows K_ref = −∂F_ref/∂η, D_ref = −∂F_ref/∂η̇ (3 × n) and adds the elastic
  // block −∂F_f/∂η, −∂F_f/∂η̇ into `stiffness`, `damping` at rows and columns offset + (0 … n − 1):
  //   −∂F_R/∂η = −θ̇² A S̄ + θ̈ A Ĩ S̄,  −∂F_R/∂η̇ = 2θ̇ A Ĩ S̄,
  //   −∂F_θ/∂η = 2θ̇ (M_ff η̇)ᵀ − gᵀ A Ĩ S̄ + R̈ᵀ A Ĩ S̄ + 2θ̈ (dᵀ + M_ff η)ᵀ − (S̃ a_η)ᵀ,
  //   −∂F_θ/∂η̇ = 2θ̇ (dᵀ + M_ff η)ᵀ,
  //   −∂F_f/∂η = K + K_σ + θ̇² K_c − θ̇² M_ff − θ̈ S̃ᵀ,  −∂F_f/∂η̇ = βK + αM_ff + 2θ̇ S̃.
  void add_elastic_derivatives(ConstRef q, ConstRef v, ConstRef a, const Eigen::Vector2d& gravity,
                               Eigen::Matrix<double, 3, Eigen::Dynamic>& stiffness_reference,
                               Eigen::Matrix<double, 3, Eigen::Dynamic>& damping_reference, solve::BorderedBandMatrix& stiffness,
                               solve::BorderedBandMatrix& damping, int offset, BodyWorkspace& work) const {
    const auto eta = q.tail(n_);
    const auto eta_dot = v.tail(n_);
    const auto eta_ddot = a.tail(n_);
    const double w = v(2), w_dot = a(2);
    const Eigen::Matrix2d rotated_perp = rotation(q(2)) * (Eigen::Matrix2d() << 0.0, -1.0, 1.0, 0.0).finished();  // A Ĩ
    const Eigen::Matrix<double, 2, Eigen::Dynamic>& shape = coords_.shape_integral();  // S̄
    stiffness_reference.resize(3, n_);
    damping_reference.resize(3, n_);
    stiffness_reference.template topRows<2>().noalias() = (w_dot * rotated_perp - w * w * rotation(q(2))) * shape;
    damping_reference.template topRows<2>().noalias() = (2.0 * w * rotated_perp) * shape;
    work.first.noalias() = coords_.mass_ff() * eta;      // M_ff η
    work.second.noalias() = coords_.mass_ff() * eta_dot;  // M_ff η̇
    const Eigen::RowVector2d lever = (a.head<2>() - gravity).transpose() * rotated_perp;  // (R̈ − g)ᵀ A Ĩ
    stiffness_reference.row(2).noalias() = lever * shape;
    stiffness_reference.row(2) += 2.0 * w * work.second.transpose() + 2.0 * w_dot * (coords_.u0_dot_shape() + work.first.transpose());
    work.second.noalias() = coords_.skew_ff() * eta_ddot;  // S̃ a_η
    stiffness_reference.row(2) -= work.second.transpose();
    damping_reference.row(2) = 2.0 * w * (coords_.u0_dot_shape() + work.first.transpose());
    add_scaled(coords_.stiffness(), 1.0, false, stiffness, offset);
    if (has_prestress()) add_scaled(prestress_, 1.0, false, stiffness, offset);
    if (has_centrifugal_stiffening()) add_scaled(centrifugal_, w * w, false, stiffness, offset);
    add_scaled(coords_.mass_ff(), -w * w, false, stiffness, offset);
    add_scaled(coords_.skew_ff(), -w_dot, true, stiffness, offset);
    add_scaled(coords_.stiffness(), beta_, false, damping, offset);
    add_scaled(coords_.mass_ff(), alpha_, false, damping, offset);
    add_scaled(coords_.skew_ff(), 2.0 * w, false, damping, offset);
  }

  // target(offset + i, offset + j) += scale · m(i, j) (or m(j, i) when transposed), sparse or dense m.
  static void add_scaled(const ElasticMatrix& m, double scale, bool transposed, solve::BorderedBandMatrix& target, int offset) {
    if (scale == 0.0) return;
    if constexpr (std::is_base_of_v<Eigen::SparseMatrixBase<ElasticMatrix>, ElasticMatrix>) {
      for (int k = 0; k < m.outerSize(); ++k) {
        for (typename ElasticMatrix::InnerIterator it(m, k); it; ++it) {
          const int i = static_cast<int>(transposed ? it.col() : it.row()), j = static_cast<int>(transposed ? it.row() : it.col());
          target.at(offset + i, offset + j) += scale * it.value();
        }
      }
    } else {
      for (int j = 0; j < m.cols(); ++j) {
        for (int i = 0; i < m.rows(); ++i) target.at(offset + i, offset + j) += scale * (transposed ? m(j, i) : m(i, j));
      }
    }
  }

  double kinetic_energy(ConstRef q, ConstRef v) const {
    Eigen::Matrix3d reference;
    Eigen::Matrix<double, 3, Eigen::Dynamic> coupling;
    BodyWorkspace work(n_);
    mass_blocks(q, reference, coupling, work);
    return kinetic_energy(v, reference, coupling, work);
  }
  // ½ηᵀ(K + K_σ)η: elastic energy plus the second-order work of the constant prestress.
  double strain_energy(ConstRef q) const {
    BodyWorkspace work(n_);
    return strain_energy(q, work);
  }
  double strain_energy(ConstRef q, BodyWorkspace& work) const {
    const auto eta = q.tail(n_);
    work.first.noalias() = coords_.stiffness() * eta;
    if (has_prestress()) work.first.noalias() += prestress_ * eta;
    return 0.5 * eta.dot(work.first);
  }
  // V = −gᵀ ∫ρ r = −gᵀ (m R + A ∫ρū).
  double gravity_potential(ConstRef q, const Eigen::Vector2d& gravity) const {
    const Eigen::Vector2d centroid = coords_.first_moment() + coords_.shape_integral() * q.tail(n_);
    return -gravity.dot(coords_.mass() * q.head<2>() + rotation(q(2)) * centroid);
  }

 private:
  // The mass blocks from A(θ), M_Rθ = A Ĩ ∫ρū and work.first = M_ff η (uses work.second).
  void assemble_mass_blocks(ConstRef eta, const Eigen::Matrix2d& a, const Eigen::Vector2d& rotation_column,
                            Eigen::Matrix3d& reference, Eigen::Matrix<double, 3, Eigen::Dynamic>& coupling,
                            BodyWorkspace& work) const {
    reference.setZero();
    reference(0, 0) = reference(1, 1) = coords_.mass();
    reference.block<2, 1>(0, 2) = rotation_column;
    reference.block<1, 2>(2, 0) = reference.block<2, 1>(0, 2).transpose();
    reference(2, 2) = coords_.second_moment() + 2.0 * coords_.u0_dot_shape().dot(eta) + eta.dot(work.first);
    coupling.resize(3, n_);
    coupling.template topRows<2>().noalias() = a * coords_.shape_integral();
    work.second.noalias() = coords_.skew_ff().transpose() * eta;  // (ηᵀS̃)ᵀ
    coupling.row(2) = -(coords_.u0_cross_shape() + work.second.transpose());
  }

  Coords coords_;
  double beta_;
  double alpha_;
  ElasticMatrix prestress_;    // empty: no static stiffening
  ElasticMatrix centrifugal_;  // empty: no centrifugal stiffening
  Eigen::Index n_;
};

}  // namespace ffrf::multibody
