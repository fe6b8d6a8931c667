// Projection of the nodal-space beam model on a modal basis Φ (done once).
#include "modal/modal_coordinates.hpp"

#include <stdexcept>

#include "fem/point_shape.hpp"

namespace ffrf::modal {

ModalCoordinates::ModalCoordinates(std::shared_ptr<const fem::BeamModel> beam, ModalBasis basis)
    : beam_(std::move(beam)), basis_(std::move(basis)) {
  if (!beam_) throw std::invalid_argument("ModalCoordinates needs a beam model");
  const Eigen::MatrixXd& phi = basis_.vectors;
  if (phi.rows() != beam_->dofs.free_count()) {
    throw std::invalid_argument("modal basis has " + std::to_string(phi.rows()) + " rows but the beam has " +
                                std::to_string(beam_->dofs.free_count()) + " free DOFs");
  }
  const fem::NodalInvariants& inv = beam_->invariants;
  shape_integral_ = inv.shape_integral * phi;
  u0_dot_shape_ = inv.u0_dot_shape * phi;
  u0_cross_shape_ = inv.u0_cross_shape * phi;
  mass_ff_ = phi.transpose() * (inv.mass_ff * phi);
  skew_ff_ = phi.transpose() * (inv.skew_ff * phi);
  stiffness_ = phi.transpose() * (beam_->stiffness * phi);
  unit_geometric_stiffness_ = phi.transpose() * (beam_->unit_geometric_stiffness * phi);
}

ModalCoordinates::Rows ModalCoordinates::displacement_rows(double x) const {
  return fem::point_shape(beam_->mesh, beam_->dofs, x).displacement * basis_.vectors;
}

ModalCoordinates::Rows ModalCoordinates::rotation_row(double x) const {
  return fem::point_shape(beam_->mesh, beam_->dofs, x).rotation * basis_.vectors;
}

}  // namespace ffrf::modal
