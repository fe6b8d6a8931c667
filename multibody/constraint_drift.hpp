// The constraint drift of the ways to treat the clamp at B: minimal coordinates (cvode: no
// constraint, |C| = 0 exactly), Lagrange multipliers in the stabilized index-2 form (ida) and the
// index-1 ODE unstabilized, with Baumgarte's feedback, and with projection (index1, baumgarte,
// projection). Each runs on a fresh set of equations from one factory, from the same z0 at rest;
// the result is |C(q(t))| per output sample (CraneOutputs::constraint_residual) and the cost.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "multibody/crane_run.hpp"

namespace ffrf::multibody {

using EquationsFactory = std::function<std::unique_ptr<CraneEquations>()>;

struct FormulationDrift {
  Integrator formulation;
  RunResult run;                  // the full run (time, outputs, statistics, wire events)
  std::vector<double> residual;   // |C| at run.time [m]
  double max_residual = 0.0;      // [m]
  double final_residual = 0.0;    // [m]
};

// The formulations compared by default: cvode, ida, index1, baumgarte, projection.
std::vector<Integrator> constraint_formulations();

// Runs each formulation with `settings` (its kind replaced) on a fresh make_equations() from z0.
// Exceptions (SolverFailure) propagate: a formulation that fails is a failure of the comparison.
std::vector<FormulationDrift> compare_constraint_drift(const EquationsFactory& make_equations, const Eigen::VectorXd& z0,
                                                       const RunSettings& settings,
                                                       const std::vector<Integrator>& formulations = constraint_formulations());

}  // namespace ffrf::multibody
