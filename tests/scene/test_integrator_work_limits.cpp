// Work limits for every integrator: a run that needs more work than its limit ends with
// the named failure and the remedy of its kind, within the limit.
//  * adaptive explicit RK on a stiff boom (nodal N = 8, > 1000 stability-bound steps per output
//    interval by its linearized limit): "too much work" before the first step, naming the limit;
//    on a boom too large for the linearized limit (N = 110), after its first thousand steps;
//  * the step limit of every other integrator, and the wall-clock limit of every integrator;
//  * a step-size floor above the steps a wire snap needs (the dropped load): "step-size collapse".
#include <gtest/gtest.h>

#include <cstdio>

#include "solve/integrator_table.hpp"
#include "crane_test_support.hpp"

namespace integrator_work_limits_test {

using namespace ffrf;
using solve::FailureKind;
using solve::Integrator;

struct Crane {
  scene::Scene scene;
  std::unique_ptr<multibody::CraneEquations> equations;
  Eigen::VectorXd z0;
  Crane(scene::Scene s, scene::BoomChoice choice) : scene(std::move(s)), equations(scene::build_crane_equations(scene, choice)) {
    z0 = multibody::solve_static_equilibrium(*equations, equations->initial_guess()).z;
  }
};

multibody::RunSettings settings(Integrator kind, double duration) {
  multibody::RunSettings s;
  s.kind = kind;
  s.relative_tolerance = 1e-6;
  s.absolute_tolerance = 1e-6;
  s.duration = duration;
  s.output_interval = 0.05;
  if (kind.solver == solve::Solver::generalized_alpha) s.fixed_step = 0.01;
  return s;
}

// The failure of a run that must fail.
solve::SolverFailure failure_of(multibody::CraneEquations& equations, const Eigen::VectorXd& z0,
                                   const multibody::RunSettings& s) {
  try {
    multibody::simulate(equations, z0, s);
  } catch (const solve::SolverFailure& failure) {
    std::printf("%s\n", failure.what());
    return failure;
  }
  throw std::runtime_error(std::string(solve::to_string(s.kind)) + ": the run did not fail");
}

TEST(IntegratorWorkLimits, ExplicitRungeKuttaOnAStiffBoomStopsWithTooMuchWork) {
  Crane crane(test::reference_scene(), {scene::BoomKind::nodal, 8, 0, false});
  auto s = settings(Integrator::arkode, 120.0);
  const double stable_step = solve::explicit_stable_step(*crane.equations, crane.z0);
  std::printf("stable ERK step %.3e s: 120 s need at least %.3g steps\n", stable_step, s.duration / stable_step);
  ASSERT_GT(s.output_interval / stable_step, 1000.0) << "the boom is stiff for ERK: > 1000 steps per output interval";
  const solve::SolverFailure failure = failure_of(*crane.equations, crane.z0, s);
  EXPECT_EQ(failure.kind(), FailureKind::too_much_work);
  EXPECT_EQ(failure.time(), 0.0) << "stopped before its first step";
  EXPECT_NE(failure.cause().find("the explicit step limit ~"), std::string::npos) << failure.cause();
  EXPECT_NE(failure.remedy().find("use cvode"), std::string::npos) << failure.remedy();
  EXPECT_DOUBLE_EQ(failure.value(), stable_step);
}

// Without the linearized limit before the start (a model beyond its size), the mean of the first
// steps names the same stiffness: the run stops after a thousand steps, not after the step limit.
TEST(IntegratorWorkLimits, ExplicitRungeKuttaStopsFromItsFirstStepsStatistics) {
  Crane crane(test::reference_scene(), {scene::BoomKind::nodal, 110, 0, false});  // 333 coordinates
  auto s = settings(Integrator::arkode, 120.0);
  const solve::SolverFailure failure = failure_of(*crane.equations, crane.z0, s);
  EXPECT_EQ(failure.kind(), FailureKind::too_much_work);
  EXPECT_NE(failure.cause().find("the mean of the first 1000 steps"), std::string::npos) << failure.cause();
  EXPECT_LT(failure.time(), s.output_interval) << "stopped within the first output interval";
}

TEST(IntegratorWorkLimits, EveryIntegratorStopsAtItsStepLimit) {
  Crane crane(test::reference_scene(), {scene::BoomKind::nodal, 2, 0, false});
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    auto s = settings(entry.choice, 30.0);
    s.work.max_steps = 40;  // far fewer than 30 s of waves need (and than 3000 fixed steps)
    const solve::SolverFailure failure = failure_of(*crane.equations, crane.z0, s);
    EXPECT_EQ(failure.kind(), FailureKind::too_much_work) << entry.name;
    EXPECT_NE(failure.cause().find("step limit of 40"), std::string::npos) << entry.name << ": " << failure.cause();
    EXPECT_FALSE(failure.remedy().empty());
    if (failure.partial()) {
      EXPECT_LE(failure.partial()->stats.steps, 40) << entry.name;
    }
  }
}

TEST(IntegratorWorkLimits, EveryIntegratorStopsAtItsWallClockLimit) {
  Crane crane(test::reference_scene(), {scene::BoomKind::nodal, 2, 0, false});
  for (const solve::IntegratorEntry& entry : solve::integrator_table()) {
    auto s = settings(entry.choice, 30.0);
    s.work.max_wall_seconds = 1e-4;  // a 30 s run takes far longer
    const solve::SolverFailure failure = failure_of(*crane.equations, crane.z0, s);
    EXPECT_EQ(failure.kind(), FailureKind::too_much_work) << entry.name;
    EXPECT_NE(failure.cause().find("wall-clock limit"), std::string::npos) << entry.name << ": " << failure.cause();
    EXPECT_LT(failure.time(), 30.0) << entry.name;
  }
}

TEST(IntegratorWorkLimits, AStepSizeFloorAboveWhatAWireSnapNeedsIsAStepSizeCollapse) {
  // The dropped load: releasing the cargo sets the elastic boom vibrating (its highest modes at N = 4
  // far above 1/0.05 s⁻¹) and the cargo falls onto the slack wire (a kink in the force): at rtol 1e-6
  // BDF needs steps well below 0.05 s from the start, so a floor of 0.05 s cannot pass the error test.
  Crane crane(scene::load_scene(FFRF_SOURCE_DIR "/cases/dropped_load.toml"), {scene::BoomKind::nodal, 4, 0, false});
  Eigen::VectorXd z0 = crane.z0;
  z0(crane.equations->cargo_offset() + 1) += 0.5;  // simulation.cargo_lift
  for (const Integrator kind : {Integrator::cvode, Integrator::ida, Integrator::baumgarte, Integrator::arkode}) {
    auto s = settings(kind, 2.0);
    s.output_interval = 0.002;
    s.work.min_step = 0.05;
    const solve::SolverFailure failure = failure_of(*crane.equations, z0, s);
    EXPECT_EQ(failure.kind(), FailureKind::step_size_collapse) << solve::to_string(kind);
    EXPECT_NE(failure.cause().find("step-size floor"), std::string::npos) << failure.cause();
    EXPECT_LT(failure.time(), 2.0);
  }
  auto s = settings(Integrator::cvode, 2.0);  // the same run without the floor finishes
  s.output_interval = 0.002;
  EXPECT_NO_THROW(multibody::simulate(*crane.equations, z0, s));
}

}  // namespace integrator_work_limits_test
