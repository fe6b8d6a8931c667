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
  // The statics solve the ropes as bilateral springs: each must come out taut.
  Eigen::VectorXd stretch(equations.wire_count());
  if (result.z.size() > 0) equations.wire_stretches_minimal(0.0, result.z, stretch);
  for (int wire = 0; wire < stretch.size(); ++wire) {
    if (stretch(wire) > 0.0) continue;
    const WireRole role = equations.wire_role(wire);
    const bool hoist = role == WireRole::hoist;
    const std::string remedy =
        hoist ? "hang the cargo below the boom tip: check the wire's unstretched length and the hook position"
        : role == WireRole::backstay
            ? "shorten the " + equations.wire_name(wire) + " (backstay.unstretched_length, or leave it out to derive it) so that it "
                                                           "holds the A-frame against the luffing wires"
            : "shorten the " + equations.wire_name(wire) + " (luffing.unstretched_length, or leave it out to derive it) so that it "
                                                           "holds the boom";
    throw solve::SolverFailure(solve::FailureKind::wire_slack, "KINSOL (static equilibrium)",
                               fmt::format("the {} is slack at rest (stretch {:.3g} m)", hoist ? "wire" : equations.wire_name(wire), stretch(wire)),
                               0.0, remedy);
  }
  result.outputs = equations.minimal_outputs(0.0, result.z, rest);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ffrf::multibody
