// The failure detectors (multibody/run_monitor.hpp, solve/failure.hpp) against independent facts:
//  * buckling margin: the root compression of a boom on a fixed hub carrying a hanging cargo is beam
//    statics, (ρA g L + m g) sin φ (both loads vertical; their axial components at the root); the
//    ratio to the clamped–free Euler load π²EI/(4L²) is reported from 0.5 on, and not below;
//  * loss of positive definiteness: a hull with a negative added pitch inertia larger than the whole
//    crane's pitch inertia about G1 has an indefinite mass matrix: the run must stop at t = 0 with
//    the kind named, and no non-finite sample;
//  * constraint drift: the unstabilized index-1 formulation drifts off C = 0 (it only enforces
//    C̈ = 0), Baumgarte's feedback C̈ + 2ω_b Ċ + ω_b² C = 0 keeps |C| near round-off;
//  * divergence watch: a boom spun at constant Ωs above its first bending frequency without
//    centrifugal stiffening grows without bound; the partial result stops at the failure, finite;
//  * every failure kind has a distinct, non-empty name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>

#include "crane_test_support.hpp"

namespace failure_detectors_test {

using namespace ffrf;

multibody::MonitorLimits limits_of(const scene::Scene& scene) {
  multibody::MonitorLimits limits;
  const fem::BeamMesh& mesh = scene.boom.mesh;
  limits.boom_length = mesh.length;
  limits.buckling_load = std::numbers::pi * std::numbers::pi * mesh.section.bending_rigidity() / (4.0 * mesh.length * mesh.length);
  limits.wire_unstretched_length = scene.wire ? scene.wire->unstretched_length : 0.0;
  return limits;
}

const solve::Detection* find(const std::vector<solve::Detection>& detections, solve::FailureKind kind) {
  for (const solve::Detection& d : detections) {
    if (d.kind == kind) return &d;
  }
  return nullptr;
}

TEST(FailureDetectors, BucklingMarginFromBeamStatics) {
  for (const double cargo_mass : {5000.0, 2000.0}) {
    const scene::Scene scene = test::hub_crane_scene({2.1e11, 1.0e-3, 1.0e-5, 10.0, 4, cargo_mass, 1.0e7});
    const double g = scene.environment.gravity, phi = std::numbers::pi / 4.0, L = scene.boom.mesh.length;
    const double compression = (scene.boom.mesh.section.mass_per_length * g * L + cargo_mass * g) * std::sin(phi);
    const multibody::MonitorLimits limits = limits_of(scene);
    const double ratio = compression / limits.buckling_load;

    auto equations = scene::build_crane_equations(scene, {scene::BoomKind::rigid, 1, 0, false});
    const auto statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
    EXPECT_NEAR(statics.outputs.root_axial_force / -compression, 1.0, 1e-6) << "cargo " << cargo_mass << " kg";

    multibody::RunSettings settings;
    settings.duration = 1.0;
    settings.output_interval = 0.01;
    settings.monitor = limits;
    const multibody::RunResult run = multibody::simulate(*equations, statics.z, settings);
    const solve::Detection* buckling = find(run.detections, solve::FailureKind::buckling);
    if (ratio > 0.5) {
      ASSERT_NE(buckling, nullptr) << "ratio " << ratio;
      EXPECT_NEAR(buckling->value / ratio, 1.0, 1e-6);
      EXPECT_FALSE(buckling->fatal);
    } else {
      EXPECT_EQ(buckling, nullptr) << "ratio " << ratio;
    }
    std::printf("cargo %.0f kg: root compression %.6g N (statics %.6g N), P_cr %.6g N, ratio %.4f\n", cargo_mass,
                compression, -statics.outputs.root_axial_force, limits.buckling_load, ratio);
  }
}

TEST(FailureDetectors, IndefiniteMassMatrixStopsTheRunAtTheStart) {
  const scene::Scene scene = test::reference_scene();
  auto model = scene::build_crane_parameters(scene, scene::modal_coordinates(scene, {scene::BoomKind::rigid, 1, 0, false}));
  // The crane's pitch inertia about G1 is at most the hull's plus the boom's and cargo's masses at
  // the boom tip's distance: a negative added inertia ten times that makes the hull–boom block indefinite.
  const double reach = scene.boom.mesh.length + std::hypot(scene.boom.mount->root_x, scene.boom.mount->root_y) + 50.0;
  const double crane_inertia =
      scene.hull->pitch_inertia() + (scene.boom.mesh.total_mass() + scene.cargo->mass) * reach * reach;
  model.hull.added_mass(2) = -10.0 * crane_inertia;
  auto equations = multibody::make_crane_equations(std::move(model));
  multibody::RunSettings settings;
  settings.duration = 1.0;
  settings.output_interval = 0.05;
  try {
    multibody::simulate(*equations, equations->initial_guess(), settings);
    FAIL() << "an indefinite mass matrix must stop the run";
  } catch (const solve::SolverFailure& failure) {
    EXPECT_EQ(failure.kind(), solve::FailureKind::mass_not_positive_definite) << failure.what();
    EXPECT_LE(failure.time(), settings.output_interval) << failure.what();
    if (multibody::partial_run(failure)) {
      for (const multibody::CraneOutputs& sample : multibody::partial_run(failure)->samples) {
        EXPECT_TRUE(sample.hull.allFinite() && sample.cargo.allFinite() && std::isfinite(sample.wire_tension));
      }
    }
    std::printf("%s\n", failure.what());
  }
}

TEST(FailureDetectors, UnstabilizedIndexOneDriftsAndBaumgarteDoesNot) {
  const scene::Scene scene = test::reference_scene();
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 2, 0, false});
  const auto statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  multibody::RunSettings settings;
  settings.duration = 60.0;
  settings.output_interval = 0.1;
  settings.monitor = limits_of(scene);
  // Measured over 60 s: index1 1.5e-7 m, baumgarte 1.4e-9 m; the bound sits between them with a
  // factor of 10 either side (1e-7 would leave index1 only 1.5 x above it).
  settings.monitor.constraint_drift_limit = 1.5e-8;
  double drift[2] = {0.0, 0.0};
  const solve::Integrator kinds[2] = {solve::Integrator::index1, solve::Integrator::baumgarte};
  for (int i = 0; i < 2; ++i) {
    settings.kind = kinds[i];
    const multibody::RunResult run = multibody::simulate(*equations, statics.z, settings);
    drift[i] = multibody::max_constraint_drift(run);
    const solve::Detection* found = find(run.detections, solve::FailureKind::constraint_drift);
    if (i == 0) {
      ASSERT_NE(found, nullptr) << "index1 drift " << drift[i];
      // The detection reports the largest residual and the first output time beyond the bound.
      double largest = 0.0, first = -1.0;
      for (std::size_t k = 0; k < run.samples.size(); ++k) {
        largest = std::max(largest, run.samples[k].constraint_residual);
        if (first < 0.0 && run.samples[k].constraint_residual > settings.monitor.constraint_drift_limit) first = run.time[k];
      }
      EXPECT_EQ(found->value, largest);
      EXPECT_GT(found->value, settings.monitor.constraint_drift_limit);
      EXPECT_EQ(found->time, first);
      EXPECT_GT(found->time, 0.0);
    } else {
      EXPECT_EQ(found, nullptr) << "baumgarte drift " << drift[i];
    }
  }
  std::printf("max |C| over 60 s: index1 %.3g m, baumgarte %.3g m\n", drift[0], drift[1]);
}

// A 10 m Simo–Vu-Quoc beam spun at a constant Ωs = 6 rad/s, above ω1 = 3.80 rad/s, no stiffening.
scene::Scene spinning_beam() {
  scene::Scene scene = test::constant_spin_beam(6.0, scene::Stiffening::none, 10);
  scene.simulation.duration = 10.0;
  scene.simulation.output_interval = 0.01;
  scene.simulation.deflection_limit = 0.2;
  return scene;
}

TEST(FailureDetectors, DivergenceWatchStopsWithAFinitePartialResult) {
  const scene::Scene scene = spinning_beam();
  auto equations = scene::build_crane_equations(scene, {scene::BoomKind::nodal, 10, 0, false});
  multibody::RunSettings settings;
  settings.duration = 10.0;
  settings.output_interval = 0.01;
  settings.monitor = limits_of(scene);
  try {
    multibody::simulate(*equations, equations->initial_guess(), settings);
    FAIL() << "the unstiffened beam above its first bending frequency must diverge";
  } catch (const solve::SolverFailure& failure) {
    ASSERT_EQ(failure.kind(), solve::FailureKind::divergence) << failure.what();
    ASSERT_TRUE(multibody::partial_run(failure));
    const multibody::RunResult& partial = *multibody::partial_run(failure);
    ASSERT_FALSE(partial.samples.empty());
    for (const multibody::CraneOutputs& sample : partial.samples) {
      ASSERT_TRUE(sample.tip_deflection.allFinite() && sample.hull.allFinite());
    }
    EXPECT_NEAR(partial.time.back(), failure.time(), 1e-12);
    const double bound = settings.monitor.deflection_limit * scene.boom.mesh.length;
    EXPECT_GT(partial.samples.back().tip_deflection.norm(), bound);
    for (std::size_t k = 0; k + 1 < partial.samples.size(); ++k) {
      EXPECT_LE(partial.samples[k].tip_deflection.norm(), bound) << "the watch must stop at the first sample past the bound";
    }
    std::printf("diverged at t = %.3f s, last deflection %.3g m (bound %.3g m)\n", failure.time(),
                partial.samples.back().tip_deflection.norm(), bound);
  }
}

TEST(FailureDetectors, EveryFailureKindHasADistinctName) {
  std::set<std::string> names;
  const int count = static_cast<int>(solve::FailureKind::setup) + 1;
  for (int k = 0; k < count; ++k) {
    const std::string name(solve::to_string(static_cast<solve::FailureKind>(k)));
    EXPECT_FALSE(name.empty());
    EXPECT_NE(name, "?");
    names.insert(name);
  }
  EXPECT_EQ(names.size(), static_cast<std::size_t>(count));
}

}  // namespace failure_detectors_test
