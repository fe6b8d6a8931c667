// Template definitions of the crane equations (multibody/crane_model.hpp); included only by
// multibody/crane_model.cpp, which instantiates them for the nodal and the modal coordinates.
// CraneEquationsOf is the per-instance half (Pinocchio's Data): it reads the shared, immutable
// CraneModelOf (multibody/crane_model_of.hpp) and owns only its workspace (the vectors and
// matrices one evaluation fills, allocated once) and its run state (the radiation memory).
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "multibody/crane_model_of.hpp"
#include "sea/excitation_record.hpp"
#include "sea/hull_pressure_recorded.hpp"
#include "multibody/wire_rope.hpp"

namespace ffrf::multibody::detail {

template <fem::ElasticCoordinates Coords>
class CraneEquationsOf final : public CraneEquations {
 public:
  explicit CraneEquationsOf(std::shared_ptr<const CraneModelOf<Coords>> shared);

  int minimal_size() const override { return elastic_at_ + n_; }
  Eigen::VectorXd initial_guess() const override;
  void minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) override;
  void static_residual(ConstRef z, Ref residual) override;
  void minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) override;
  Eigen::VectorXd static_residual_scale() const override;
  Eigen::VectorXd coordinate_scale() const override;
  CraneOutputs minimal_outputs(double t, ConstRef z, ConstRef z_dot) override;

  int full_size() const override { return elastic_at_ + 3 + n_; }
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
  int constraint_count() const override { return 3; }  // the clamp at B: x, y and angle
  double wire_stretch_minimal(double t, ConstRef z) override;
  double wire_stretch_full(ConstRef q) override;
  int cargo_offset() const override { return has_cargo() ? cargo_at_ : -1; }
  int elastic_size() const override { return n_; }
  HullLoadCounts hull_load_counts() const override { return hull_load_counts_; }
  const sea::IncidentWaveRecord* wave_record() const override { return m_.hull.wave_record.get(); }
  std::string exact_kinematics_reason() const override { return m_.hull.exact_kinematics_reason; }
  BandStructure minimal_structure() const override { return shared_->minimal_structure; }
  void minimal_jacobian(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, SecondOrderJacobian& out) override;
  // The hull and cargo columns by differences (twice: positions, velocities) plus the base residual.
  int minimal_jacobian_evaluations() const override { return 2 * elastic_at_ + 1; }
  BandStructure full_structure() const override { return shared_->full_structure; }
  int full_jacobian_evaluations() const override { return 2 * (elastic_at_ + 3) + 1; }
  void full_jacobian(double t, ConstRef q, ConstRef v, ConstRef v_dot, SecondOrderJacobian& out) override;
  CraneOutputs minimal_outputs_with_accelerations(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot) override;

 private:
  bool hull_free() const { return !m_.hull.fixed; }
  bool has_cargo() const { return m_.cargo.present; }
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
  Eigen::Vector3d cargo_inertia() const { return {m_.cargo.mass, m_.cargo.mass, m_.cargo.pitch_inertia}; }
  // Boom frame (R_B, θ_B) and its velocity from the hull pose and velocity (the clamp at B).
  void mount_boom(const Eigen::Vector3d& hull_q, const Eigen::Vector3d& hull_v);
  // Loads on hull, cargo and boom (boom_q_, boom_v_ must be set) at time t. with_wave = false is
  // the static problem: calm water and a bilateral wire (see wire_state).
  void evaluate_loads(double t, const Eigen::Vector3d& hull_q, const Eigen::Vector3d& hull_v,
                      const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v, bool with_wave);
  // The boom's own loads (quadratic velocity, gravity, elastic) and the wire's into boom_force_ and
  // cargo_force_, and the boom's mass blocks: evaluate_loads without the hull.
  void boom_and_wire_loads(const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v, bool bilateral_wire);
  // The wire's pull added to `boom` (3 + n) and `cargo`; sets wire_.
  void add_wire_loads(const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v, bool bilateral, Ref boom,
                      Eigen::Vector3d& cargo);
  // Minimal-coordinate residual Q_z − M_z a at (t, z, ż) with a given (all loads), and the wire's
  // share of it alone (for the wire's columns of the Jacobian).
  void minimal_residual(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, Ref out);
  void minimal_wire_residual(double t, ConstRef z, ConstRef z_dot, Ref out);
  // Full-coordinate residual Q − M a (no constraint terms) and the wire's share of it.
  void full_residual(double t, ConstRef q, ConstRef v, ConstRef v_dot, Ref out);
  void full_wire_residual(ConstRef q, ConstRef v, Ref out);
  // Known part of the boom frame's acceleration (see frame_known_acc_) at t for the hull's velocity.
  Eigen::Vector3d frame_known_acceleration(double t, const Eigen::Vector3d& hull_v) const;
  // J_r of the clamp (hull velocities → boom frame velocities) for the current mount_offset_.
  Eigen::Matrix3d mount_jacobian() const;
  // Minimal-coordinate generalized forces (hull rows through Jᵀ, convective term included).
  void minimal_forces(double t, ConstRef z, ConstRef z_dot, bool with_wave);
  // Q_z of the last minimal_forces: hull rows (when free), cargo rows (with a cargo), elastic rows.
  void gather_minimal_forces(Ref forces) const;
  void split_minimal(double t, ConstRef z, ConstRef z_dot, Eigen::Vector3d& hull_q, Eigen::Vector3d& hull_v) const;
  // Boom axial force at the root from the joint reaction on the boom (tension > 0).
  double root_axial_force(const Eigen::Vector3d& reaction, double frame_angle) const {
    return -(reaction.x() * std::cos(frame_angle) + reaction.y() * std::sin(frame_angle));
  }
  CraneOutputs common_outputs(const Eigen::Vector3d& hull_q, const Eigen::Vector3d& hull_v,
                              const Eigen::Vector3d& cargo_q, const Eigen::Vector3d& cargo_v);
  void boom_tip_kinematics(const Eigen::Vector3d& cargo_q, Eigen::Vector2d& tip, Eigen::Vector2d& hook) const;

  // The shared model (read-only) and, for brevity, its CraneParameters and layout.
  std::shared_ptr<const CraneModelOf<Coords>> shared_;
  const CraneParameters<Coords>& m_;
  const int n_;
  const int cargo_at_;    // index of the cargo block (0 with a fixed hull, 3 otherwise)
  const int elastic_at_;  // minimal: index of η; full: index of the boom frame (R_B, θ_B) (cargo_at_ + 3 or + 0)
  // workspace (allocated once)
  BodyWorkspace boom_work_;  // the boom's own scratch vectors (multibody/floating_frame_body.hpp)
  Eigen::VectorXd boom_q_, boom_v_, boom_force_;
  Eigen::Vector2d mount_offset_ = Eigen::Vector2d::Zero();  // A(θ1) b
  Eigen::Vector3d hull_force_ = Eigen::Vector3d::Zero(), cargo_force_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d hull_rhs_ = Eigen::Vector3d::Zero();
  Eigen::VectorXd elastic_rhs_;
  Eigen::VectorXd schur_rhs_column_;
  // The two-column solve's workspace and M_ff⁻¹ M_fR (n × 3) before the clamp's J_r.
  Eigen::Matrix<double, Eigen::Dynamic, 2> pair_rhs_, pair_solution_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> frame_columns_;
  Eigen::Matrix3d boom_reference_mass_ = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, Eigen::Dynamic> boom_coupling_;
  Eigen::Matrix<double, 3, Eigen::Dynamic> hull_elastic_mass_;
  Eigen::Matrix<double, Eigen::Dynamic, 3> schur_columns_;
  Eigen::VectorXd schur_rhs_;
  // Known part of the boom frame's acceleration (R̈_B, θ̈_B): the convective −θ̇1² A1 b, plus the
  // prescribed acceleration of a driven base.
  Eigen::Vector3d frame_known_acc_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d joint_reaction_ = Eigen::Vector3d::Zero();
  WireState wire_;
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
#include "multibody/crane_equations_full.ipp"
#include "multibody/crane_equations_jacobian.ipp"
