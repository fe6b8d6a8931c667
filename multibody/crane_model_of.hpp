// The immutable half of the crane equations (Pinocchio's Model; multibody/crane_model.hpp): the
// CraneParameters and the constant data derived from it alone, computed once and shared read-only by
// every CraneEquations made from it (any thread):
//  * the factorization of the constant elastic mass M_ff (sparse LDLᵀ for nodal coordinates, dense
//    for modal ones), M_ff as a dense block, and M_ff⁻¹S̄ᵀ, M_ff⁻¹cᵀ (the constant columns of
//    M_ff⁻¹M_fR in the Schur complement, crane_equations_minimal.ipp);
//  * the index map of the coordinates (multibody/crane_layout.hpp);
//  * the Newton blocks' structure (bordered band for a nodal boom, dense otherwise) and the elastic
//    coordinates that move the wires' attachments on the boom (crane_equations_jacobian.ipp);
//  * the coordinates' typical sizes (tolerances and difference increments).
// Template definitions; included only through multibody/crane_equations_of.hpp.
#pragma once

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "linalg/dense_solvers.hpp"
#include "multibody/crane_layout.hpp"
#include "multibody/crane_model.hpp"

namespace ffrf::multibody::detail {

template <class Matrix>
using MassFactor = std::conditional_t<std::is_base_of_v<Eigen::SparseMatrixBase<Matrix>, Matrix>,
                                      Eigen::SimplicialLDLT<Matrix>, Eigen::LDLT<Eigen::MatrixXd>>;

template <fem::ElasticCoordinates Coords>
class CraneModelOf final : public CraneModel, public std::enable_shared_from_this<CraneModelOf<Coords>> {
 public:
  explicit CraneModelOf(CraneParameters<Coords> crane);

  std::unique_ptr<CraneEquations> equations() const override;  // multibody/crane_model.cpp
  std::shared_ptr<const CraneModel> in_waters(const HullModel& hull,
                                                    const std::optional<sea::WaveField>& wave) const override;  // ditto
  int elastic_size() const override { return n; }

  bool hull_free() const { return !model.hull.fixed; }
  int minimal_size() const { return layout.minimal_size(); }
  int full_size() const { return layout.full_size(); }

  CraneParameters<Coords> model;
  int n;               // elastic coordinates
  CraneLayout layout;  // where each body's and joint's coordinates sit
  double heel_inertia = 0.0;  // the boom's rotational inertia about B at rest (the heel row's scale)
  MassFactor<typename Coords::Matrix> elastic_mass_factor;
  Eigen::MatrixXd elastic_mass_dense;  // M_ff as a dense block of the full mass matrix
  Eigen::Matrix<double, Eigen::Dynamic, 2> mass_inverse_shape;  // M_ff⁻¹ S̄ᵀ
  Eigen::VectorXd mass_inverse_cross;                           // M_ff⁻¹ cᵀ (c = u0_cross_shape)
  BandStructure minimal_structure, full_structure;
  std::vector<int> wire_columns;  // elastic coordinates that move a wire's attachment on the boom (ascending)
  // Typical sizes: of each elastic coordinate, and of every minimal and full coordinate (the
  // difference increments' floor).
  Eigen::VectorXd elastic_scale, minimal_scale, full_scale;

 private:
  void find_structures();
};

template <fem::ElasticCoordinates Coords>
CraneModelOf<Coords>::CraneModelOf(CraneParameters<Coords> crane)
    : model(std::move(crane)),
      n(static_cast<int>(model.boom.elastic_size())),
      layout(crane_layout(!model.hull.fixed, model.bodies, model.mount.joint == HeelJoint::pin, n)) {
  const int body_count = static_cast<int>(model.bodies.size());
  if (model.cargo >= body_count || model.a_frame >= body_count) {
    throw std::invalid_argument("the crane's cargo or A-frame is not one of its rigid bodies");
  }
  if (model.cargo >= 0 && (model.hoist_wire < 0 || model.hoist_wire >= static_cast<int>(model.wires.size()))) {
    throw std::invalid_argument("the cargo hangs on no wire: give the crane a hoist wire");
  }
  if (model.cargo >= 0 && model.bodies[model.cargo].pinned()) throw std::invalid_argument("the cargo hangs free: it is not pinned to the hull");
  for (const RigidBodyModel& body : model.bodies) {
    // (the full coordinates' mass is diag(m, m, I_G) per body: a pinned body needs I_G > 0 as well)
    if (!(body.mass > 0.0) || !(body.rotary_inertia > 0.0)) {
      throw std::invalid_argument("the " + body.name + " needs a positive mass and rotary inertia about its centre of mass (mass " +
                                  std::to_string(body.mass) + " kg, rotary inertia " + std::to_string(body.rotary_inertia) + " kg m²)");
    }
  }
  if (layout.constraint_count() > solve::max_constraints) {
    throw std::invalid_argument("the crane's joints make " + std::to_string(layout.constraint_count()) +
                                " constraint rows in full coordinates; at most " + std::to_string(solve::max_constraints) +
                                " are held (the heel's 3 for a clamp or 2 for a pin, and 2 per body pinned to the hull)");
  }
  for (const WireConnector& wire : model.wires) {
    for (const BodyAttachment* end : {&wire.from, &wire.to}) {
      if (end->body == Body::rigid && (end->index < 0 || end->index >= body_count)) {
        throw std::invalid_argument("the " + wire.name + " ends on a rigid body the crane does not have (body " +
                                    std::to_string(end->index) + " of " + std::to_string(body_count) + ")");
      }
    }
  }
  if (model.wires.size() > static_cast<std::size_t>(solve::max_events)) {
    throw std::invalid_argument("the crane has " + std::to_string(model.wires.size()) + " wires; at most " +
                                std::to_string(solve::max_events) + " are tracked (one slack event each)");
  }
  // The hull's mass is read whole by the residual and the Jacobian but by its lower triangle in the
  // LDLᵀ of the minimal-coordinate accelerations: one matrix for every path needs a symmetric added
  // mass (scene/scene_loader.cpp makes the BEM files' symmetric when they are read).
  if (model.hull.radiation_memory) {
    const Eigen::Matrix3d& added = model.hull.radiation_memory->added_mass;
    const double asymmetry = (added - added.transpose()).cwiseAbs().maxCoeff();
    if (!(asymmetry <= 1e-12 * added.cwiseAbs().maxCoeff())) {
      throw std::invalid_argument("the hull's radiation added mass is not symmetric (largest |A_ij − A_ji| = " +
                                  std::to_string(asymmetry) + "): give its symmetric part (hydro::symmetrise_added_mass)");
    }
  }
  // Typical size of each elastic coordinate: the η_i that moves some nodal DOF by 1 cm (1 cm or
  // 0.01 rad for nodal coordinates; 0.01 / max|Φ e_i| for mass-normalized modal ones, whose units
  // are m·√kg), so tolerances mean the same physical displacement in every coordinate set.
  elastic_scale.resize(n);
  for (int i = 0; i < n; ++i) {
    const double largest = model.boom.coords().to_nodal(Eigen::VectorXd::Unit(n, i)).cwiseAbs().maxCoeff();
    elastic_scale(i) = largest > 0.0 ? 0.01 / largest : 0.01;
  }
  elastic_mass_dense = Eigen::MatrixXd(model.boom.coords().mass_ff());
  if (n > 0) {
    elastic_mass_factor.compute(model.boom.coords().mass_ff());
    if (elastic_mass_factor.info() != Eigen::Success) {
      throw std::runtime_error("the boom's elastic mass matrix is not positive definite: check the section's mass per length");
    }
    const Eigen::MatrixXd shape_t = model.boom.coords().shape_integral().transpose();
    mass_inverse_shape = elastic_mass_factor.solve(shape_t);
    const Eigen::VectorXd cross_t = model.boom.coords().u0_cross_shape().transpose();
    mass_inverse_cross = elastic_mass_factor.solve(cross_t);
  }
  Eigen::Matrix3d reference;
  Eigen::Matrix<double, 3, Eigen::Dynamic> coupling;
  model.boom.mass_blocks(Eigen::VectorXd::Zero(3 + n), reference, coupling);
  heel_inertia = reference(2, 2);
  find_structures();
}

template <fem::ElasticCoordinates Coords>
void CraneModelOf<Coords>::find_structures() {
  // A wire's loads on the boom couple the columns of its attachment's shape rows with each other.
  int bandwidth = 0;
  std::vector<bool> moves_a_wire(n, false);
  for (const WireConnector& wire : model.wires) {
    for (const BodyAttachment* end : {&wire.from, &wire.to}) {
      if (end->body != Body::boom) continue;
      int first = n, last = -1;
      for (int j = 0; j < n; ++j) {
        if (end->point.shape.col(j).squaredNorm() == 0.0) continue;
        moves_a_wire[j] = true;
        first = std::min(first, j);
        last = std::max(last, j);
      }
      if (last >= first) bandwidth = std::max(bandwidth, last - first);
    }
  }
  for (int j = 0; j < n; ++j) {
    if (moves_a_wire[j]) wire_columns.push_back(j);
  }
  bool banded = false;
  if constexpr (std::is_base_of_v<Eigen::SparseMatrixBase<typename Coords::Matrix>, typename Coords::Matrix>) {
    const auto widen = [&bandwidth](const typename Coords::Matrix& m) {
      for (int k = 0; k < m.outerSize(); ++k) {
        for (typename Coords::Matrix::InnerIterator it(m, k); it; ++it) {
          bandwidth = std::max(bandwidth, static_cast<int>(std::abs(it.row() - it.col())));
        }
      }
    };
    widen(model.boom.coords().mass_ff());
    widen(model.boom.coords().stiffness());
    widen(model.boom.coords().skew_ff());
    if (model.boom.has_prestress()) widen(model.boom.prestress_stiffness());
    if (model.boom.has_centrifugal_stiffening()) widen(model.boom.centrifugal_stiffness());
    banded = 2 * bandwidth + 1 < n;  // otherwise the band saves nothing
  }
  minimal_structure = banded ? BandStructure{layout.elastic, n, bandwidth, bandwidth} : BandStructure{minimal_size(), 0, 0, 0};
  full_structure = banded ? BandStructure{layout.frame + 3, n, bandwidth, bandwidth} : BandStructure{full_size(), 0, 0, 0};
  // Minimal coordinates: 1 m for positions, 0.01 rad for the hull's and the free bodies' pitch, the
  // pinned bodies' and the heel's angles, then the elastic ones. Full coordinates: every body's pose and
  // the boom frame like the hull's (1 m, 0.01 rad), then the elastic coordinates.
  minimal_scale = Eigen::VectorXd::Constant(minimal_size(), 1.0);
  full_scale = Eigen::VectorXd::Constant(full_size(), 1.0);
  if (layout.hull >= 0) minimal_scale(layout.hull + 2) = full_scale(layout.hull + 2) = 0.01;
  for (const BodyBlock& block : layout.bodies) {
    minimal_scale(block.minimal + (block.pinned ? 0 : 2)) = 0.01;
    full_scale(block.full + 2) = 0.01;
  }
  if (layout.heel >= 0) minimal_scale(layout.heel) = 0.01;
  minimal_scale.tail(n) = elastic_scale;
  full_scale(layout.frame + 2) = 0.01;
  full_scale.tail(n) = elastic_scale;
}

}  // namespace ffrf::multibody::detail
