// The Scene value from a scene file's valid keys (see scene_build.hpp).
#include "scene/scene_build.hpp"

#include <cmath>
#include <stdexcept>

#include "scene/bem_files.hpp"
#include "scene/scene_key.hpp"
#include "fem/section_forces.hpp"

namespace ffrf::scene {
namespace {

// [bem]: the keys (the files are read by read_bem_files once every key is valid).
BemHull bem_keys(const WrittenKeys& keys, const std::string& file) {
  BemHull bem;
  const auto path = [&](std::string_view key) {
    return keys.has(key) ? resolve_scene_path(file, keys.text(key)) : std::string();
  };
  bem.radiation_file = path(scene_key("bem.radiation_file"));
  bem.excitation_file = path(scene_key("bem.excitation_file"));
  bem.hydrostatics_file = path(scene_key("bem.hydrostatics_file"));
  if (keys.has(scene_key("bem.capytaine_file"))) {  // one dataset holds A, B and the excitation (check_bem_keys: no WAMIT keys)
    bem.format = BemFormat::capytaine;
    bem.radiation_file = bem.excitation_file = path(scene_key("bem.capytaine_file"));
  }
  if (keys.text(scene_key("bem.infinite_frequency_added_mass")) == "high-frequency")
    bem.infinite_frequency_method = hydro::InfiniteFrequencyMethod::high_frequency;
  bem.length_scale = keys.number(scene_key("bem.length_scale"));
  bem.origin_above_keel = keys.number(scene_key("bem.origin_above_keel"));
  bem.origin_forward_of_mid_length = keys.number(scene_key("bem.origin_forward_of_mid_length"));
  hydro::parse_radiation_kind(keys.text(scene_key("bem.radiation_model")), bem.radiation_model);
  bem.excitation = keys.text(scene_key("bem.excitation")) == "bem" ? ExcitationModel::bem : ExcitationModel::froude_krylov;
  if (keys.has(scene_key("bem.constant_period"))) bem.constant_period = keys.number(scene_key("bem.constant_period"));
  bem.state_space_tolerance = keys.number(scene_key("bem.state_space_tolerance"));
  bem.kernel_time_step = keys.number(scene_key("bem.kernel_time_step"));
  bem.truncation_time = keys.number(scene_key("bem.truncation_time"));
  return bem;
}

double boom_mass_per_length(const WrittenKeys& keys) {
  return keys.has(scene_key("boom.mass_per_length")) ? keys.number(scene_key("boom.mass_per_length"))
                                          : keys.number(scene_key("boom.density")) * keys.number(scene_key("boom.area"));
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
  if (keys.has(scene_key("scene.name"))) scene.name = keys.text(scene_key("scene.name"));
  if (keys.has(scene_key("scene.description"))) scene.description = keys.text(scene_key("scene.description"));
  const fem::BeamSection section{keys.number(scene_key("boom.youngs_modulus")), keys.number(scene_key("boom.area")),
                                 keys.number(scene_key("boom.second_moment")), boom_mass_per_length(keys)};
  scene.boom.mesh = fem::BeamMesh{keys.number(scene_key("boom.length")), static_cast<int>(keys.number(scene_key("boom.elements"))), section};
  scene.boom.boundary = boundary_of(keys.text(scene_key("boom.boundary")));
  scene.boom.damping_ratio = keys.number(scene_key("boom.damping_ratio"));
  scene.boom.rayleigh_damping = keys.text(scene_key("boom.damping")) == "rayleigh";
  if (keys.has(scene_key("boom.density"))) scene.boom.density = keys.number(scene_key("boom.density"));
  scene.boom.stiffening = parse_stiffening(keys.text(scene_key("boom.stiffening"))).value_or(Stiffening::none);
  scene.boom.fibre_distance = keys.has(scene_key("boom.fibre_distance")) ? keys.number(scene_key("boom.fibre_distance"))
                                                                        : fem::two_flange_fibre_distance(section);
  if (keys.has(scene_key("boom.allowable_stress"))) scene.boom.allowable_stress = keys.number(scene_key("boom.allowable_stress"));
  if (parts.crane) {
    scene.boom.mount = BoomMount{keys.number(scene_key("boom.angle")), keys.number(scene_key("boom.root_x")),
                                 keys.number(scene_key("boom.root_y")), keys.text(scene_key("boom.heel")) == "pinned"};
    if (keys.has(scene_key("luffing.a_frame_x"))) {
      Luffing luffing{keys.number(scene_key("luffing.a_frame_x")), keys.number(scene_key("luffing.a_frame_y")),
                      keys.number(scene_key("luffing.stiffness")), static_cast<int>(keys.number(scene_key("luffing.wires"))),
                      std::nullopt, std::nullopt, 0.0};
      if (keys.has(scene_key("luffing.attachment"))) luffing.attachment = keys.number(scene_key("luffing.attachment"));
      if (keys.has(scene_key("luffing.unstretched_length"))) {
        luffing.unstretched_length = keys.number(scene_key("luffing.unstretched_length"));
      }
      luffing.damping_ratio = keys.number(scene_key("luffing.damping_ratio"));
      luffing.parts = static_cast<int>(keys.number(scene_key("luffing.parts")));
      scene.luffing = luffing;
    }
    if (keys.has(scene_key("a_frame.pin_x"))) {
      AFrame a_frame{keys.number(scene_key("a_frame.pin_x")), keys.number(scene_key("a_frame.pin_y")),
                     keys.number(scene_key("a_frame.mass")), std::nullopt};
      if (keys.has(scene_key("a_frame.radius_of_gyration"))) a_frame.radius_of_gyration = keys.number(scene_key("a_frame.radius_of_gyration"));
      scene.a_frame = a_frame;
    }
    if (keys.has(scene_key("backstay.deck_x"))) {
      Backstay backstay{keys.number(scene_key("backstay.deck_x")), keys.number(scene_key("backstay.deck_y")),
                        keys.number(scene_key("backstay.stiffness")), static_cast<int>(keys.number(scene_key("backstay.wires"))),
                        std::nullopt, keys.number(scene_key("backstay.damping_ratio"))};
      if (keys.has(scene_key("backstay.unstretched_length"))) {
        backstay.unstretched_length = keys.number(scene_key("backstay.unstretched_length"));
      }
      scene.backstay = backstay;
    }
    scene.hull = Hull{keys.number(scene_key("hull.mass")),          keys.number(scene_key("hull.pitch_radius_of_gyration")),
                      keys.number(scene_key("hull.length")),        keys.number(scene_key("hull.width")),
                      keys.number(scene_key("hull.depth")),         keys.number(scene_key("hull.g1_above_keel")),
                      keys.number(scene_key("hull.g1_aft_of_mid_length"))};
  }
  if (parts.hub) {
    const std::string& motion = keys.text(scene_key("hub.motion"));
    scene.hub = Hub{keys.number(scene_key("hub.radius")), keys.number(scene_key("hub.angle")),
                    motion == "spin-up" ? HubMotion::spin_up
                                        : (motion == "constant-spin" ? HubMotion::constant_spin : HubMotion::fixed),
                    keys.number(scene_key("hub.spin_rate")), keys.number(scene_key("hub.spin_up_time"))};
    scene.boom.mount = BoomMount{0.0, keys.number(scene_key("hub.radius")), 0.0};
  }
  if (parts.cargo) {
    const double l = keys.number(scene_key("cargo.length"));
    const double h = keys.number(scene_key("cargo.height"));
    const bool derived = !keys.has(scene_key("cargo.pitch_radius_of_gyration"));
    scene.cargo = Cargo{keys.number(scene_key("cargo.mass")), l, h, keys.number(scene_key("cargo.hook_x")), keys.number(scene_key("cargo.hook_y")),
                        derived ? std::sqrt((l * l + h * h) / 12.0) : keys.number(scene_key("cargo.pitch_radius_of_gyration")),
                        derived};
    scene.wire = Wire{keys.number(scene_key("wire.unstretched_length")), keys.number(scene_key("wire.stiffness")),
                      keys.number(scene_key("wire.damping_ratio"))};
  }
  scene.environment = Environment{keys.number(scene_key("environment.water_density")), keys.number(scene_key("environment.gravity")),
                                  keys.number(scene_key("environment.water_depth"))};
  if (parts.wave) build_wave(keys, scene);
  scene.radiation = Radiation{keys.number(scene_key("radiation.surge_added_mass")), keys.number(scene_key("radiation.heave_added_mass")),
                              keys.number(scene_key("radiation.pitch_added_inertia")), keys.number(scene_key("radiation.surge_damping")),
                              keys.number(scene_key("radiation.heave_damping")), keys.number(scene_key("radiation.pitch_damping"))};
  if (parts.bem) scene.bem = bem_keys(keys, file);
  scene.hull_damping.linear = {keys.number(scene_key("hull_damping.surge_linear")), keys.number(scene_key("hull_damping.heave_linear")),
                               keys.number(scene_key("hull_damping.pitch_linear"))};
  scene.hull_damping.quadratic = {keys.number(scene_key("hull_damping.surge_quadratic")), keys.number(scene_key("hull_damping.heave_quadratic")),
                                  keys.number(scene_key("hull_damping.pitch_quadratic"))};
  scene.mooring = Mooring{keys.number(scene_key("mooring.surge_stiffness"))};
  scene.simulation = Simulation{keys.number(scene_key("simulation.duration")), keys.number(scene_key("simulation.output_interval")),
                                keys.text(scene_key("simulation.initial_state")) == "as-built" ? InitialState::as_built
                                                                                    : InitialState::static_equilibrium,
                                keys.number(scene_key("simulation.cargo_lift")), keys.number(scene_key("simulation.deflection_limit")),
                                keys.number(scene_key("simulation.constraint_drift_limit"))};
  return scene;
}

}  // namespace ffrf::scene
