// The boom's structural damping is the same physical damping in nodal and modal coordinates: the free
// decay of the boom's first bending mode gives the scene's damping ratio. The boom of the reference
// crane on a held hull (turned so that the boom lies level), without cargo or water, at its static
// equilibrium under its weight, released from rest displaced in its first mode (from the crane's own
// linearisation about that equilibrium); the logarithmic decrement of the tip's transverse deflection
// about its static value over ten periods gives ζ = δ/√(4π² + δ²) (Clough & Penzien, §2-8), against
// boom.damping_ratio within 2 %. A pinned boom's luffing wire stays taut: its tension at rest, half the
// boom's weight, exceeds the mode's tip shear.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <vector>

#include "held_boom.hpp"
#include "linalg/dense_solvers.hpp"
#include "multibody/crane_model.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"
#include "multibody/linearisation.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf {
namespace {

// The boom of `scene` on its held hull (boom level), alone: no water, cargo or wires but the luffing
// wires of a pinned heel.
template <class Parameters>
std::unique_ptr<multibody::CraneEquations> isolated_boom(Parameters model) {
  const Eigen::Vector3d pose = test::level_boom_pose(model);
  return test::held_boom(std::move(model), pose);
}

std::unique_ptr<multibody::CraneEquations> isolated_boom(const scene::Scene& scene, const scene::BoomChoice& choice) {
  if (choice.kind == scene::BoomKind::nodal) {
    return isolated_boom(scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, choice.elements))));
  }
  return isolated_boom(scene::build_crane_parameters(scene, scene::modal_coordinates(scene, choice)));
}

// ζ of the free decay from `start` (a mode shape): the mean logarithmic decrement between the tip's
// transverse deflection peaks (each located by a parabola through three samples).
double free_decay_ratio(multibody::CraneEquations& equations, const Eigen::VectorXd& start, double period,
                        double static_deflection) {
  multibody::RunSettings settings;
  settings.kind = solve::Integrator::cvode;
  settings.relative_tolerance = settings.absolute_tolerance = 1e-10;
  settings.duration = 10.5 * period;
  settings.output_interval = period / 64.0;
  const multibody::RunResult run = multibody::simulate(equations, start, settings);
  std::vector<double> peaks;
  for (std::size_t k = 1; k + 1 < run.samples.size(); ++k) {
    const double a = run.samples[k - 1].tip_deflection.y() - static_deflection,
                 b = run.samples[k].tip_deflection.y() - static_deflection,
                 c = run.samples[k + 1].tip_deflection.y() - static_deflection;
    if (b > a && b >= c && b > 0.0) peaks.push_back(b - 0.125 * (c - a) * (c - a) / (a - 2.0 * b + c));  // vertex height
  }
  EXPECT_GE(peaks.size(), 8u);
  const double decrement = std::log(peaks.front() / peaks.back()) / static_cast<double>(peaks.size() - 1);
  return decrement / std::sqrt(4.0 * M_PI * M_PI + decrement * decrement);
}

// The boom's first mode of the linearisation about its equilibrium, scaled to a 0.02 m tip deflection,
// and its period.
std::pair<Eigen::VectorXd, double> first_bending_mode(multibody::CraneEquations& equations, const Eigen::VectorXd& rest) {
  const multibody::LinearisedCrane linear = multibody::linearise_crane(equations, rest);
  // The undamped modes of M⁻¹K as linearised (a taut wire's terms make K slightly unsymmetric).
  const Eigen::MatrixXd mass_inverse_stiffness = linear.mass.lu().solve(linear.stiffness);
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(mass_inverse_stiffness);
  int lowest = -1;
  for (int i = 0; i < solver.eigenvalues().size(); ++i) {
    const double value = solver.eigenvalues()(i).real();
    if (value > 0.0 && (lowest < 0 || value < solver.eigenvalues()(lowest).real())) lowest = i;
  }
  Eigen::VectorXd mode = solver.eigenvectors().col(lowest).real();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(mode.size());
  const double tip = equations.minimal_outputs(0.0, mode, zero).tip_deflection.y();
  mode *= 0.02 / tip;
  return {mode, 2.0 * M_PI / std::sqrt(solver.eigenvalues()(lowest).real())};
}

struct DampingCase {
  const char* scene_file;
  bool rayleigh;
};

TEST(BoomDamping, FreeDecayOfTheFirstModeGivesTheScenesRatioInNodalAndModalCoordinates) {
  for (const DampingCase c : {DampingCase{"paper_floating_crane.toml", false}, DampingCase{"paper_floating_crane.toml", true},
                       DampingCase{"pinned_luffing_crane.toml", false}}) {
    scene::Scene scene = scene::load_scene(std::string(FFRF_SOURCE_DIR "/cases/") + c.scene_file);
    scene.boom.damping_ratio = 0.02;
    scene.boom.rayleigh_damping = c.rayleigh;
    if (scene.luffing) {
      // The luffing wire across the tip, so stiff that the boom's first mode is its pinned–pinned one,
      // at its length at rest (the weight stretches it).
      const double angle = scene.boom.mount->angle, length = scene.boom.mesh.length;
      const Eigen::Vector2d heel(scene.boom.mount->root_x, scene.boom.mount->root_y);
      const Eigen::Vector2d anchor = heel + length * Eigen::Vector2d(std::cos(angle), std::sin(angle)) +
                                     20.0 * Eigen::Vector2d(-std::sin(angle), std::cos(angle));
      scene.luffing->a_frame_x = anchor.x();
      scene.luffing->a_frame_y = anchor.y();
      scene.luffing->wires = 1;
      scene.luffing->stiffness = 2e10;
      scene.luffing->unstretched_length = 20.0;
      scene.luffing->damping_ratio = 0.0;
    }
    for (const scene::BoomChoice& choice : {scene::BoomChoice{scene::BoomKind::nodal, 16},
                                            scene::BoomChoice{scene::BoomKind::modal, 16, 4, true}}) {
      auto equations = isolated_boom(scene, choice);
      const multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
      const auto [mode, period] = first_bending_mode(*equations, statics.z);
      const double zeta =
          free_decay_ratio(*equations, statics.z + mode, period, statics.outputs.tip_deflection.y());
      std::printf("%s%s, %s: first mode %.4f s, free-decay damping ratio %.5f (scene 0.02)\n", c.scene_file,
                  c.rayleigh ? " (rayleigh)" : "", choice.label().c_str(), period, zeta);
      EXPECT_NEAR(zeta, 0.02, 0.02 * 0.02) << c.scene_file << (c.rayleigh ? " rayleigh " : " ") << choice.label();
    }
  }
}

}  // namespace
}  // namespace ffrf
