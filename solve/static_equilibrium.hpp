// Static equilibrium of a second-order system: the minimal coordinates z at which all generalized
// forces vanish at rest (SecondOrderSystem::static_residual; for the crane: hull draft and trim,
// boom deflection, wire stretch, cargo position in calm water), solved by KINSOL (Newton with line
// search, dense difference-quotient Jacobian) from the rest-pose guess.
//
// Scaling. Each residual row is measured as the displacement that would remove it: the row's
// force divided by its own stiffness times its coordinate's typical size, |∂Q_i/∂z_i| s_i (the
// Jacobian's diagonal at the guess, by differences), never less than 10⁻³ of the row's weight
// scale (a row without stiffness of its own). A merit function in forces would weigh the cargo's
// rows by the cargo's weight: a light cargo on a stiff wire (20 t on 2.5e8 N/m) turns the few
// centimetres by which a full Newton step misses the boom tip (the hull's trim rotates it) into
// tens of cargo weights, the line search refuses the step that a stiffness-weighted merit accepts,
// and Newton crawls. The tolerance is then on that displacement (in coordinate scales).
//
// Continuation. When Newton from the guess fails, the out-of-balance load at the guess is applied
// in steps (Newton homotopy): Q_z(z) − (1 − λ) Q_z(z0) = 0 from λ = 0 (solved by z0) to λ = 1, each
// step from the last solution, the step halved when Newton fails and grown when it succeeds.
#pragma once

#include <Eigen/Dense>

#include "solve/second_order_system.hpp"

namespace ffrf::solve {

struct StaticSolution {
  Eigen::VectorXd z;              // minimal coordinates
  long newton_iterations = 0;     // over every solve (continuation steps included)
  long function_evaluations = 0;
  double scaled_residual = 0.0;   // max |residual| / (stiffness × typical size) at the solution
  double wall_seconds = 0.0;
};

// How the equilibrium was reached and what it left out of balance (`ffrf statics` reports it).
struct StaticSolvePath {
  int continuation_steps = 0;        // 0: Newton from the guess converged directly
  double max_force_residual = 0.0;   // largest out-of-balance force of the rigid bodies [N]
  double max_moment_residual = 0.0;  // largest out-of-balance moment of the rigid bodies [N m]
  bool by_continuation() const { return continuation_steps > 0; }
};

// Throws SolverFailure (solve/failure.hpp) when neither Newton nor the continuation converges; the
// failure names the row that stays out of balance (SecondOrderSystem::residual_row).
StaticSolution solve_static_equilibrium(SecondOrderSystem& system, const Eigen::VectorXd& guess, double tolerance = 1e-11);
// The same, with how it was reached in `path`.
StaticSolution solve_static_equilibrium(SecondOrderSystem& system, const Eigen::VectorXd& guess, StaticSolvePath& path,
                                        double tolerance = 1e-11);

}  // namespace ffrf::solve
