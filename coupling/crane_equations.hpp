// What the solvers (KINSOL, CVODE, IDA, generalized-α) see of the crane: an abstract set of
// equations in two coordinate sets, so the solvers need not know the elastic coordinates.
//  * Minimal coordinates z = (hull x, y, θ | cargo x, y, θ | η): the boom frame is eliminated by
//    the clamp at B; M_z(z) z̈ = Q_z(z, ż, t) is solved for z̈ (ODE). Without hull DOFs when the
//    hull is held fixed.
//  * Full coordinates q = (hull | cargo | boom R_B, θ_B, η) with the clamp as 3 constraints
//    C(q, t) = 0 and Lagrange multipliers: M(q) q̈ = Q(q, q̇, t) − C_qᵀ λ (paper eqs. 17, 22, 31–34).
//    With a driven base (prescribed motion) C depends on t: C_q v + C_t = 0 at velocity level.
// The hull block is absent when the base is held or driven, the cargo block when there is no cargo.
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <string>

#include "coupling/second_order_jacobian.hpp"

namespace ffrf::sea {
class IncidentWaveRecord;  // sea/incident_wave_record.hpp
}  // namespace ffrf::sea

namespace ffrf::coupling {

// One output sample: what a time-series row and the static report show.
struct CraneOutputs {
  Eigen::Vector3d hull = Eigen::Vector3d::Zero();        // G1 (or hub) x [m], y [m], pitch [rad]
  Eigen::Vector3d cargo = Eigen::Vector3d::Zero();       // G2 x [m], y [m], pitch [rad]
  Eigen::Vector2d tip_deflection = Eigen::Vector2d::Zero();  // elastic (u, v) at A′ in the boom frame [m]
  double wire_tension = 0.0;                             // [N]
  double wire_length = 0.0;                              // [m]
  Eigen::Vector3d joint_reaction = Eigen::Vector3d::Zero();  // on the boom at B: Fx, Fy [N] (global), M [N m]
  double root_axial_force = 0.0;                         // boom axial force at B, tension > 0 [N]
  double constraint_residual = 0.0;                      // |C(q)| (0 in minimal coordinates) [m]
  double kinetic_energy = 0.0;                           // [J] (added mass included)
  double gravity_energy = 0.0;                           // [J]
  double strain_energy = 0.0;                            // [J]
  double wire_energy = 0.0;                              // [J]
  double spring_energy = 0.0;                            // mooring + support springs [J]
};

// The equations' mass matrix lost positive definiteness at a state (e.g. the hull–boom Schur
// complement of the minimal-coordinate ODE): the failure detectors name it (coupling/run_monitor.hpp).
class MassMatrixError : public std::runtime_error {
 public:
  explicit MassMatrixError(double smallest_pivot)
      : std::runtime_error("loss of positive definiteness of the mass matrix (smallest LDLT pivot " +
                           std::to_string(smallest_pivot) + ")"),
        smallest_pivot_(smallest_pivot) {}
  double smallest_pivot() const { return smallest_pivot_; }

 private:
  double smallest_pivot_;
};


// How this system's hull loads read the incident wave so far: from the record of the sea, or by
// the exact component sums where the record could not answer (outside its patches or its time).
struct HullLoadCounts {
  long recorded = 0;
  long exact = 0;  // with a record: the fallbacks
};

// Constraint-sized vectors and matrices: a run-time constraint count (3 for the clamp at B) in
// storage fixed at max_constraints, so the solvers' hot paths allocate nothing whatever the joint.
inline constexpr int max_constraints = 6;
using ConstraintVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_constraints, 1>;
using ConstraintMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, max_constraints, max_constraints>;

class CraneEquations {
 public:
  using ConstRef = Eigen::Ref<const Eigen::VectorXd>;
  using Ref = Eigen::Ref<Eigen::VectorXd>;
  virtual ~CraneEquations() = default;

  // --- minimal coordinates (ODE) ---
  virtual int minimal_size() const = 0;
  virtual Eigen::VectorXd initial_guess() const = 0;  // rest pose before static equilibrium
  virtual void minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) = 0;
  virtual void static_residual(ConstRef z, Ref residual) = 0;  // Q_z at rest, calm water
  // Q_z(z, ż, t) in the waves, the right-hand side of M_z z̈ = Q_z, without solving for z̈ (the
  // linearisation's wave excitation is this force itself).
  virtual void minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) = 0;
  virtual Eigen::VectorXd static_residual_scale() const = 0;   // 1 / typical force per row
  virtual Eigen::VectorXd coordinate_scale() const = 0;        // typical size of each z
  virtual CraneOutputs minimal_outputs(double t, ConstRef z, ConstRef z_dot) = 0;

  // --- full coordinates with the clamp as constraints (DAE) ---
  virtual int full_size() const = 0;
  virtual int constraint_count() const = 0;  // m ≤ max_constraints
  virtual void full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const = 0;
  virtual void full_mass_times(ConstRef q, ConstRef a, Ref out) = 0;       // M(q) a
  virtual void full_forces(double t, ConstRef q, ConstRef v, Ref out) = 0;  // Q(q, v, t)
  virtual void constraint(double t, ConstRef q, Ref c) const = 0;           // C(q, t)
  virtual void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const = 0;  // C_q (3 × n)
  virtual void constraint_time_derivative(double t, Ref c_t) const = 0;    // C_t (velocity level: C_q v + C_t = 0)
  // γ with C_q q̈ = γ: −(C_q v)_q v − C_tt (C_q does not depend on t).
  virtual void constraint_rate_terms(double t, ConstRef q, ConstRef v, Ref gamma) const = 0;
  // M(q), filled in place (resized only when its size differs: allocation-free in a solver loop).
  virtual void full_mass_matrix(ConstRef q, Eigen::MatrixXd& mass) = 0;
  Eigen::MatrixXd full_mass_matrix(ConstRef q) {
    Eigen::MatrixXd mass;
    full_mass_matrix(q, mass);
    return mass;
  }
  virtual CraneOutputs full_outputs(double t, ConstRef q, ConstRef v, ConstRef lambda) = 0;

  // Wire slack indicator ℓ − L0 [m] (root function for event location); 1 m when there is no wire.
  virtual double wire_stretch_minimal(double t, ConstRef z) = 0;
  virtual double wire_stretch_full(ConstRef q) = 0;
  // Index of the cargo's (x, y, θ) in the minimal coordinates; −1 without a cargo.
  virtual int cargo_offset() const = 0;
  // Elastic coordinate count (0 for the rigid boom).
  virtual int elastic_size() const = 0;
  // Hull-load evaluations in a wave so far, by path (zeros without a wave).
  virtual HullLoadCounts hull_load_counts() const { return {}; }
  // The record of the sea the hull loads read (nullptr: component sums), and why not when absent.
  virtual const sea::IncidentWaveRecord* wave_record() const { return nullptr; }
  virtual std::string exact_kinematics_reason() const { return {}; }

  // --- structured linearizations for the Newton solvers (coupling/second_order_jacobian.hpp) ---
  // Structure of the minimal-coordinate blocks (dense by default).
  virtual BandStructure minimal_structure() const { return {minimal_size(), 0, 0, 0}; }
  // M_z, K = −∂(Q_z − M_z a)/∂z, D = −∂(Q_z − M_z a)/∂ż at (t, z, ż), a = z̈ (out has
  // minimal_structure()). The default differentiates minimal_accelerations (M = I, K = −∂z̈/∂z,
  // D = −∂z̈/∂ż: 2n right-hand sides); the crane overrides it with analytic blocks.
  virtual void minimal_jacobian(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, SecondOrderJacobian& out);
  // Residual or right-hand-side evaluations one minimal_jacobian call costs (for the statistics).
  virtual int minimal_jacobian_evaluations() const { return 2 * minimal_size(); }
  // Structure of the full-coordinate blocks (dense by default). The clamp's C_q must depend only on
  // the border coordinates.
  virtual BandStructure full_structure() const { return {full_size(), 0, 0, 0}; }
  // M(q), K = −∂(Q − M a)/∂q, D = −∂Q/∂v at (t, q, v), a = v̇, without constraint terms (out has
  // full_structure()). Default: forward differences of full_forces and full_mass_times.
  virtual void full_jacobian(double t, ConstRef q, ConstRef v, ConstRef v_dot, SecondOrderJacobian& out);
  virtual int full_jacobian_evaluations() const { return 2 * full_size() + 1; }
  // The outputs at a state whose accelerations z̈ are known (an integrator's interpolant): the joint
  // reaction from them, without solving the equations of motion. Default: minimal_outputs(t, z, ż).
  virtual CraneOutputs minimal_outputs_with_accelerations(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot);
};

}  // namespace ffrf::coupling
