// Stress recovery along the boom (see header).
#include "multibody/boom_stress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/axial_force.hpp"
#include "fem/beam_element.hpp"
#include "multibody/planar.hpp"

namespace ffrf::multibody {

std::string_view to_string(StressRecovery method) {
  switch (method) {
    case StressRecovery::mode_displacement: return "displacement";
    case StressRecovery::mode_acceleration: return "acceleration";
  }
  return "?";
}

std::optional<StressRecovery> parse_stress_recovery(std::string_view text) {
  for (const StressRecovery method : all_stress_recoveries) {
    if (text == to_string(method)) return method;
  }
  return std::nullopt;
}

std::string stress_recovery_choices() { return "displacement|acceleration"; }

BoomStressModel make_boom_stress_model(BoomStressInputs in) {
  if (!in.beam) throw std::invalid_argument("boom stress recovery needs the boom's nodal mesh");
  const fem::BeamModel& beam = *in.beam;
  if (!(in.fibre_distance > 0.0 && std::isfinite(in.fibre_distance))) {
    throw std::invalid_argument("the boom's fibre distance must be positive, got " + std::to_string(in.fibre_distance));
  }
  if (!in.identity_basis && in.basis.rows() != beam.dofs.free_count()) {
    throw std::invalid_argument("the boom's basis has " + std::to_string(in.basis.rows()) + " rows for a mesh of " +
                                std::to_string(beam.dofs.free_count()) + " free DOFs");
  }
  if (in.method == StressRecovery::mode_acceleration && !in.mode_acceleration && !in.identity_basis) {
    throw std::invalid_argument("mode-acceleration stress recovery needs the boom's nodal body");
  }
  BoomStressModel model;
  const int elements = beam.mesh.element_count;
  for (int e = 0; e < elements; ++e) model.elements.push_back(fem::element_invariants(beam.mesh, e));
  model.element_stiffness = fem::element_stiffness(beam.mesh.section, beam.mesh.element_length());
  if (in.prestress) {
    for (int e = 0; e < elements; ++e) model.prestress_elements.push_back(fem::element_geometric_stiffness(beam.mesh, e, in.prestress));
  }
  if (in.centrifugal) {
    for (int e = 0; e < elements; ++e) {
      model.centrifugal_elements.push_back(fem::element_geometric_stiffness(beam.mesh, e, in.centrifugal));
    }
  }
  if (in.mode_acceleration && !in.identity_basis) {
    auto body = std::make_shared<FloatingFrameBody<nodal::NodalCoordinates>>(nodal::NodalCoordinates(in.beam), in.stiffness_damping,
                                                                              in.mass_damping);
    Eigen::SparseMatrix<double> stiffness = beam.stiffness;
    if (in.prestress) {
      Eigen::SparseMatrix<double> prestress = fem::assemble_geometric_stiffness(beam.mesh, beam.dofs, in.prestress);
      stiffness += prestress;
      body->set_prestress_stiffness(std::move(prestress));
    }
    if (in.centrifugal) body->set_centrifugal_stiffness(fem::assemble_geometric_stiffness(beam.mesh, beam.dofs, in.centrifugal));
    auto factor = std::make_shared<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(stiffness);
    if (factor->info() != Eigen::Success || !(factor->vectorD().minCoeff() > 0.0)) {
      throw std::invalid_argument(
          "the boom's static stiffness K + K_σ is not positive definite (a prestress beyond the buckling load?): "
          "mode-acceleration stress recovery needs it; run without static stiffening or with --stress-recovery displacement");
    }
    for (const double x : in.load_points) model.load_points.push_back({x, body->point(x)});
    model.static_stiffness = std::move(factor);
    model.nodal_body = std::move(body);
  }
  model.beam = std::move(in.beam);
  model.basis = std::move(in.basis);
  model.identity_basis = in.identity_basis;
  model.fibre_distance = in.fibre_distance;
  model.allowable_stress = in.allowable_stress;
  model.method = in.method;
  model.stiffness_damping = in.stiffness_damping;
  model.mass_damping = in.mass_damping;
  return model;
}

namespace {

constexpr int sections_per_element = 4;

// Each element's end forces r_e from the full nodal displacements, velocities and accelerations in
// `work` and the frame's motion (see the header), then the section forces and fibre stresses.
void fill_profile(const BoomStressModel& model, const BoomMotion& motion, std::span<const BoomPointLoad> point_loads,
                  const Eigen::Vector2d& gravity, BoomStressProfile& out, BoomStressWorkspace& work) {
  const fem::BeamMesh& mesh = model.beam->mesh;
  const int elements = mesh.element_count;
  const double l = mesh.element_length();
  const double w = motion.frame_velocity(2), w_dot = motion.frame_acceleration(2);
  const Eigen::Matrix2d a = rotation(motion.frame_pose(2));
  const Eigen::Vector2d body_load = a.transpose() * (gravity - motion.frame_acceleration.head<2>());  // per unit mass
  work.end_forces.resize(static_cast<std::size_t>(elements));
  work.transverse_load.resize(elements);
  for (int e = 0; e < elements; ++e) {
    const auto q = work.full_displacement.segment<6>(fem::node_dofs * e);
    const auto v = work.full_velocity.segment<6>(fem::node_dofs * e);
    const auto acc = work.full_acceleration.segment<6>(fem::node_dofs * e);
    const fem::ElementInvariants& inv = model.elements[static_cast<std::size_t>(e)];
    fem::ElementForces loads = (w * w) * (inv.u0_dot_shape.transpose() + inv.mass * q);
    loads.noalias() -= (2.0 * w) * (inv.skew * v);
    loads.noalias() += inv.shape_integral.transpose() * body_load;
    loads.noalias() += w_dot * (inv.u0_cross_shape.transpose() + inv.skew.transpose() * q);
    loads.noalias() -= inv.mass * (acc + model.mass_damping * v);
    work.transverse_load(e) = (loads(1) + loads(4)) / l;  // ∫ p_v dx / l: the v shapes sum to one
    fem::ElementForces& r = work.end_forces[static_cast<std::size_t>(e)];
    r.noalias() = model.element_stiffness * (q + model.stiffness_damping * v);
    if (!model.prestress_elements.empty()) r.noalias() += model.prestress_elements[static_cast<std::size_t>(e)] * q;
    if (!model.centrifugal_elements.empty()) r.noalias() += (w * w) * (model.centrifugal_elements[static_cast<std::size_t>(e)] * q);
    r -= loads;
  }
  // A wire's pull inside an element is one of its loads (one at a node acts between two elements' ends).
  for (const BoomPointLoad& load : point_loads) {
    const double at = load.x / l;
    const int e = static_cast<int>(std::floor(at));
    const double xi = at - e;
    if (e < 0 || e >= elements || xi < 1e-9 || xi > 1.0 - 1e-9) continue;
    const Eigen::Vector2d local = a.transpose() * load.force;
    work.end_forces[static_cast<std::size_t>(e)].noalias() -= fem::element_shape(xi, l).transpose() * local;
  }
  // Inside an element the distributed load is nearly its mean p_v, so N is linear and
  // M(s) = M_start (1 − s/l) + M_end s/l − p_v s (l − s)/2 (exact for a uniform load).
  const auto inside = [&](int e, double s) {
    const fem::ElementForces& r = work.end_forces[static_cast<std::size_t>(e)];
    const double t = s / l;
    return std::pair{-r(0) * (1.0 - t) + r(3) * t, -r(2) * (1.0 - t) + r(5) * t - 0.5 * work.transverse_load(e) * s * (l - s)};
  };
  // The sections: each node (both elements' ends averaged) and the quarters of each element.
  fem::section_forces_from_end_forces(mesh, work.end_forces, work.nodal_sections);
  const int sections = sections_per_element * elements + 1;
  out.forces.position.resize(sections);
  out.forces.axial_force.resize(sections);
  out.forces.bending_moment.resize(sections);
  for (int e = 0; e <= elements; ++e) {
    const int at = sections_per_element * e;
    out.forces.position(at) = work.nodal_sections.position(e);
    out.forces.axial_force(at) = work.nodal_sections.axial_force(e);
    out.forces.bending_moment(at) = work.nodal_sections.bending_moment(e);
    if (e == elements) break;
    for (int k = 1; k < sections_per_element; ++k) {
      const double s = l * k / sections_per_element;
      const auto [axial, moment] = inside(e, s);
      out.forces.position(at + k) = mesh.node_position(e) + s;
      out.forces.axial_force(at + k) = axial;
      out.forces.bending_moment(at + k) = moment;
    }
  }
  out.top.resize(sections);
  out.bottom.resize(sections);
  for (int s = 0; s < sections; ++s) {
    const fem::FibreStress stress =
        fem::fibre_stress(mesh.section, model.fibre_distance, out.forces.axial_force(s), out.forces.bending_moment(s));
    out.top(s) = stress.top;
    out.bottom(s) = stress.bottom;
  }
  // The peak between the sections too: the largest |N|/A + |M|c/I over eight points per element
  // and the vertex of its moment parabola.
  out.peak = 0.0;
  out.peak_position = 0.0;
  for (int e = 0; e < elements; ++e) {
    const fem::ElementForces& r = work.end_forces[static_cast<std::size_t>(e)];
    const double m_start = -r(2), m_end = r(5), p = work.transverse_load(e);
    const auto consider = [&](double s) {
      const auto [axial, moment] = inside(e, s);
      const double stress = fem::fibre_stress(mesh.section, model.fibre_distance, axial, moment).extreme();
      if (stress > out.peak) {
        out.peak = stress;
        out.peak_position = mesh.node_position(e) + s;
      }
    };
    for (int k = 0; k <= 8; ++k) consider(l * k / 8.0);
    if (p != 0.0) {
      const double vertex = 0.5 * l - (m_end - m_start) / (p * l);
      if (vertex > 0.0 && vertex < l) consider(vertex);
    }
  }
}

// The free nodal values Φ x (x itself for nodal coordinates; zeros for a rigid boom) into `out`.
void to_nodal(const BoomStressModel& model, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  if (model.identity_basis) {
    out = x;
  } else if (model.basis.cols() == 0) {
    out.setZero(model.beam->dofs.free_count());
  } else {
    out.noalias() = model.basis * x;
  }
}

void to_full(const fem::DofMap& dofs, const Eigen::VectorXd& free, Eigen::VectorXd& full) {
  full.setZero(dofs.full_count());
  for (int i = 0; i < dofs.free_count(); ++i) full(dofs.free_to_full[static_cast<std::size_t>(i)]) = free(i);
}

}  // namespace

void recover_boom_stress(const BoomStressModel& model, StressRecovery method, const BoomMotion& motion,
                         std::span<const BoomPointLoad> point_loads, const Eigen::Vector2d& gravity, BoomStressProfile& out,
                         BoomStressWorkspace& work) {
  const fem::DofMap& dofs = model.beam->dofs;
  const int free = dofs.free_count();
  to_nodal(model, motion.elastic, work.nodal_q);
  to_nodal(model, motion.elastic_rate, work.nodal_v);
  to_nodal(model, motion.elastic_acceleration, work.nodal_a);
  if (method == StressRecovery::mode_acceleration && !model.identity_basis) {
    if (!model.has_mode_acceleration()) throw std::logic_error("recover_boom_stress: no mode-acceleration data");
    const FloatingFrameBody<nodal::NodalCoordinates>& body = *model.nodal_body;
    work.full_q.resize(3 + free);
    work.full_v.resize(3 + free);
    work.force.resize(3 + free);
    work.full_q.head<3>() = motion.frame_pose;
    work.full_v.head<3>() = motion.frame_velocity;
    work.full_q.tail(free) = work.nodal_q;
    work.full_v.tail(free) = work.nodal_v;
    if (work.body.first.size() != free) work.body = body.workspace();
    body.loads_and_mass_blocks(work.full_q, work.full_v, gravity, work.force, work.reference, work.coupling, work.body);
    for (const BoomPointLoad& load : point_loads) {
      // The nodal point made with the model (a wire added since is made here).
      const auto known = std::find_if(model.load_points.begin(), model.load_points.end(),
                                      [&](const BoomLoadPoint& p) { return std::abs(p.x - load.x) < 1e-12; });
      body.add_point_force(work.full_q, known != model.load_points.end() ? known->point : body.point(load.x), load.force, work.force);
    }
    work.residual = work.force.tail(free);
    work.residual.noalias() -= work.coupling.transpose() * motion.frame_acceleration;
    work.residual.noalias() -= body.coords().mass_ff() * work.nodal_a;
    work.nodal_q += model.static_stiffness->solve(work.residual);
  }
  to_full(dofs, work.nodal_q, work.full_displacement);
  to_full(dofs, work.nodal_v, work.full_velocity);
  to_full(dofs, work.nodal_a, work.full_acceleration);
  fill_profile(model, motion, point_loads, gravity, out, work);
}

}  // namespace ffrf::multibody
