// What the solvers (KINSOL, CVODE, IDA, ARKODE, generalized-α) see of a mechanical system: second-
// order equations of motion in two coordinate sets, constraint functions, event functions, and
// nothing of what the coordinates describe.
//  * Minimal coordinates z (the constraints eliminated): M_z(z) z̈ = Q_z(z, ż, t), solved for z̈ (ODE).
//  * Full coordinates q with m = constraint_count() holonomic constraints C(q, t) = 0 and Lagrange
//    multipliers λ: M(q) q̈ = Q(q, q̇, t) − C_qᵀ λ (a DAE; C depends on t when a base is driven, so
//    C_q v + C_t = 0 at velocity level).
// Event functions g(t, ·) (a wire going slack, a contact opening) are located by the root finders
// and recorded with their direction; what is sampled at an output time is handed to an OutputSink
// (solve/output_sink.hpp), so the solvers never name an output.
#pragma once

#include <Eigen/Dense>
#include <stdexcept>
#include <string>
#include <vector>

#include "solve/second_order_jacobian.hpp"

namespace ffrf::solve {

// The equations' mass matrix lost positive definiteness at a state (e.g. a Schur complement of the
// minimal-coordinate ODE): the failure detectors name it.
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

// Constraint-sized vectors and matrices: a run-time constraint count in storage fixed at
// max_constraints, so the solvers' hot paths allocate nothing whatever the joints.
inline constexpr int max_constraints = 6;
using ConstraintVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_constraints, 1>;
using ConstraintMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, max_constraints, max_constraints>;
// Event-sized vectors: at most max_events event functions.
inline constexpr int max_events = 8;
using EventVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_events, 1>;

// What a static-equilibrium failure says of one residual row: the force it is, whether it is a
// moment (N m) or a force (N), whether it belongs to the rigid bodies (whose balance names the
// cause first), and what to check.
struct ResidualRow {
  std::string what;
  std::string check;
  bool moment = false;
  bool rigid = false;
};

class SecondOrderSystem;

// Typical size of each full coordinate: its minimal counterpart's (coordinate_scale through
// full_from_minimal), at least 1e-2 — the full-coordinate integrators' tolerances and Newton norms.
Eigen::VectorXd full_coordinate_scale(SecondOrderSystem& system);

class SecondOrderSystem {
 public:
  using ConstRef = Eigen::Ref<const Eigen::VectorXd>;
  using Ref = Eigen::Ref<Eigen::VectorXd>;
  virtual ~SecondOrderSystem() = default;

  // --- minimal coordinates (ODE) ---
  virtual int minimal_size() const = 0;
  virtual Eigen::VectorXd initial_guess() const = 0;  // rest pose before static equilibrium
  virtual void minimal_accelerations(double t, ConstRef z, ConstRef z_dot, Ref z_ddot) = 0;
  virtual void static_residual(ConstRef z, Ref residual) = 0;  // Q_z at rest, without excitation
  // Q_z(z, ż, t), the right-hand side of M_z z̈ = Q_z, without solving for z̈.
  virtual void minimal_generalized_forces(double t, ConstRef z, ConstRef z_dot, Ref forces) = 0;
  virtual Eigen::VectorXd static_residual_scale() const = 0;   // 1 / typical force per row
  virtual Eigen::VectorXd coordinate_scale() const = 0;        // typical size of each z
  virtual double minimal_kinetic_energy(double t, ConstRef z, ConstRef z_dot) = 0;  // [J]
  // What residual row `row` of static_residual is (for the static solver's failure messages).
  virtual ResidualRow residual_row(int row) const { return {"generalized force " + std::to_string(row), {}, false, false}; }
  // What to check when the model refuses a state during the static solve.
  virtual std::string static_model_check() const { return "check the model's values"; }
  // The first row of each rigid body's (x, y, θ) block in the minimal coordinates: the static solver's
  // residual scaling shares a body's stiffest translation among its rows.
  virtual std::vector<int> rigid_body_blocks() const { return {}; }

  // --- full coordinates with constraints (DAE) ---
  virtual int full_size() const = 0;
  virtual int constraint_count() const = 0;  // m ≤ max_constraints
  virtual void full_from_minimal(double t, ConstRef z, ConstRef z_dot, Ref q, Ref v) const = 0;
  virtual void full_mass_times(ConstRef q, ConstRef a, Ref out) = 0;       // M(q) a
  virtual void full_forces(double t, ConstRef q, ConstRef v, Ref out) = 0;  // Q(q, v, t)
  virtual void constraint(double t, ConstRef q, Ref c) const = 0;           // C(q, t)
  virtual void constraint_jacobian(ConstRef q, Eigen::MatrixXd& jacobian) const = 0;  // C_q (m × n)
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

  // --- event functions (root finding) ---
  // Functions whose sign changes the solvers locate and record (solve/integration.hpp, Event).
  virtual int event_count() const { return 0; }
  virtual void minimal_events(double /*t*/, ConstRef /*z*/, Ref /*g*/) {}
  virtual void full_events(double /*t*/, ConstRef /*q*/, Ref /*g*/) {}

  // --- structured linearizations for the Newton solvers (solve/second_order_jacobian.hpp) ---
  // Structure of the minimal-coordinate blocks (dense by default).
  virtual BandStructure minimal_structure() const { return {minimal_size(), 0, 0, 0}; }
  // M_z, K = −∂(Q_z − M_z a)/∂z, D = −∂(Q_z − M_z a)/∂ż at (t, z, ż), a = z̈ (out has
  // minimal_structure()). The default differentiates minimal_accelerations (M = I, K = −∂z̈/∂z,
  // D = −∂z̈/∂ż: 2n right-hand sides); a system may override it with analytic blocks.
  virtual void minimal_jacobian(double t, ConstRef z, ConstRef z_dot, ConstRef z_ddot, SecondOrderJacobian& out);
  // Residual or right-hand-side evaluations one minimal_jacobian call costs (for the statistics).
  virtual int minimal_jacobian_evaluations() const { return 2 * minimal_size(); }
  // Structure of the full-coordinate blocks (dense by default). C_q must depend only on the border
  // coordinates.
  virtual BandStructure full_structure() const { return {full_size(), 0, 0, 0}; }
  // M(q), K = −∂(Q − M a)/∂q, D = −∂Q/∂v at (t, q, v), a = v̇, without constraint terms (out has
  // full_structure()). Default: forward differences of full_forces and full_mass_times.
  virtual void full_jacobian(double t, ConstRef q, ConstRef v, ConstRef v_dot, SecondOrderJacobian& out);
  virtual int full_jacobian_evaluations() const { return 2 * full_size() + 1; }
};

}  // namespace ffrf::solve
