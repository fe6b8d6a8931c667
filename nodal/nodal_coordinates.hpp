// Nodal elastic coordinates (docs/theory.md §2): η = q_n, Φ = I — all free FE degrees of freedom of
// the beam, kept sparse and banded (the paper's choice, Table 1). Implements
// fem::ElasticCoordinates by passing the nodal-space beam model through unchanged.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>

#include "fem/beam_model.hpp"
#include "fem/elastic_coordinates.hpp"

namespace ffrf::nodal {

class NodalCoordinates {
 public:
  using Matrix = Eigen::SparseMatrix<double>;
  using Space = fem::Space;  // the beam mesh's (fem/element_space.hpp)
  using Rows = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  explicit NodalCoordinates(std::shared_ptr<const fem::BeamModel> beam);

  Eigen::Index size() const { return beam_->dofs.free_count(); }
  double mass() const { return beam_->invariants.mass; }
  Space::Vector first_moment() const { return beam_->invariants.first_moment; }
  Space::SecondMoment second_moment() const { return beam_->invariants.second_moment; }
  const Eigen::Matrix<double, 2, Eigen::Dynamic>& shape_integral() const { return beam_->invariants.shape_integral; }
  const Eigen::RowVectorXd& u0_dot_shape() const { return beam_->invariants.u0_dot_shape; }
  const Eigen::RowVectorXd& u0_cross_shape() const { return beam_->invariants.u0_cross_shape; }
  const Matrix& mass_ff() const { return beam_->invariants.mass_ff; }
  const Matrix& skew_ff() const { return beam_->invariants.skew_ff; }
  const Matrix& stiffness() const { return beam_->stiffness; }
  const Matrix& unit_geometric_stiffness() const { return beam_->unit_geometric_stiffness; }
  Rows displacement_rows(double x) const;
  Rows rotation_row(double x) const;
  Eigen::VectorXd to_nodal(const Eigen::VectorXd& eta) const { return eta; }
  Matrix project(const Eigen::SparseMatrix<double>& nodal_matrix) const { return nodal_matrix; }

  const fem::BeamModel& beam() const { return *beam_; }
  const std::shared_ptr<const fem::BeamModel>& beam_model() const { return beam_; }

 private:
  std::shared_ptr<const fem::BeamModel> beam_;
};

static_assert(fem::ElasticCoordinates<NodalCoordinates>);

}  // namespace ffrf::nodal
