// The pinned boom's natural modes as the crane supports it (see the header).
#include "study/supported_boom.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/rigid_motion.hpp"
#include "linalg/dense_solvers.hpp"
#include "multibody/crane_equations.hpp"
#include "multibody/crane_model.hpp"
#include "multibody/crane_statics.hpp"
#include "multibody/linearisation.hpp"
#include "nodal/nodal_coordinates.hpp"
#include "scene/crane_builder.hpp"

namespace ffrf::study {

std::string_view to_string(SupportedBoomMode::Kind kind) {
  switch (kind) {
    case SupportedBoomMode::Kind::swing: return "swing";
    case SupportedBoomMode::Kind::bending: return "bending";
    case SupportedBoomMode::Kind::axial: return "axial";
    case SupportedBoomMode::Kind::a_frame: return "A-frame";
  }
  return "?";
}

std::optional<SupportedBoomModes> supported_boom_modes(const scene::Scene& scene, int elements, int count) {
  if (!scene.is_crane() || !scene.boom.mount || !scene.boom.mount->pinned) return std::nullopt;
  const auto beam = scene::boom_beam(scene, elements);  // clamped-free in the frame the heel's angle turns
  const nodal::NodalCoordinates coordinates(beam);
  auto parameters = scene::build_crane_parameters(scene, coordinates, scene.boom.stiffening);
  // The deck held at its as-built pose, out of the water; the boom alone on its heel and wires.
  parameters.hull.fixed = true;
  parameters.hull.hydrostatics = false;
  parameters.hull.support_pose = Eigen::Vector3d::Zero();
  multibody::remove_cargo(parameters);
  parameters.stress.reset();  // (no stresses sampled here)
  const std::unique_ptr<multibody::CraneEquations> equations = multibody::make_crane_equations(std::move(parameters));
  const multibody::StaticEquilibrium statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
  const multibody::LinearisedCrane linear = multibody::linearise_crane(*equations, statics.z);

  const Eigen::MatrixXd stiffness = 0.5 * (linear.stiffness + linear.stiffness.transpose());
  const Eigen::MatrixXd mass = 0.5 * (linear.mass + linear.mass.transpose());
  // The generalized solver factors the mass by Cholesky without reporting a failure: check it first.
  if (Eigen::LLT<Eigen::MatrixXd>(mass).info() != Eigen::Success) {
    throw std::runtime_error("supported boom modes: the linearised mass matrix is not positive definite; check the "
                             "boom's section and mass per length");
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
  SupportedBoomModes out;
  out.elements = elements;
  out.luffing_tension = statics.outputs.luffing_tension;
  out.backstay_tension = statics.outputs.backstay_tension;
  // The rocking coordinates of the bodies pinned to the deck (the A-frame): their kinetic energy is
  // their inertia about the pin (the linearised mass's diagonal; nothing else moves with them) times γ̇².
  std::vector<int> rocking;
  for (const multibody::BodyBlock& block : equations->layout().bodies) {
    if (block.pinned) rocking.push_back(block.minimal);
  }
  out.a_frame = !rocking.empty();
  const int heel = equations->heel_offset();
  const fem::BeamSection& section = scene.boom.mesh.section;
  const double length = scene.boom.mesh.length;
  const double span_rate = std::sqrt(section.bending_rigidity() / (section.mass_per_length * std::pow(length, 4)));
  // The beam's consistent mass over its free nodal coordinates, the rigid turn about the heel in
  // them (node at x: u = 0, v = x, φ = 1) and a mask of the axial ones (u).
  const int free = beam->dofs.free_count();
  const Eigen::MatrixXd beam_mass(coordinates.mass_ff());
  const Eigen::VectorXd rotation = fem::rigid_motion(beam->mesh, beam->dofs, fem::RigidMotion::turn_about_root);
  const Eigen::VectorXd axial_part = fem::rigid_motion(beam->mesh, beam->dofs, fem::RigidMotion::axial_translation);
  const Eigen::MatrixXd beam_stiffness(coordinates.stiffness());
  int order = 0;
  for (int j = 0; j < std::min(count, linear.size()); ++j) {
    const Eigen::VectorXd shape = solver.eigenvectors().col(j);
    SupportedBoomMode mode;
    mode.hz = std::sqrt(std::max(solver.eigenvalues()(j), 0.0)) / (2.0 * std::numbers::pi);
    // The boom's displacement in the frame at rest: the heel's turn β r plus the elastic η. Its
    // kinetic energy ω² dᵀM d / 2 is the mode's whole potential energy; the boom's deformation
    // stores ηᵀK η / 2 of it (K ignores the rigid turn), the wires and gravity the rest.
    const Eigen::VectorXd elastic = shape.segment(linear.elastic_at, free);
    Eigen::VectorXd field = elastic;
    if (heel >= 0) field += shape(heel) * rotation;
    const Eigen::VectorXd field_momentum = beam_mass * field;
    double rocking_kinetic = 0.0;
    for (const int at : rocking) rocking_kinetic += shape(at) * shape(at) * linear.mass(at, at);
    const double kinetic = field.dot(field_momentum) + rocking_kinetic, omega = 2.0 * std::numbers::pi * mode.hz;
    mode.a_frame_share = rocking_kinetic / kinetic;
    mode.strain_share = omega > 0.0 ? std::min(elastic.dot(beam_stiffness * elastic) / (omega * omega * kinetic), 1.0) : 0.0;
    mode.axial_share = axial_part.cwiseProduct(field).dot(field_momentum) / kinetic;
    mode.kind = mode.a_frame_share > 0.5  ? SupportedBoomMode::Kind::a_frame
                : mode.strain_share < 0.5 ? SupportedBoomMode::Kind::swing
                : mode.axial_share > 0.5 ? SupportedBoomMode::Kind::axial : SupportedBoomMode::Kind::bending;
    if (mode.kind == SupportedBoomMode::Kind::bending) {
      mode.bending_order = ++order;
      mode.pinned_pinned_hz = std::pow(order * std::numbers::pi, 2) * span_rate / (2.0 * std::numbers::pi);
    }
    out.modes.push_back(mode);
  }
  return out;
}

}  // namespace ffrf::study
