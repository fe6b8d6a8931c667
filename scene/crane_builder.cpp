// Scene → coupled crane (see header).
#include "scene/crane_builder.hpp"

#include <cmath>
#include <numbers>
#include <type_traits>

#include "scene/irregular_sea.hpp"
#include "scene/a_frame.hpp"
#include "scene/luffing_wires.hpp"
#include "scene/bem_hull_model.hpp"
#include "scene/scene_key.hpp"
#include "scene/scene_loader.hpp"
#include "scene/recorded_sea.hpp"
#include "fem/analytic_beam.hpp"
#include "fem/axial_force.hpp"
#include "modal/free_free_modes.hpp"
#include "multibody/boom_stress.hpp"

namespace ffrf::scene {

std::string_view to_string(BoomKind kind) {
  switch (kind) {
    case BoomKind::rigid: return "rigid";
    case BoomKind::nodal: return "nodal";
    case BoomKind::modal: return "modal";
  }
  return "?";
}

std::optional<BoomKind> parse_boom_kind(std::string_view text) {
  for (BoomKind k : {BoomKind::rigid, BoomKind::nodal, BoomKind::modal}) {
    if (text == to_string(k)) return k;
  }
  return std::nullopt;
}

std::string boom_kind_choices() { return "rigid|nodal|modal"; }

std::string BoomChoice::label() const {
  // Appended piece by piece: `" " + std::string(...)` makes GCC 12 at -O3 report a false
  // -Wstringop-overflow when compiled through the precompiled header.
  std::string stiffened;
  if (stiffening && *stiffening != Stiffening::none) {
    stiffened += ' ';
    stiffened += to_string(*stiffening);
    stiffened += "-stiffened";
  }
  switch (kind) {
    case BoomKind::rigid: return "rigid";
    case BoomKind::nodal: return "nodal N=" + std::to_string(elements) + stiffened;
    case BoomKind::modal: {
      std::string set;
      if (mode_set != fem::Boundary::clamped_free) {
        set += ' ';
        set += fem::to_string(mode_set);
      }
      // (mode acceleration, the default stress recovery, is not named)
      const std::string stress = stress_recovery == StressRecovery::mode_displacement ? " (MD stress)" : "";
      return "modal k=" + std::to_string(modes) + (static_modes ? "+static" : "") + set + " (N=" + std::to_string(elements) +
             ")" + stiffened + stress;
    }
  }
  return "?";
}

std::shared_ptr<const fem::BeamModel> boom_beam(const Scene& scene, int elements, fem::Boundary reference) {
  fem::BeamMesh mesh = scene.boom.mesh;
  mesh.element_count = elements;
  return std::make_shared<const fem::BeamModel>(fem::make_beam_model(mesh, reference));
}

BoomDamping boom_damping(const Scene& scene) {
  const bool pinned = scene.boom.mount && scene.boom.mount->pinned;
  const auto modes =
      fem::analytic_bending_modes(scene.boom.mesh, pinned ? fem::Boundary::pinned_pinned : fem::Boundary::clamped_free, 2);
  const double zeta = scene.boom.damping_ratio, omega1 = modes[0].angular_frequency, omega2 = modes[1].angular_frequency;
  if (!scene.boom.rayleigh_damping) return {0.0, 2.0 * zeta / omega1};
  return {2.0 * zeta * omega1 * omega2 / (omega1 + omega2), 2.0 * zeta / (omega1 + omega2)};
}

namespace {

[[noreturn]] void scene_problem(const Scene& scene, const std::string& key, const std::string& value, const std::string& message) {
  throw SceneError({SceneProblem{scene.file, 0, 0, key, value, message}});
}

double critical_damping(double mass, double stiffness) { return 2.0 * std::sqrt(mass * stiffness); }

const fem::BeamModel& coords_beam(const nodal::NodalCoordinates& coords) { return coords.beam(); }
const fem::BeamModel& coords_beam(const modal::ModalCoordinates& coords) { return coords.beam(); }

// The floating hull of a crane scene: box section, hydrostatic stiffness for the radiation damping,
// added mass, mooring, the even-keel pose at the mean draft.
multibody::HullModel floating_hull(const Scene& scene) {
  const Hull& hull = *scene.hull;
  const Cargo& cargo = *scene.cargo;
  const Wire& wire = *scene.wire;
  const Environment& env = scene.environment;
  const double g = env.gravity, rho = env.water_density;
  const double boom_mass = scene.boom.mesh.total_mass();
  const double a_frame_mass = scene.a_frame ? scene.a_frame->mass : 0.0;  // (an A-frame rigid with the hull is in hull.mass)
  const double displaced_mass = hull.mass + boom_mass + cargo.mass + a_frame_mass;
  const double capacity = rho * hull.length * hull.width * hull.depth;
  if (displaced_mass >= capacity) {
    scene_problem(scene, scene_key("hull.mass"), std::to_string(hull.mass),
                  "the hull would sink: hull + boom + cargo (+ A-frame) = " + std::to_string(displaced_mass / 1e3) +
                      " t exceeds the buoyancy of the whole box ρ·L·B·D = " + std::to_string(capacity / 1e3) +
                      " t; reduce the masses or enlarge hull.length/width/depth");
  }
  multibody::HullModel h;
  h.mass = hull.mass;
  h.pitch_inertia = hull.pitch_inertia();
  const double mid_x = hull.g1_aft_of_mid_length;  // mid-length lies forward of G1
  h.section = {mid_x - 0.5 * hull.length, mid_x + 0.5 * hull.length, -hull.g1_above_keel,
               hull.depth - hull.g1_above_keel, hull.width};
  const Radiation& rad = scene.radiation;
  h.added_mass = {rad.surge_added_mass * displaced_mass, rad.heave_added_mass * displaced_mass,
                  rad.pitch_added_inertia * h.pitch_inertia};
  const double draft = displaced_mass / (rho * hull.length * hull.width);
  // Centre of gravity of hull + boom + hanging cargo (+ an A-frame on its pin, its centre halfway up)
  // above the keel (undeformed, even keel).
  const BoomMount& mount = *scene.boom.mount;
  const double boom_cg = mount.root_y + 0.5 * scene.boom.mesh.length * std::sin(mount.angle);
  const double cargo_cg = mount.root_y + scene.boom.mesh.length * std::sin(mount.angle) - wire.unstretched_length - cargo.hook_y;
  const double a_frame_cg = scene.a_frame ? 0.5 * (scene.a_frame->pin_y + scene.luffing->a_frame_y) : 0.0;
  const double center_of_gravity_above_keel =
      hull.g1_above_keel + (boom_mass * boom_cg + cargo.mass * cargo_cg + a_frame_mass * a_frame_cg) / displaced_mass;
  const Eigen::Vector2d hydrostatic =
      sea::box_hydrostatic_stiffness(h.section, rho, g, displaced_mass / rho, center_of_gravity_above_keel);
  h.mooring_stiffness = scene.mooring.surge_stiffness;
  h.radiation_damping = {rad.surge_damping * critical_damping(displaced_mass + h.added_mass(0), h.mooring_stiffness),
                         rad.heave_damping * critical_damping(displaced_mass + h.added_mass(1), hydrostatic(0)),
                         rad.pitch_damping * critical_damping(h.pitch_inertia + h.added_mass(2), std::max(hydrostatic(1), 0.0))};
  h.support_pose = Eigen::Vector3d(0.0, hull.g1_above_keel - draft, 0.0);  // even keel at the mean draft
  h.added_linear_damping = scene.hull_damping.linear;
  h.quadratic_damping = scene.hull_damping.quadratic;
  return h;
}

// The hub of a hub scene: held, or turned by its prescribed rotation; no water.
multibody::HullModel driven_hub(const Hub& hub) {
  multibody::HullModel h;
  h.hydrostatics = false;
  h.fixed = true;
  h.support_pose = Eigen::Vector3d(0.0, 0.0, hub.angle);
  multibody::PrescribedMotion motion;
  motion.pose0 = h.support_pose;
  motion.profile = hub.motion == HubMotion::spin_up         ? multibody::RotationProfile::spin_up
                   : hub.motion == HubMotion::constant_spin ? multibody::RotationProfile::constant_spin
                                                            : multibody::RotationProfile::fixed;
  motion.spin_rate = hub.spin_rate;
  motion.spin_up_time = hub.spin_up_time;
  h.prescribed = motion;
  return h;
}

}  // namespace

double boom_angle_at_rest(const Scene& scene) {
  return scene.hub ? scene.hub->angle : (scene.boom.mount ? scene.boom.mount->angle : 0.0);
}

double centrifugal_hub_radius(const Scene& scene) {
  if (scene.hub) return scene.hub->radius;
  if (!scene.boom.mount) return 0.0;
  const BoomMount& mount = *scene.boom.mount;
  return mount.root_x * std::cos(mount.angle) + mount.root_y * std::sin(mount.angle);
}

fem::AxialForce static_reference_axial_force(const Scene& scene) {
  const double g = scene.environment.gravity;
  const double along_axis = -std::sin(boom_angle_at_rest(scene));  // component of "down" along the boom axis
  const double cargo_weight = scene.cargo ? scene.cargo->mass * g : 0.0;
  double tip_load = cargo_weight * along_axis;
  if (scene.boom.mount && scene.boom.mount->pinned && scene.luffing) {
    // The luffing wires pull the tip back towards the A-frame: their tension at rest along the axis.
    const LuffingGeometry luffing = luffing_geometry(scene);
    if (luffing.attachment < scene.boom.mesh.length) {
      scene_problem(scene, scene_key("luffing.attachment"), std::to_string(luffing.attachment),
                    "static stiffening of a pinned boom takes the luffing wires' compression at the tip; with the wires "
                    "on the span, run without it (--stiffening none)");
    }
    const double angle = boom_angle_at_rest(scene);
    const Eigen::Vector2d axis(std::cos(angle), std::sin(angle));
    tip_load += luffing.total_tension * ((luffing.a_frame - luffing.boom_point) / luffing.length).dot(axis);
  }
  return fem::static_axial_force(scene.boom.mesh, scene.boom.mesh.section.mass_per_length * g * along_axis, tip_load);
}

SceneWaters scene_waters(const Scene& scene) {
  SceneWaters waters{scene.hub ? driven_hub(*scene.hub) : floating_hull(scene), std::nullopt};
  if (scene.is_crane()) waters.wave = scene_wave_field(scene);  // regular: one component; irregular: synthesized
  if (scene.bem && scene.is_crane()) apply_bem_hydrodynamics(scene, waters.hull, waters.wave);
  if (scene.is_crane() && waters.wave) {
    WaveKinematicsChoice choice;
    waters.hull.wave_record = recorded_sea(scene, waters.hull, *waters.wave, &choice);
    waters.hull.exact_kinematics_reason = choice.reason;
  }
  return waters;
}

std::shared_ptr<const multibody::CraneModel> with_waters(const multibody::CraneModel& model, const Scene& scene) {
  const SceneWaters waters = scene_waters(scene);
  return model.in_waters(waters.hull, waters.wave);
}

// A pinned heel and its luffing wires (scene/luffing_wires.hpp), each a rope from the A-frame top —
// on the hull, or on the A-frame pinned to the deck with its backstays (scene/a_frame.hpp) — to the
// boom point; their damping is the scene's fraction of critical for the boom's inertia about the heel,
// ρA L³/3, on the wires' rotational stiffness n k lever².
namespace {

// The A-frame as a rigid body pinned to the hull at its foot (its body frame at its centre of mass, x
// from the pin to the top) and its backstays from the top to the deck point; returns the top's point
// on it for the luffing wires.
template <fem::ElasticCoordinates Coords>
multibody::BodyAttachment add_a_frame(const Scene& scene, multibody::CraneParameters<Coords>& model) {
  const AFrameGeometry geometry = a_frame_geometry(scene);
  const Backstay& backstay = *scene.backstay;
  model.a_frame = static_cast<int>(model.bodies.size());
  const Eigen::Vector2d half(0.5 * geometry.height, 0.0);  // the top from the centre, body frame (the pin at −half)
  model.bodies.push_back({.name = "A-frame",
                          .mass = scene.a_frame->mass,
                          .rotary_inertia = geometry.rotary_inertia,
                          .mount = multibody::RigidMount::pinned_to_hull,
                          .pivot_on_hull = geometry.pin,
                          .pivot_on_body = -half,
                          .angle = geometry.angle});
  const multibody::BodyAttachment top = multibody::on_rigid_body(model.a_frame, half);
  for (int i = 0; i < backstay.wires; ++i) {
    model.wires.push_back({backstay.wires == 1 ? "backstay" : "backstay " + std::to_string(i + 1),
                           {geometry.backstay_unstretched_length, backstay.stiffness, geometry.backstay_damping},
                           top,
                           multibody::on_hull(geometry.deck),
                           1,
                           multibody::WireRole::backstay});
  }
  return top;
}

template <fem::ElasticCoordinates Coords>
void add_luffing_wires(const Scene& scene, multibody::CraneParameters<Coords>& model) {
  const Luffing& luffing = *scene.luffing;
  const LuffingGeometry geometry = luffing_geometry(scene);
  model.mount.joint = multibody::HeelJoint::pin;
  const double length = scene.boom.mesh.length;
  const double heel_inertia = scene.boom.mesh.total_mass() * length * length / 3.0;
  const double lever_squared = geometry.lever * geometry.lever;
  const double tackle = tackle_stiffness(luffing);
  const double rotational_stiffness = luffing.wires * tackle * lever_squared;
  const double damping = luffing.damping_ratio * 2.0 * std::sqrt(rotational_stiffness * heel_inertia) / (luffing.wires * lever_squared);
  if (scene.a_frame && !scene.backstay) {
    scene_problem(scene, "a_frame", "", "an A-frame pinned to the deck needs the [backstay] wires that hold it");
  }
  const multibody::BodyAttachment a_frame_top = scene.a_frame ? add_a_frame(scene, model) : multibody::on_hull(geometry.a_frame);
  for (int i = 0; i < luffing.wires; ++i) {
    model.wires.push_back({luffing.wires == 1 ? "luffing wire" : "luffing wire " + std::to_string(i + 1),
                           {geometry.unstretched_length, tackle, damping},
                           multibody::on_boom(model.boom.point(geometry.attachment)),
                           a_frame_top,
                           luffing.parts,
                           multibody::WireRole::luffing});
  }
}

}  // namespace

// The stresses along the boom (multibody/boom_stress.hpp), recovered on the coordinates' own mesh —
// for a rigid boom (no elastic coordinates) on the scene's mesh, by mode acceleration alone — with the
// boom's damping, the same geometric stiffening and the wires' ends on the boom as its loads.
template <fem::ElasticCoordinates Coords>
std::shared_ptr<const multibody::BoomStressModel> boom_stress_model(const Scene& scene, const multibody::CraneParameters<Coords>& crane,
                                                                    StressRecovery method, Stiffening stiffening) {
  const Coords& coords = crane.boom.coords();
  constexpr bool nodal = std::is_same_v<Coords, nodal::NodalCoordinates>;
  const bool rigid = coords.size() == 0;
  multibody::BoomStressInputs in;
  in.beam = rigid ? boom_beam(scene, scene.boom.mesh.element_count) : coords.beam_model();
  if constexpr (!nodal) in.basis = rigid ? Eigen::MatrixXd(in.beam->dofs.free_count(), 0) : coords.basis().vectors;
  in.identity_basis = nodal;
  in.fibre_distance = scene.boom.fibre_distance;
  in.allowable_stress = scene.boom.allowable_stress.value_or(0.0);
  // (a nodal boom's displacements are its answer; a rigid boom's stresses are the quasi-static ones)
  in.method = nodal ? StressRecovery::mode_displacement : rigid ? StressRecovery::mode_acceleration : method;
  in.stiffness_damping = crane.boom.stiffness_damping();
  in.mass_damping = crane.boom.mass_damping();
  if (has_static_stiffening(stiffening)) in.prestress = static_reference_axial_force(scene);
  if (has_centrifugal_stiffening(stiffening)) in.centrifugal = fem::centrifugal_axial_force(in.beam->mesh, centrifugal_hub_radius(scene));
  for (const multibody::WireConnector& wire : crane.wires) {
    for (const multibody::BodyAttachment* end : {&wire.from, &wire.to}) {
      if (end->body == multibody::Body::boom) in.load_points.push_back(end->point.undeformed.x());
    }
  }
  in.mode_acceleration = !nodal;
  return std::make_shared<const multibody::BoomStressModel>(multibody::make_boom_stress_model(std::move(in)));
}

template <fem::ElasticCoordinates Coords>
multibody::CraneParameters<Coords> build_crane_parameters(const Scene& scene, Coords coords, Stiffening stiffening,
                                                          StressRecovery stress_recovery) {
  if (!scene.has_base() || !scene.boom.mount || (scene.is_crane() && (!scene.cargo || !scene.wire))) {
    scene_problem(scene, "hull", "", "a crane run needs [hull] (with [cargo], [wire] and boom.angle/root_x/root_y) or [hub]");
  }
  const Environment& env = scene.environment;
  const BoomDamping damping = boom_damping(scene);
  // Geometric stiffening, assembled in nodal space on the coordinates' own mesh and projected.
  const fem::BeamModel& beam = coords_beam(coords);
  typename Coords::Matrix prestress, centrifugal;
  if (has_static_stiffening(stiffening)) {
    prestress = coords.project(fem::assemble_geometric_stiffness(beam.mesh, beam.dofs, static_reference_axial_force(scene)));
  }
  if (has_centrifugal_stiffening(stiffening)) {
    centrifugal = coords.project(fem::assemble_geometric_stiffness(
        beam.mesh, beam.dofs, fem::centrifugal_axial_force(beam.mesh, centrifugal_hub_radius(scene))));
  }
  multibody::FloatingFrameBody<Coords> boom(std::move(coords), damping.stiffness, damping.mass);
  if (prestress.size() > 0) boom.set_prestress_stiffness(std::move(prestress));
  if (centrifugal.size() > 0) boom.set_centrifugal_stiffness(std::move(centrifugal));
  multibody::BodyPoint tip = boom.point(scene.boom.mesh.length);
  const BoomMount& mount = *scene.boom.mount;
  SceneWaters waters = scene_waters(scene);
  multibody::CraneParameters<Coords> model{.hull = std::move(waters.hull),
                                           .mount = {Eigen::Vector2d(mount.root_x, mount.root_y), mount.angle},
                                           .boom = std::move(boom),
                                           .boom_tip = tip,
                                           .gravity = env.gravity,
                                           .water_density = env.water_density,
                                           .wave = std::move(waters.wave)};  // (the stresses' recovery, set below)
  if (scene.cargo && scene.wire) {
    const Cargo& cargo = *scene.cargo;
    const Wire& wire = *scene.wire;
    model.cargo = static_cast<int>(model.bodies.size());
    model.bodies.push_back({.name = "cargo", .mass = cargo.mass, .rotary_inertia = cargo.pitch_inertia()});
    model.hoist_wire = static_cast<int>(model.wires.size());
    model.wires.push_back({"hoist wire",
                           {wire.unstretched_length, wire.stiffness, wire.damping_ratio * critical_damping(cargo.mass, wire.stiffness)},
                           multibody::on_boom(std::move(tip)),
                           multibody::on_rigid_body(model.cargo, Eigen::Vector2d(cargo.hook_x, cargo.hook_y)),
                           1,
                           multibody::WireRole::hoist});
  }
  if (mount.pinned) add_luffing_wires(scene, model);
  model.stress = boom_stress_model(scene, model, stress_recovery, stiffening);
  return model;
}

template multibody::CraneParameters<nodal::NodalCoordinates> build_crane_parameters(const Scene&, nodal::NodalCoordinates, Stiffening,
                                                                                   StressRecovery);
template multibody::CraneParameters<modal::ModalCoordinates> build_crane_parameters(const Scene&, modal::ModalCoordinates, Stiffening,
                                                                                   StressRecovery);

modal::ModalCoordinates modal_coordinates(const Scene& scene, const BoomChoice& choice, modal::ModeCache* cache) {
  const bool modal = choice.kind == BoomKind::modal;
  if (modal && choice.mode_set == fem::Boundary::pinned_pinned && !(scene.boom.mount && scene.boom.mount->pinned)) {
    // The pinned-pinned set's frame is the chord frame: its origin at the heel pin, its angle free.
    // A clamped heel holds the frame at the root tangent, which the clamped-free and free-free sets
    // (both taken in the tangent frame) describe.
    scene_problem(scene, scene_key("boom.heel"), "\"clamped\"",
                  "the pinned-pinned mode set needs a boom pinned at its heel (boom.heel = \"pinned\", its chord frame "
                  "turning about the pin); a clamped boom takes the clamped-free or the free-free set");
  }
  // The free-free set lives in the tangent frame: the clamped-free DOFs.
  const bool chord = modal && choice.mode_set == fem::Boundary::pinned_pinned;
  auto beam = boom_beam(scene, choice.kind == BoomKind::rigid ? 1 : choice.elements,
                        chord ? fem::Boundary::pinned_pinned : fem::Boundary::clamped_free);
  if (choice.kind == BoomKind::rigid) {
    modal::ModalBasis basis;
    basis.vectors = Eigen::MatrixXd(beam->dofs.free_count(), 0);
    return modal::ModalCoordinates(beam, std::move(basis));
  }
  // One way to the vibration modes, cached or not, so a basis never depends on who built it.
  modal::ModeCache local;
  modal::ModeCache& modes_of_mesh = cache != nullptr ? *cache : local;
  modal::EigenPairs modes{Eigen::VectorXd(0), Eigen::MatrixXd(beam->dofs.free_count(), 0), {}};
  if (choice.modes > 0) {
    modes = choice.mode_set == fem::Boundary::free_free
                ? modal::free_free_modes_in_tangent_frame(*beam, choice.modes, choice.solver, modes_of_mesh)
                : modes_of_mesh.lowest_modes(beam->mesh, beam->boundary, choice.modes, choice.solver);
  }
  const std::vector<modal::UnitLoad> loads =
      choice.static_modes ? modal::tip_and_body_unit_loads(beam->mesh) : std::vector<modal::UnitLoad>{};
  modal::ModalBasis basis = modal::append_static_modes(beam->mesh, beam->dofs, beam->stiffness, beam->mass,
                                                       modes.eigenvectors, modes.eigenvalues, loads);
  return modal::ModalCoordinates(beam, std::move(basis));
}

std::shared_ptr<const multibody::CraneModel> build_crane_model(const Scene& scene, const BoomChoice& choice,
                                                                     modal::ModeCache* cache) {
  const Stiffening stiffening = choice.stiffening.value_or(scene.boom.stiffening);
  if (choice.kind == BoomKind::nodal) {
    return multibody::make_crane_model(
        build_crane_parameters(scene, nodal::NodalCoordinates(boom_beam(scene, choice.elements)), stiffening, choice.stress_recovery));
  }
  return multibody::make_crane_model(
      build_crane_parameters(scene, modal_coordinates(scene, choice, cache), stiffening, choice.stress_recovery));
}

std::unique_ptr<multibody::CraneEquations> build_crane_equations(const Scene& scene, const BoomChoice& choice, modal::ModeCache* cache) {
  return build_crane_model(scene, choice, cache)->equations();
}

}  // namespace ffrf::scene
