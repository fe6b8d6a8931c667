// Modal elastic coordinates (docs/theory.md §3): q_n = Φ η with Φ an M-orthonormal modal basis
// (vibration + static correction modes). Every inertia invariant, the stiffness and the unit
// geometric stiffness are projected once on Φ (dense, small); shape rows are S(x)Φ.
// Implements fem::ElasticCoordinates.
#pragma once

#include <Eigen/Dense>
#include <memory>

#include "fem/beam_model.hpp"
#include "fem/elastic_coordinates.hpp"
#include "modal/modal_basis.hpp"

namespace ffrf::modal {

class ModalCoordinates {
 public:
  using Matrix = Eigen::MatrixXd;
  using Space = fem::Space;  // the beam mesh's (fem/element_space.hpp)
  using Rows = Eigen::MatrixXd;

  ModalCoordinates(std::shared_ptr<const fem::BeamModel> beam, ModalBasis basis);

  Eigen::Index size() const { return basis_.vectors.cols(); }
  double mass() const { return beam_->invariants.mass; }
  Space::Vector first_moment() const { return beam_->invariants.first_moment; }
  Space::SecondMoment second_moment() const { return beam_->invariants.second_moment; }
  const Eigen::Matrix<double, 2, Eigen::Dynamic>& shape_integral() const { return shape_integral_; }
  const Eigen::RowVectorXd& u0_dot_shape() const { return u0_dot_shape_; }
  const Eigen::RowVectorXd& u0_cross_shape() const { return u0_cross_shape_; }
  const Matrix& mass_ff() const { return mass_ff_; }
  const Matrix& skew_ff() const { return skew_ff_; }
  const Matrix& stiffness() const { return stiffness_; }
  const Matrix& unit_geometric_stiffness() const { return unit_geometric_stiffness_; }
  Rows displacement_rows(double x) const;
  Rows rotation_row(double x) const;
  Eigen::VectorXd to_nodal(const Eigen::VectorXd& eta) const { return basis_.vectors * eta; }
  Matrix project(const Eigen::SparseMatrix<double>& nodal_matrix) const {
    return basis_.vectors.transpose() * (nodal_matrix * basis_.vectors);
  }

  const ModalBasis& basis() const { return basis_; }
  const fem::BeamModel& beam() const { return *beam_; }
  const std::shared_ptr<const fem::BeamModel>& beam_model() const { return beam_; }

 private:
  std::shared_ptr<const fem::BeamModel> beam_;
  ModalBasis basis_;
  Eigen::Matrix<double, 2, Eigen::Dynamic> shape_integral_;
  Eigen::RowVectorXd u0_dot_shape_;
  Eigen::RowVectorXd u0_cross_shape_;
  Matrix mass_ff_;
  Matrix skew_ff_;
  Matrix stiffness_;
  Matrix unit_geometric_stiffness_;
};

static_assert(fem::ElasticCoordinates<ModalCoordinates>);

}  // namespace ffrf::modal
