// Shape rows of a material point (paper eq. 4 on the element holding x) and the nodal loads of
// point and distributed loads by virtual work (paper eq. 13).
#include "fem/point_shape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/beam_element.hpp"

namespace ffrf::fem {
namespace {

struct ElementPoint {
  int element;
  double xi;
};

ElementPoint locate(const BeamMesh& mesh, double x) {
  if (!(x >= 0.0 && x <= mesh.length)) {
    throw std::out_of_range("point x = " + std::to_string(x) + " m lies outside the beam [0, " +
                            std::to_string(mesh.length) + "] m");
  }
  const double l = mesh.element_length();
  const int element = std::min(static_cast<int>(std::floor(x / l)), mesh.element_count - 1);
  return {element, (x - element * l) / l};
}

Eigen::SparseMatrix<double, Eigen::RowMajor> scatter_rows(const Eigen::MatrixXd& local, int element, const DofMap& dofs) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int r = 0; r < local.rows(); ++r) {
    for (int i = 0; i < 6; ++i) {
      const int fi = dofs.full_to_free[static_cast<std::size_t>(node_dofs * element + i)];
      if (fi >= 0 && local(r, i) != 0.0) entries.emplace_back(r, fi, local(r, i));
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> rows(local.rows(), dofs.free_count());
  rows.setFromTriplets(entries.begin(), entries.end());
  return rows;
}

}  // namespace

PointShape point_shape(const BeamMesh& mesh, const DofMap& dofs, double x) {
  const ElementPoint p = locate(mesh, x);
  const double l = mesh.element_length();
  PointShape shape;
  shape.displacement = scatter_rows(element_shape(p.xi, l), p.element, dofs);
  shape.rotation = scatter_rows(element_shape_slope(p.xi, l).row(1), p.element, dofs);
  return shape;
}

Eigen::VectorXd point_load(const BeamMesh& mesh, const DofMap& dofs, double x, const Eigen::Vector2d& force,
                           double moment) {
  const PointShape shape = point_shape(mesh, dofs, x);
  Eigen::VectorXd load = shape.displacement.transpose() * force;
  load += shape.rotation.transpose() * moment;
  return load;
}

Eigen::VectorXd distributed_load(const BeamMesh& mesh, const DofMap& dofs, const Eigen::Vector2d& load_per_length) {
  // ∫ Sᵀ w dx per element: axial l/2 per node; transverse (l/2, l²/12, l/2, −l²/12).
  const double l = mesh.element_length();
  Eigen::Matrix<double, element_dofs, 1> local;
  local << 0.5 * l * load_per_length(0), 0.5 * l * load_per_length(1), l * l / 12.0 * load_per_length(1),
      0.5 * l * load_per_length(0), 0.5 * l * load_per_length(1), -l * l / 12.0 * load_per_length(1);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(dofs.free_count());
  for (int e = 0; e < mesh.element_count; ++e) {
    for (int i = 0; i < 6; ++i) {
      const int fi = dofs.full_to_free[static_cast<std::size_t>(node_dofs * e + i)];
      if (fi >= 0) load(fi) += local(i);
    }
  }
  return load;
}

}  // namespace ffrf::fem
