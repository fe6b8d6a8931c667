// Static equilibrium of the crane (the paper's future work, §6): the minimal coordinates z at
// which all generalized forces vanish at rest in calm water — hull draft and trim, boom
// deflection, wire stretch, cargo position — solved by KINSOL (Newton with line search, dense
// difference-quotient Jacobian) from the rest-pose guess.
#pragma once

#include <Eigen/Dense>

#include "coupling/crane_equations.hpp"

namespace ffrf::coupling {

struct StaticEquilibrium {
  Eigen::VectorXd z;              // minimal coordinates
  CraneOutputs outputs;           // at equilibrium (tensions, deflection, reaction)
  long newton_iterations = 0;
  long function_evaluations = 0;
  double scaled_residual = 0.0;   // max |scaled force| at the solution
  double wall_seconds = 0.0;
};

// Throws SolverFailure (coupling/simulation.hpp) when Newton does not converge.
StaticEquilibrium solve_static_equilibrium(CraneEquations& equations, const Eigen::VectorXd& guess,
                                           double tolerance = 1e-11);

}  // namespace ffrf::coupling
