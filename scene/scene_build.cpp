// The Scene value from a scene file's valid keys (see scene_build.hpp).
#include "scene/scene_build.hpp"

#include <cmath>
#include <stdexcept>

#include "scene/bem_files.hpp"

namespace ffrf::scene {
namespace {

// [bem]: the keys (the files are read by read_bem_files once every key is valid).
BemHull bem_keys(const WrittenKeys& keys, const std::string& file) {
  BemHull bem;
  const auto path = [&](std::string_view key) {
    return keys.has(key) ? resolve_scene_path(file, keys.text(key)) : std::string();
  };
  bem.radiation_file = path("bem.radiation_file");
  bem.excitation_file = path("bem.excitation_file");
  bem.hydrostatics_file = path("bem.hydrostatics_file");
  if (keys.has("bem.capytaine_file")) {  // one dataset holds A, B and the excitation (check_bem_keys: no WAMIT keys)
    bem.format = BemFormat::capytaine;
    bem.radiation_file = bem.excitation_file = path("bem.capytaine_file");
  }
  if (keys.text("bem.infinite_frequency_added_mass") == "high-frequency")
    bem.infinite_frequency_method = hydro::InfiniteFrequencyMethod::high_frequency;
  bem.length_scale = keys.number("bem.length_scale");
  bem.origin_above_keel = keys.number("bem.origin_above_keel");
  bem.origin_forward_of_mid_length = keys.number("bem.origin_forward_of_mid_length");
  hydro::parse_radiation_kind(keys.text("bem.radiation_model"), bem.radiation_model);
  bem.excitation = keys.text("bem.excitation") == "bem" ? ExcitationModel::bem : ExcitationModel::froude_krylov;
  if (keys.has("bem.constant_period")) bem.constant_period = keys.number("bem.constant_period");
  bem.state_space_tolerance = keys.number("bem.state_space_tolerance");
  bem.kernel_time_step = keys.number("bem.kernel_time_step");
  bem.truncation_time = keys.number("bem.truncation_time");
  return bem;
}

double boom_mass_per_length(const WrittenKeys& keys) {
  return keys.has("boom.mass_per_length") ? keys.number("boom.mass_per_length")
                                          : keys.number("boom.density") * keys.number("boom.area");
}

fem::Boundary boundary_of(const std::string& keyword) {
  // The schema's choices equal fem::boundary_choices(); the loader has validated the keyword.
  const auto boundary = fem::parse_boundary(keyword);
  if (!boundary) throw std::logic_error("scene schema and fem::parse_boundary disagree on " + keyword);
  return *boundary;
}

}  // namespace

Scene build_scene(const WrittenKeys& keys, const std::string& file, const SceneParts& parts) {
  Scene scene;
  scene.file = file;
  if (keys.has("scene.name")) scene.name = keys.text("scene.name");
  if (keys.has("scene.description")) scene.description = keys.text("scene.description");
  const fem::BeamSection section{keys.number("boom.youngs_modulus"), keys.number("boom.area"),
                                 keys.number("boom.second_moment"), boom_mass_per_length(keys)};
  scene.boom.mesh = fem::BeamMesh{keys.number("boom.length"), static_cast<int>(keys.number("boom.elements")), section};
  scene.boom.boundary = boundary_of(keys.text("boom.boundary"));
  scene.boom.damping_ratio = keys.number("boom.damping_ratio");
  if (keys.has("boom.density")) scene.boom.density = keys.number("boom.density");
  scene.boom.stiffening = parse_stiffening(keys.text("boom.stiffening")).value_or(Stiffening::none);
  if (parts.crane) {
    scene.boom.mount = BoomMount{keys.number("boom.angle"), keys.number("boom.root_x"), keys.number("boom.root_y")};
    scene.hull = Hull{keys.number("hull.mass"),          keys.number("hull.pitch_radius_of_gyration"),
                      keys.number("hull.length"),        keys.number("hull.width"),
                      keys.number("hull.depth"),         keys.number("hull.g1_above_keel"),
                      keys.number("hull.g1_aft_of_mid_length")};
  }
  if (parts.hub) {
    const std::string& motion = keys.text("hub.motion");
    scene.hub = Hub{keys.number("hub.radius"), keys.number("hub.angle"),
                    motion == "spin-up" ? HubMotion::spin_up
                                        : (motion == "constant-spin" ? HubMotion::constant_spin : HubMotion::fixed),
                    keys.number("hub.spin_rate"), keys.number("hub.spin_up_time")};
    scene.boom.mount = BoomMount{0.0, keys.number("hub.radius"), 0.0};
  }
  if (parts.cargo) {
    const double l = keys.number("cargo.length");
    const double h = keys.number("cargo.height");
    const bool derived = !keys.has("cargo.pitch_radius_of_gyration");
    scene.cargo = Cargo{keys.number("cargo.mass"), l, h, keys.number("cargo.hook_x"), keys.number("cargo.hook_y"),
                        derived ? std::sqrt((l * l + h * h) / 12.0) : keys.number("cargo.pitch_radius_of_gyration"),
                        derived};
    scene.wire = Wire{keys.number("wire.unstretched_length"), keys.number("wire.stiffness"),
                      keys.number("wire.damping_ratio")};
  }
  scene.environment = Environment{keys.number("environment.water_density"), keys.number("environment.gravity"),
                                  keys.number("environment.water_depth")};
  if (parts.wave) build_wave(keys, scene);
  scene.radiation = Radiation{keys.number("radiation.surge_added_mass"), keys.number("radiation.heave_added_mass"),
                              keys.number("radiation.pitch_added_inertia"), keys.number("radiation.surge_damping"),
                              keys.number("radiation.heave_damping"), keys.number("radiation.pitch_damping")};
  if (parts.bem) scene.bem = bem_keys(keys, file);
  scene.hull_damping.linear = {keys.number("hull_damping.surge_linear"), keys.number("hull_damping.heave_linear"),
                               keys.number("hull_damping.pitch_linear")};
  scene.hull_damping.quadratic = {keys.number("hull_damping.surge_quadratic"), keys.number("hull_damping.heave_quadratic"),
                                  keys.number("hull_damping.pitch_quadratic")};
  scene.mooring = Mooring{keys.number("mooring.surge_stiffness")};
  scene.simulation = Simulation{keys.number("simulation.duration"), keys.number("simulation.output_interval"),
                                keys.text("simulation.initial_state") == "as-built" ? InitialState::as_built
                                                                                    : InitialState::static_equilibrium,
                                keys.number("simulation.cargo_lift"), keys.number("simulation.deflection_limit"),
                                keys.number("simulation.constraint_drift_limit")};
  return scene;
}

}  // namespace ffrf::scene
