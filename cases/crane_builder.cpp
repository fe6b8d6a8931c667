// Scene → coupled crane (see header).
#include "cases/crane_builder.hpp"

#include <cmath>
#include <numbers>

#include "cases/scene_loader.hpp"
#include "fem/analytic_beam.hpp"

namespace ffrf::cases {

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
  switch (kind) {
    case BoomKind::rigid: return "rigid";
    case BoomKind::nodal: return "nodal N=" + std::to_string(elements);
    case BoomKind::modal:
      return "modal k=" + std::to_string(modes) + (static_modes ? "+static" : "") + " (N=" + std::to_string(elements) + ")";
  }
  return "?";
}

std::shared_ptr<const fem::BeamModel> boom_beam(const Scene& scene, int elements) {
  fem::BeamMesh mesh = scene.boom.mesh;
  mesh.element_count = elements;
  return std::make_shared<const fem::BeamModel>(fem::make_beam_model(mesh, fem::Boundary::clamped_free));
}

double boom_stiffness_damping(const Scene& scene) {
  const double omega1 = fem::analytic_bending_modes(scene.boom.mesh, fem::Boundary::clamped_free, 1)[0].angular_frequency;
  return 2.0 * scene.boom.damping_ratio / omega1;
}

namespace {

[[noreturn]] void scene_problem(const Scene& scene, const std::string& key, const std::string& value, const std::string& message) {
  throw SceneError({SceneProblem{scene.file, 0, 0, key, value, message}});
}

}  // namespace

template <fem::ElasticCoordinates Coords>
coupling::CraneModel<Coords> build_crane_model(const Scene& scene, Coords coords) {
  if (!scene.is_crane() || !scene.cargo || !scene.wire || !scene.boom.mount) {
    scene_problem(scene, "hull", "", "a crane run needs the [hull], [cargo], [wire] sections and boom.angle/root_x/root_y");
  }
  const Hull& hull = *scene.hull;
  const Cargo& cargo = *scene.cargo;
  const Wire& wire = *scene.wire;
  const Environment& env = scene.environment;
  const double g = env.gravity, rho = env.water_density;
  const double boom_mass = scene.boom.mesh.total_mass();
  const double displaced_mass = hull.mass + boom_mass + cargo.mass;
  const double capacity = rho * hull.length * hull.width * hull.depth;
  if (displaced_mass >= capacity) {
    scene_problem(scene, "hull.mass", std::to_string(hull.mass),
                  "the hull would sink: hull + boom + cargo = " + std::to_string(displaced_mass / 1e3) +
                      " t exceeds the buoyancy of the whole box ρ·L·B·D = " + std::to_string(capacity / 1e3) +
                      " t; reduce the masses or enlarge hull.length/width/depth");
  }
  coupling::HullModel h;
  h.mass = hull.mass;
  h.pitch_inertia = hull.pitch_inertia();
  const double mid_x = hull.g1_aft_of_mid_length;  // mid-length lies forward of G1
  h.section = {mid_x - 0.5 * hull.length, mid_x + 0.5 * hull.length, -hull.g1_above_keel,
               hull.depth - hull.g1_above_keel, hull.width};
  const Radiation& rad = scene.radiation;
  h.added_mass = {rad.surge_added_mass * displaced_mass, rad.heave_added_mass * displaced_mass,
                  rad.pitch_added_inertia * h.pitch_inertia};
  const double draft = displaced_mass / (rho * hull.length * hull.width);
  // Centre of gravity of hull + boom + hanging cargo above the keel (undeformed, even keel).
  const BoomMount& mount = *scene.boom.mount;
  const double boom_cg = mount.root_y + 0.5 * scene.boom.mesh.length * std::sin(mount.angle);
  const double cargo_cg = mount.root_y + scene.boom.mesh.length * std::sin(mount.angle) - wire.unstretched_length - cargo.hook_y;
  const double center_of_gravity_above_keel =
      hull.g1_above_keel + (boom_mass * boom_cg + cargo.mass * cargo_cg) / displaced_mass;
  const Eigen::Vector2d hydrostatic =
      coupling::box_hydrostatic_stiffness(h.section, rho, g, displaced_mass / rho, center_of_gravity_above_keel);
  const auto critical = [](double mass, double stiffness) { return 2.0 * std::sqrt(mass * stiffness); };
  h.mooring_stiffness = scene.mooring.surge_stiffness;
  h.radiation_damping = {rad.surge_damping * critical(displaced_mass + h.added_mass(0), h.mooring_stiffness),
                         rad.heave_damping * critical(displaced_mass + h.added_mass(1), hydrostatic(0)),
                         rad.pitch_damping * critical(h.pitch_inertia + h.added_mass(2), std::max(hydrostatic(1), 0.0))};
  h.support_pose = Eigen::Vector3d(0.0, hull.g1_above_keel - draft, 0.0);  // even keel at the mean draft

  const double beta = boom_stiffness_damping(scene);
  coupling::FloatingFrameBody<Coords> boom(std::move(coords), beta);
  coupling::BodyPoint tip = boom.point(scene.boom.mesh.length);
  coupling::CraneModel<Coords> model{h, {Eigen::Vector2d(scene.boom.mount->root_x, scene.boom.mount->root_y), scene.boom.mount->angle},
                                     std::move(boom), std::move(tip), {}, {}, g, rho, std::nullopt};
  model.cargo = {cargo.mass, cargo.pitch_inertia(), Eigen::Vector2d(cargo.hook_x, cargo.hook_y)};
  model.wire = {wire.unstretched_length, wire.stiffness, wire.damping_ratio * critical(cargo.mass, wire.stiffness)};
  if (scene.wave) {
    const double direction = scene.wave->direction == WaveDirection::following ? 1.0 : -1.0;
    model.wave = coupling::AiryWave::from_height_period(scene.wave->height, scene.wave->period, direction,
                                                        scene.wave->ramp_periods, env.water_depth, g);
  }
  return model;
}

template coupling::CraneModel<nodal::NodalCoordinates> build_crane_model(const Scene&, nodal::NodalCoordinates);
template coupling::CraneModel<modal::ModalCoordinates> build_crane_model(const Scene&, modal::ModalCoordinates);

modal::ModalCoordinates modal_coordinates(const Scene& scene, const BoomChoice& choice, ModeCache* cache) {
  auto beam = boom_beam(scene, choice.kind == BoomKind::rigid ? 1 : choice.elements);
  modal::ModalBasis basis;
  if (choice.kind == BoomKind::rigid) {
    basis.vectors = Eigen::MatrixXd(beam->dofs.free_count(), 0);
  } else if (cache != nullptr) {
    const modal::EigenPairs modes = choice.modes > 0 ? cache->lowest_modes(scene, choice.elements, choice.modes, choice.solver)
                                                     : modal::EigenPairs{Eigen::VectorXd(0), Eigen::MatrixXd(beam->dofs.free_count(), 0), {}};
    const std::vector<modal::UnitLoad> loads =
        choice.static_modes ? modal::tip_and_body_unit_loads(beam->mesh) : std::vector<modal::UnitLoad>{};
    basis = modal::append_static_modes(beam->mesh, beam->dofs, beam->stiffness, beam->mass, modes.eigenvectors,
                                       modes.eigenvalues, loads);
  } else {
    modal::ModalBasisRequest request;
    request.vibration_modes = choice.modes;
    request.static_correction = choice.static_modes;
    if (choice.static_modes) request.loads = modal::tip_and_body_unit_loads(beam->mesh);
    request.solver = choice.solver;
    basis = modal::make_modal_basis(beam->mesh, beam->dofs, beam->stiffness, beam->mass, request);
  }
  return modal::ModalCoordinates(beam, std::move(basis));
}

std::unique_ptr<coupling::CraneEquations> build_crane(const Scene& scene, const BoomChoice& choice, ModeCache* cache) {
  if (choice.kind == BoomKind::nodal) {
    return coupling::make_crane_equations(build_crane_model(scene, nodal::NodalCoordinates(boom_beam(scene, choice.elements))));
  }
  return coupling::make_crane_equations(build_crane_model(scene, modal_coordinates(scene, choice, cache)));
}

}  // namespace ffrf::cases
