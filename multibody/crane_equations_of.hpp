// Template definitions of the crane equations (multibody/crane_model.hpp); included only by
// multibody/crane_model.cpp, which instantiates them for the nodal and the modal coordinates, each with
// the hull's fixed 3 × 3 rigid block and with an articulated one (a pinned heel, bodies pinned to the
// hull: up to max_rigid_block coordinates).
// CraneEquationsOf is the per-instance half (Pinocchio's Data): it reads the shared, immutable
// CraneModelOf (multibody/crane_model_of.hpp) and owns only its workspace (the vectors and
// matrices one evaluation fills, allocated once) and its run state (the radiation memory).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <type_traits>
#include <vector>

#include "multibody/boom_stress.hpp"
#include "multibody/crane_model_of.hpp"
#include "sea/excitation_record.hpp"
#include "sea/hull_pressure_recorded.hpp"
#include "multibody/rigid_body.hpp"
#include "multibody/wire_rope.hpp"

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords, bool Articulated>
class CraneEquationsOf final : public CraneEquations {
 public:
  explicit CraneEquationsOf(std::shared_ptr<const CraneModelOf<Coords>> shared);

  int minimal_size() const override { return layout_.minimal_size(); }
  Eigen::VectorXd initial_guess() const override;
  void minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) override;
  void static_residual(ConstRef z, Ref residual) override;
  void minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) override;
  Eigen::VectorXd static_residual_scale() const override;
  Eigen::VectorXd coordinate_scale() const override;
  CraneOutputs minimal_outputs(double t, ConstRef z, ConstRef z_dot) override;

  int full_size() const override { return layout_.full_size(); }
  void full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const override;
  void full_mass_times(ConstRef q, ConstRef a, Ref out) override;
  void full_forces(double t, ConstRef q, ConstRef v, Ref out) override;
  void constraint(double t, ConstRef q, Ref c) const override;
  void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const override;
  void constraint_time_derivative(double t, Ref c_t) const override;
  void constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const override;
  using CraneEquations::full_mass_matrix;
  void full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) override;
  CraneOutputs full_outputs(double t, ConstRef q, ConstRef v, ConstRef lambda) override;
  // The heel at B: a clamp holds the frame's position and angle (3 rows), a pin its position (2); each
  // pinned body's pin holds its pivot (2).
  int constraint_count() const override { return layout_.constraint_count(); }
  int wire_count() const override { return static_cast<int>(m_.wires.size()); }
  int hoist_wire() const override { return m_.hoist_wire; }
  std::string wire_name(int wire) const override { return m_.wires[wire].name; }
  WireRole wire_role(int wire) const override { return m_.wires[wire].role; }
  void wire_stretches_minimal(double t, ConstRef z, Ref stretch) override;
  void wire_stretches_full(double t, ConstRef q, Ref stretch) override;
  const CraneLayout& layout() const override { return layout_; }
  std::string body_name(int body) const override { return m_.bodies[body].name; }
  int cargo_body() const override { return m_.cargo; }
  int elastic_size() const override { return n_; }
  HullLoadCounts hull_load_counts() const override { return hull_load_counts_; }
  const sea::IncidentWaveRecord* wave_record() const override { return m_.hull.wave_record.get(); }
  std::string exact_kinematics_reason() const override { return m_.hull.exact_kinematics_reason; }
  BandStructure minimal_structure() const override { return shared_->minimal_structure; }
  void minimal_jacobian(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, SecondOrderJacobian& out) override;
  // The hull, cargo and heel columns by differences (twice: positions, velocities) plus the base residual.
  int minimal_jacobian_evaluations() const override { return 2 * layout_.elastic + 1; }
  BandStructure full_structure() const override { return shared_->full_structure; }
  int full_jacobian_evaluations() const override { return 2 * (layout_.frame + 3) + 1; }
  void full_jacobian(double t, ConstRef q, ConstRef v, ConstRef v_dot, SecondOrderJacobian& out) override;
  CraneOutputs minimal_outputs_with_accelerations(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot) override;
  const BoomStressProfile* boom_stress_profile() const override;

 private:
  // The rigid block — the hull's coordinates (3, when it floats), the pinned bodies' angles, the pinned
  // heel's angle (1) — and its blocks: r = layout_.rigid_size() ≤ max_rigid_block. Without a pinned heel
  // or pinned bodies the block is the hull's 3 (or none with a held hull) and fixed-size.
  template <class PinnedType, class ClampedType>
  using RigidBlock = std::conditional_t<Articulated, PinnedType, ClampedType>;
  static constexpr int R = max_rigid_block;
  using FrameJacobian = RigidBlock<Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, R>, Eigen::Matrix3d>;  // J: 3 × r
  using RigidMatrix = RigidBlock<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, R, R>, Eigen::Matrix3d>;  // r × r
  using RigidVector = RigidBlock<Eigen::Matrix<double, Eigen::Dynamic, 1, 0, R, 1>, Eigen::Vector3d>;  // r
  using RigidCoupling = RigidBlock<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, R, Eigen::Dynamic>,
                                   Eigen::Matrix<double, 3, Eigen::Dynamic>>;  // r × n
  using RigidColumns = RigidBlock<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, Eigen::Dynamic, R>,
                                  Eigen::Matrix<double, Eigen::Dynamic, 3>>;  // n × r
  // A pinned body's velocity transformation over the rigid block (J_b: 3 × r).
  using BodyJacobian = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, R>;

  bool hull_free() const { return layout_.hull >= 0; }
  bool clamped() const { return layout_.heel < 0; }
  bool has_pinned_bodies() const { return layout_.pinned_count > 0; }
  // Pose, velocity and acceleration of a held or driven hull at t.
  Eigen::Vector3d base_pose(double t) const { return m_.hull.prescribed ? m_.hull.prescribed->pose(t) : m_.hull.support_pose; }
  Eigen::Vector3d base_velocity(double t) const {
    return m_.hull.prescribed ? m_.hull.prescribed->velocity(t) : Eigen::Vector3d::Zero();
  }
  Eigen::Vector3d base_acceleration(double t) const {
    return m_.hull.prescribed ? m_.hull.prescribed->acceleration(t) : Eigen::Vector3d::Zero();
  }
  // diag(m1, m1, I1) + the added mass (diagonal constants, or the BEM model's 3 × 3 A).
  Eigen::Matrix3d hull_rigid_inertia() const;
  // The hull's velocity history for the radiation memory: an accepted state at an output time.
  void record_hull_velocity(double t, const Eigen::Vector3d& hull_v) {
    if (hull_free()) radiation_.record(t, hull_v);
  }
  // A rigid body's diagonal mass over (x_G, y_G, θ).
  Eigen::Vector3d body_inertia(int body) const {
    const RigidBodyModel& b = m_.bodies[body];
    return {b.mass, b.mass, b.rotary_inertia};
  }
  // The bodies' states from minimal coordinates (hull_q_, hull_v_, bodies_, boom_q_, boom_v_;
  // velocities zero and z_dot not read when not `moving`), or from full ones.
  void set_minimal_state(double t, ConstRef z, ConstRef z_dot, bool moving = true);
  void set_full_state(double t, ConstRef q, ConstRef v);
  // Boom frame (R_B, θ_B) and its velocity from the hull's pose and velocity and the heel's angle.
  void mount_boom(double beta, double beta_rate);
  // A pinned body's pose and velocity from the hull's and its angle γ, γ̇ (with its levers).
  void mount_pinned_body(int body, double gamma, double gamma_rate);
  // Loads on the hull, the rigid bodies and the boom for the current body states at time t.
  // with_wave = false is the static problem: calm water and bilateral wires (see wire_state).
  void evaluate_loads(double t, bool with_wave);
  // The boom's own loads (quadratic velocity, gravity, elastic), the rigid bodies' weights and the
  // wires' pulls into boom_force_, hull_force_ and body_forces_, and the boom's mass blocks:
  // evaluate_loads without the hull's own.
  void boom_and_wire_loads(bool bilateral_wires);
  // Every wire's pull added to `boom` (3 + n), `hull` and each rigid body's `bodies`; sets wires_.
  void add_wire_loads(bool bilateral, Ref boom, Eigen::Vector3d& hull, std::vector<Eigen::Vector3d>& bodies);
  // A wire end's position (and velocity) for the current body states.
  struct EndMotion {
    typename FloatingFrameBody<Coords>::PointMotion boom;  // Body::boom
    RigidPointMotion rigid;                                // Body::hull, Body::rigid
    const Eigen::Vector2d& position(Body body) const { return body == Body::boom ? boom.position : rigid.position; }
    const Eigen::Vector2d& velocity(Body body) const { return body == Body::boom ? boom.velocity : rigid.velocity; }
  };
  EndMotion end_motion(const BodyAttachment& end) const;
  // Every wire's stretch ℓ − L0 for the current body states (set_minimal_state or set_full_state).
  void wire_stretches(Ref stretch) const;
  void add_end_force(const BodyAttachment& end, const EndMotion& motion, const Eigen::Vector2d& force, Ref boom,
                     Eigen::Vector3d& hull, std::vector<Eigen::Vector3d>& bodies) const;
  // Minimal-coordinate residual Q_z − M_z a at (t, z, ż) with a given (all loads), and the wires'
  // share of it alone (for the wires' columns of the Jacobian).
  void minimal_residual(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, Ref out);
  void minimal_wire_residual(double t, ConstRef z, ConstRef z_dot, Ref out);
  // Full-coordinate residual Q − M a (no constraint terms) and the wires' share of it.
  void full_residual(double t, ConstRef q, ConstRef v, ConstRef v_dot, Ref out);
  void full_wire_residual(double t, ConstRef q, ConstRef v, Ref out);
  // Known part of the boom frame's acceleration (see frame_known_acc_) at t for the hull's velocity.
  Eigen::Vector3d frame_known_acceleration(double t) const;
  // The heel's velocity transformation: the frame's velocity per rigid minimal coordinate (J).
  FrameJacobian frame_jacobian() const;
  // The rigid rows' own inertia (the hull's; none for the heel's angle), and the whole rigid block's
  // mass at the last minimal_forces: with the boom frame's Jᵀ M_RR J and the pinned bodies' J_bᵀ M_b J_b.
  RigidMatrix rigid_inertia() const;
  RigidMatrix rigid_mass() const;
  // The pinned bodies' share of the rigid block at the last state and loads: Σ J_bᵀ M_b J_b into
  // pinned_mass_ and Σ J_bᵀ (F_b − M_b a₀_b) added to `rigid` (a₀_b: the velocity-product and the
  // driven base's known acceleration); with `forces` alone (the wires' share) only the latter.
  void add_pinned_bodies(double t, const std::vector<Eigen::Vector3d>& forces, RigidVector& rigid, bool with_mass);
  BodyJacobian pinned_body_jacobian(int body) const;
  // Adds the frame's acceleration J z̈_r from the rigid coordinates' accelerations.
  void add_frame_acceleration(const RigidVector& rigid_a, Eigen::Vector3d& frame_a) const;
  // Minimal-coordinate generalized forces (rigid rows through Jᵀ, convective term included).
  void minimal_forces(double t, ConstRef z, ConstRef z_dot, bool with_wave);
  // Q_z of the last minimal_forces: hull rows (when free), free bodies' rows, the rigid block's pinned
  // bodies' and heel's rows, elastic rows.
  void gather_minimal_forces(Ref forces) const;
  // The rigid coordinates' values from z (hull's, pinned bodies', heel's) and back.
  RigidVector rigid_part(ConstRef z) const;
  void scatter_rigid(const RigidVector& rigid, Ref z) const;
  // Boom axial force at the root from the joint reaction on the boom (tension > 0).
  double root_axial_force(const Eigen::Vector3d& reaction, double frame_angle) const {
    return -(reaction.x() * std::cos(frame_angle) + reaction.y() * std::sin(frame_angle));
  }
  CraneOutputs common_outputs();
  // The stresses along the boom for the current body states and wires (after a load evaluation), the
  // frame's acceleration and the elastic accelerations: both recoveries' peaks into `out`, the
  // model's own as its channels and profile (crane_equations_stress.ipp).
  void add_boom_stress(const Eigen::Vector3d& frame_acceleration, ConstRef elastic_acceleration, CraneOutputs& out);
  // In full coordinates: the boom's accelerations from its loads and the heel's multipliers λ (the
  // frame's into the return value, the elastic ones into `elastic_acceleration`), for the stresses.
  Eigen::Vector3d full_boom_accelerations(ConstRef lambda, Eigen::VectorXd& elastic_acceleration) const;

  // The shared model (read-only) and, for brevity, its CraneParameters and layout.
  std::shared_ptr<const CraneModelOf<Coords>> shared_;
  const CraneParameters<Coords>& m_;
  const CraneLayout layout_;
  const int n_;
  // workspace (allocated once)
  BodyWorkspace boom_work_;  // the boom's own scratch vectors (multibody/floating_frame_body.hpp)
  Eigen::Vector3d hull_q_ = Eigen::Vector3d::Zero(), hull_v_ = Eigen::Vector3d::Zero();
  std::vector<PinnedBodyMotion> bodies_;  // each rigid body's pose and velocity (the levers: pinned ones)
  Eigen::VectorXd boom_q_, boom_v_, boom_force_;
  Eigen::Vector2d mount_offset_ = Eigen::Vector2d::Zero();  // A(θ1) b
  Eigen::Vector3d hull_force_ = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> body_forces_, wire_body_forces_;  // on each rigid body: all loads; the wires' alone
  RigidMatrix pinned_mass_;  // Σ J_bᵀ M_b J_b of the pinned bodies at the last minimal_forces
  RigidVector rigid_rhs_;
  FrameJacobian frame_jacobian_;
  Eigen::VectorXd elastic_rhs_;
  Eigen::VectorXd schur_rhs_column_;
  // The two-column solve's workspace and M_ff⁻¹ M_fR (n × 3) before the heel's J.
  Eigen::Matrix<double, Eigen::Dynamic, 2> pair_rhs_, pair_solution_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> frame_columns_;
  Eigen::Matrix3d boom_reference_mass_ = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, Eigen::Dynamic> boom_coupling_;
  RigidCoupling rigid_elastic_mass_;  // Jᵀ M_Rf
  RigidColumns schur_columns_;        // M_ff⁻¹ M_fR J
  Eigen::VectorXd schur_rhs_;
  // Known part of the boom frame's acceleration (R̈_B, θ̈_B): the convective −θ̇1² A1 b, plus the
  // prescribed acceleration of a driven base.
  Eigen::Vector3d frame_known_acc_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d joint_reaction_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d frame_acceleration_ = Eigen::Vector3d::Zero();  // (R̈_B, θ̈_B) of the last minimal accelerations
  // The stresses' workspace: the boom's motion, the wires' pulls on it, one profile per recovery.
  BoomMotion stress_motion_;
  std::vector<BoomPointLoad> boom_loads_;
  BoomStressWorkspace stress_work_;
  std::array<BoomStressProfile, 2> stress_profiles_;
  std::vector<WireState> wires_;  // each wire's state at the last load evaluation
  sea::WavePolynomials wave_polynomials_;  // the recorded sea at one time (sized on first use)
  HullLoadCounts hull_load_counts_;
  // run state: the history of m_.hull.radiation_memory (inactive without one)
  hydro::RadiationMemory radiation_;
  // workspace of the Jacobians (allocated once)
  Eigen::Matrix<double, 3, Eigen::Dynamic> reference_stiffness_, reference_damping_;
  Eigen::VectorXd jacobian_base_, jacobian_shifted_, jacobian_x_, jacobian_x_dot_, boom_a_, wire_boom_force_, full_inertia_;
};

}  // namespace ffrf::multibody::detail

#include "multibody/crane_equations_minimal.ipp"
#include "multibody/crane_equations_bodies.ipp"
#include "multibody/crane_equations_outputs.ipp"
#include "multibody/crane_equations_wires.ipp"
#include "multibody/crane_equations_full.ipp"
#include "multibody/crane_equations_stress.ipp"
#include "multibody/crane_equations_jacobian.ipp"
