// exploratory
#include <gtest/gtest.h>

#include <cstdio>

#include "coupling/constraint_drift.hpp"
#include "crane_test_support.hpp"

namespace {

using namespace ffrf;

TEST(ConstraintFormulations, Explore) {
  const cases::Scene scene = test::reference_scene();
  const cases::BoomChoice choice{cases::BoomKind::rigid, 1, 0, false};
  auto probe = cases::build_crane(scene, choice);
  const Eigen::VectorXd z0 = coupling::solve_static_equilibrium(*probe, probe->initial_guess()).z;
  coupling::IntegratorSettings settings;
  settings.duration = 60.0;
  settings.output_interval = 0.1;
  const auto drifts = coupling::compare_constraint_drift([&] { return cases::build_crane(scene, choice); }, z0, settings);
  for (const auto& d : drifts) {
    double early = 0.0, late = 0.0, heave = 0.0, tension = 0.0;
    for (std::size_t i = 0; i < d.residual.size(); ++i) {
      (d.run.time[i] <= 30.0 ? early : late) = std::max(d.run.time[i] <= 30.0 ? early : late, d.residual[i]);
      heave = std::max(heave, std::abs(d.run.samples[i].cargo.y() - drifts[0].run.samples[i].cargo.y()));
      tension = std::max(tension, std::abs(d.run.samples[i].wire_tension - drifts[0].run.samples[i].wire_tension));
    }
    std::printf("%-11s max %.3e final %.3e early %.3e late %.3e | dheave %.3e dT %.3e | steps %ld fe %ld je %ld nni %ld etf %ld proj %ld wall %.3f\n",
                std::string(coupling::to_string(d.formulation)).c_str(), d.max_residual, d.final_residual, early, late, heave, tension,
                d.run.stats.steps, d.run.stats.function_evaluations, d.run.stats.jacobian_evaluations, d.run.stats.newton_iterations,
                d.run.stats.error_test_failures, d.run.stats.projections, d.run.stats.wall_seconds);
  }
}

}  // namespace
