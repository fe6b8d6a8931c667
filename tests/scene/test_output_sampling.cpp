// Outputs without a right-hand side per sample: the joint reaction and every other output
// from the state and given accelerations (minimal_outputs_with_accelerations) equal the outputs that
// solve the equations of motion at the state (minimal_outputs), and a CVODE run whose outputs use the
// interpolant's derivative for the accelerations converges to the tight-tolerance run: at rtol 1e-6
// the joint reaction is within 2e-4 of its range of the rtol 1e-10 run (the error of the state itself,
// cargo heave, is of the same order), i.e. the interpolant adds nothing beyond the integration error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"

namespace output_sampling_test {

using namespace ffrf;

void expect_same_outputs(const multibody::CraneOutputs& a, const multibody::CraneOutputs& b, const std::string& label) {
  const auto near = [&](double x, double y, double scale, const char* what) {
    EXPECT_NEAR(x, y, 1e-10 * std::max(scale, 1.0)) << label << ": " << what;
  };
  const double force = std::max(b.joint_reaction.head<2>().norm(), b.wire_tension);
  for (int i = 0; i < 3; ++i) {
    near(a.hull(i), b.hull(i), 1.0, "hull");
    near(a.cargo(i), b.cargo(i), 1.0, "cargo");
    near(a.joint_reaction(i), b.joint_reaction(i), i < 2 ? force : std::abs(b.joint_reaction(2)), "joint reaction");
  }
  near(a.tip_deflection.norm(), b.tip_deflection.norm(), 1.0, "tip deflection");
  near(a.wire_tension, b.wire_tension, b.wire_tension, "wire tension");
  near(a.root_axial_force, b.root_axial_force, force, "root axial force");
  near(a.kinetic_energy, b.kinetic_energy, b.kinetic_energy, "kinetic energy");
  near(a.strain_energy, b.strain_energy, b.strain_energy, "strain energy");
  near(a.gravity_energy, b.gravity_energy, std::abs(b.gravity_energy), "gravity energy");
}

TEST(OutputSampling, OutputsFromGivenAccelerationsEqualThoseThatSolveForThem) {
  const auto crane = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  const auto hub = scene::load_scene(FFRF_SOURCE_DIR "/cases/spin_up_beam.toml");
  const std::pair<const scene::Scene*, scene::BoomChoice> models[] = {
      {&crane, {.kind = scene::BoomKind::rigid}},
      {&crane, {.kind = scene::BoomKind::nodal, .elements = 8}},
      {&crane, {.kind = scene::BoomKind::modal, .elements = 16, .modes = 2, .static_modes = true}},
      {&hub, {.kind = scene::BoomKind::nodal, .elements = 6}}};
  for (const auto& [scene, choice] : models) {
    auto eq = scene::build_crane_equations(*scene, choice);
    const int n = eq->minimal_size();
    Eigen::VectorXd z = multibody::solve_static_equilibrium(*eq, eq->initial_guess()).z, z_dot(n), z_ddot(n);
    const Eigen::VectorXd scale = eq->coordinate_scale();
    for (int i = 0; i < n; ++i) {
      z(i) += 0.02 * scale(i) * std::sin(1.3 * i);
      z_dot(i) = 0.4 * scale(i) * std::cos(0.7 * i);
    }
    for (const double t : {3.0, 27.5}) {
      eq->minimal_accelerations(t, z, z_dot, z_ddot);
      expect_same_outputs(eq->minimal_outputs_with_accelerations(t, z, z_dot, z_ddot), eq->minimal_outputs(t, z, z_dot),
                          choice.label());
    }
  }
}

TEST(OutputSampling, InterpolatedAccelerationsKeepTheJointReactionAtTheIntegrationError) {
  const auto scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml");
  auto eq = scene::build_crane_equations(scene, {.kind = scene::BoomKind::nodal, .elements = 4});
  const Eigen::VectorXd z0 = multibody::solve_static_equilibrium(*eq, eq->initial_guess()).z;
  multibody::RunSettings settings;
  settings.duration = 40.0;
  settings.output_interval = 0.05;
  settings.relative_tolerance = settings.absolute_tolerance = 1e-10;
  const auto reference = multibody::simulate(*eq, z0, settings);
  settings.relative_tolerance = settings.absolute_tolerance = 1e-6;
  const auto run = multibody::simulate(*eq, z0, settings);
  ASSERT_EQ(run.samples.size(), reference.samples.size());
  double reaction_error = 0.0, reaction_range = 0.0, heave_error = 0.0, heave_range = 0.0;
  for (std::size_t k = 0; k < run.samples.size(); ++k) {
    const auto& a = run.samples[k];
    const auto& r = reference.samples[k];
    reaction_error = std::max(reaction_error, (a.joint_reaction.head<2>() - r.joint_reaction.head<2>()).norm());
    reaction_range = std::max(reaction_range, (r.joint_reaction.head<2>() - reference.samples[0].joint_reaction.head<2>()).norm());
    heave_error = std::max(heave_error, std::abs(a.cargo.y() - r.cargo.y()));
    heave_range = std::max(heave_range, std::abs(r.cargo.y() - reference.samples[0].cargo.y()));
  }
  std::printf("joint reaction error %.2e of its range, cargo heave %.2e of its range\n", reaction_error / reaction_range,
              heave_error / heave_range);
  EXPECT_LT(reaction_error, 2e-4 * reaction_range);
  EXPECT_LT(heave_error, 2e-4 * heave_range);
}

}  // namespace output_sampling_test
