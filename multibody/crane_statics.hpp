// The crane's static equilibrium (the paper's future work, §6): the generic static solve
// (solve/static_equilibrium.hpp: KINSOL with stiffness-scaled rows and a load continuation) of the
// crane's equations at rest in calm water — hull draft and trim, boom deflection, wire stretch,
// cargo position — then the wire checked taut and the crane's outputs at the equilibrium.
#pragma once

#include <Eigen/Dense>

#include "multibody/crane_equations.hpp"
#include "solve/static_equilibrium.hpp"

namespace ffrf::multibody {

using solve::StaticSolvePath;

struct StaticEquilibrium : solve::StaticSolution {
  CraneOutputs outputs;  // at equilibrium (tensions, deflection, reaction)
};

// Throws SolverFailure when neither Newton nor the continuation converges (naming the row that
// stays out of balance: hull heave, trim, cargo, boom) or when the wire is slack at rest.
StaticEquilibrium solve_static_equilibrium(CraneEquations& equations, const Eigen::VectorXd& guess,
                                           double tolerance = 1e-11);
// The same, with how it was reached in `path`.
StaticEquilibrium solve_static_equilibrium(CraneEquations& equations, const Eigen::VectorXd& guess, StaticSolvePath& path,
                                           double tolerance = 1e-11);

}  // namespace ffrf::multibody
