// Nodal elastic coordinates: shape rows straight from the FE shape functions.
#include "nodal/nodal_coordinates.hpp"

#include <stdexcept>

#include "fem/point_shape.hpp"

namespace ffrf::nodal {

NodalCoordinates::NodalCoordinates(std::shared_ptr<const fem::BeamModel> beam) : beam_(std::move(beam)) {
  if (!beam_) throw std::invalid_argument("NodalCoordinates needs a beam model");
}

NodalCoordinates::Rows NodalCoordinates::displacement_rows(double x) const {
  return fem::point_shape(beam_->mesh, beam_->dofs, x).displacement;
}

NodalCoordinates::Rows NodalCoordinates::rotation_row(double x) const {
  return fem::point_shape(beam_->mesh, beam_->dofs, x).rotation;
}

}  // namespace ffrf::nodal
