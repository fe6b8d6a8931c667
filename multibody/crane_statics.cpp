// The crane's static equilibrium (multibody/crane_statics.hpp).
#include "multibody/crane_statics.hpp"

#include <fmt/format.h>

#include <chrono>
#include <string>

#include "solve/failure.hpp"

namespace ffrf::multibody {

StaticEquilibrium solve_static_equilibrium(CraneEquations& equations, const Eigen::VectorXd& guess, double tolerance) {
  StaticSolvePath path;
  return solve_static_equilibrium(equations, guess, path, tolerance);
}

StaticEquilibrium solve_static_equilibrium(CraneEquations& equations, const Eigen::VectorXd& guess, StaticSolvePath& path,
                                           double tolerance) {
  const auto start = std::chrono::steady_clock::now();
  StaticEquilibrium result;
  static_cast<solve::StaticSolution&>(result) = solve::solve_static_equilibrium(equations, guess, path, tolerance);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(result.z.size());
  if (result.z.size() > 0 && equations.wire_stretch_minimal(0.0, result.z) <= 0.0) {
    throw solve::SolverFailure(solve::FailureKind::wire_slack, "KINSOL (static equilibrium)",
                               fmt::format("the wire is slack at rest (stretch {:.3g} m)", equations.wire_stretch_minimal(0.0, result.z)),
                               0.0, "hang the cargo below the boom tip: check the wire's unstretched length and the hook position");
  }
  result.outputs = equations.minimal_outputs(0.0, result.z, rest);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::multibody
