// Shared helpers for the coupled-crane tests: the reference scene, building systems with tweaks,
// and period measurement from zero crossings.
#pragma once

#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "scene/crane_builder.hpp"
#include "scene/scene_loader.hpp"
#include "multibody/crane_run.hpp"
#include "multibody/crane_statics.hpp"

namespace ffrf::test {

inline scene::Scene reference_scene() { return scene::load_scene(FFRF_SOURCE_DIR "/cases/paper_floating_crane.toml"); }

// Builds a crane for `choice` with the model adjusted by `tweak` (hull supports, fixed hull, ...).
template <class Parameters>
multibody::WireModel& hoist_rope(Parameters& model) {
  static thread_local multibody::WireModel none;  // a crane without a cargo has no hoist wire to tweak
  return model.hoist_wire >= 0 ? model.wires[model.hoist_wire].rope : none;
}

inline std::unique_ptr<multibody::CraneEquations> build_with(
    const scene::Scene& scene, const scene::BoomChoice& choice,
    const std::function<void(multibody::HullModel&, multibody::WireModel&)>& tweak) {
  if (choice.kind == scene::BoomKind::nodal) {
    auto model = scene::build_crane_parameters(scene, nodal::NodalCoordinates(scene::boom_beam(scene, choice.elements)));
    tweak(model.hull, hoist_rope(model));
    return multibody::make_crane_equations(std::move(model));
  }
  auto model = scene::build_crane_parameters(scene, scene::modal_coordinates(scene, choice));
  tweak(model.hull, hoist_rope(model));
  return multibody::make_crane_equations(std::move(model));
}

// The conservative test crane: no water, waves or damping; the hull held by linear springs only
// (surge 5e5 N/m, heave 3.6e7 N/m, pitch 5e10 N m/rad), the paper's one-element boom. `start` is
// its spring-supported static equilibrium released 0.5 m up (hull and cargo together, so the wire
// keeps its stretch) with the cargo swung 1 m sideways: the wire stays taut throughout.
struct ConservativeCrane {
  std::unique_ptr<multibody::CraneEquations> equations;
  Eigen::VectorXd start;
};

inline ConservativeCrane conservative_crane() {
  scene::Scene scene = reference_scene();
  scene.wave.reset();
  scene.boom.damping_ratio = 0.0;
  scene.wire->damping_ratio = 0.0;
  scene.radiation.surge_damping = scene.radiation.heave_damping = scene.radiation.pitch_damping = 0.0;
  const double heave_stiffness = 3.6e7;
  const double weight = (scene.hull->mass + scene.boom.mesh.total_mass() + scene.cargo->mass) * scene.environment.gravity;
  ConservativeCrane crane;
  crane.equations = build_with(scene, {scene::BoomKind::nodal, 1, 0, false}, [&](multibody::HullModel& hull, multibody::WireModel&) {
    hull.hydrostatics = false;
    hull.mooring_stiffness = 0.0;
    hull.support_stiffness = Eigen::Vector3d(5.0e5, heave_stiffness, 5.0e10);
  });
  Eigen::VectorXd guess = crane.equations->initial_guess();
  guess(1) -= weight / heave_stiffness;  // start Newton where the heave spring carries the weight
  guess(4) -= weight / heave_stiffness;
  crane.start = multibody::solve_static_equilibrium(*crane.equations, guess).z;
  crane.start(1) += 0.5;
  crane.start(3) += 1.0;
  crane.start(4) += 0.5;
  return crane;
}

// A 10 m boom on a fixed hub at 45° carrying a 2 m cargo box on a 5 m wire whose hook sits
// straight above G2 (the wire hangs vertically through G2).
struct HubCrane {
  double youngs_modulus, area, second_moment, mass_per_length;  // boom section [Pa, m², m⁴, kg/m]
  int elements;
  double cargo_mass, wire_stiffness;  // [kg, N/m]
  double duration = 1.0, output_interval = 0.01;  // [s]
};
inline scene::Scene hub_crane_scene(const HubCrane& c) {
  const auto number = [](double value) {
    std::ostringstream text;
    text << std::setprecision(17) << value;
    return text.str();
  };
  const std::string text = "[scene]\nname = \"hub crane\"\n[boom]\nlength = 10.0\nyoungs_modulus = " + number(c.youngs_modulus) +
                           "\narea = " + number(c.area) + "\nsecond_moment = " + number(c.second_moment) +
                           "\nmass_per_length = " + number(c.mass_per_length) + "\nelements = " + std::to_string(c.elements) +
                           "\n[hub]\nangle = \"45 deg\"\nmotion = \"fixed\"\n[cargo]\nmass = " + number(c.cargo_mass) +
                           "\nlength = 2.0\nheight = 2.0\nhook_x = 0.0\nhook_y = 1.0\n[wire]\nunstretched_length = 5.0"
                           "\nstiffness = " + number(c.wire_stiffness) + "\n[simulation]\nduration = " + number(c.duration) +
                           "\noutput_interval = " + number(c.output_interval) + "\n";
  return scene::load_scene_text(text, "hub_crane.toml");
}

// The spin-up benchmark's beam (cases/spin_up_beam.toml) on a hub spinning at a constant rate from
// rest: N elements, the given stiffening, no gravity.
inline scene::Scene constant_spin_beam(double spin_rate, scene::Stiffening stiffening, int elements) {
  scene::Scene scene = scene::load_scene(FFRF_SOURCE_DIR "/cases/spin_up_beam.toml");
  scene.hub->motion = scene::HubMotion::constant_spin;
  scene.hub->spin_rate = spin_rate;
  scene.boom.mesh.element_count = elements;
  scene.boom.stiffening = stiffening;
  return scene;
}

// Mean period of a signal from its upward mean crossings (linear interpolation between samples).
inline double mean_period(const std::vector<double>& t, const std::vector<double>& x) {
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  std::vector<double> crossings;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (x[i - 1] < mean && x[i] >= mean) {
      crossings.push_back(t[i - 1] + (mean - x[i - 1]) / (x[i] - x[i - 1]) * (t[i] - t[i - 1]));
    }
  }
  if (crossings.size() < 2) return std::nan("");
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// max |a − b| / max |b − b[0]|: error relative to the motion's amplitude.
inline double relative_history_error(const std::vector<double>& a, const std::vector<double>& b) {
  double diff = 0.0, range = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    range = std::max(range, std::abs(b[i] - b[0]));
  }
  return diff / range;
}

template <class Get>
std::vector<double> column(const multibody::RunResult& run, Get get) {
  std::vector<double> values;
  for (const auto& s : run.samples) values.push_back(get(s));
  return values;
}

}  // namespace ffrf::test
