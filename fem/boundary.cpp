// Boundary conditions as sets of fixed nodal DOFs, and restriction/extension between full and
// free DOF vectors and matrices.
#include "fem/boundary.hpp"

#include <vector>

namespace ffrf::fem {

std::string_view to_string(Boundary boundary) {
  switch (boundary) {
    case Boundary::clamped_free: return "clamped-free";
    case Boundary::free_free: return "free-free";
    case Boundary::pinned_pinned: return "pinned-pinned";
  }
  return "?";
}

std::optional<Boundary> parse_boundary(std::string_view text) {
  for (Boundary b : {Boundary::clamped_free, Boundary::free_free, Boundary::pinned_pinned}) {
    if (text == to_string(b)) return b;
  }
  return std::nullopt;
}

std::string boundary_choices() { return "clamped-free|free-free|pinned-pinned"; }

DofMap make_dof_map(const BeamMesh& mesh, Boundary boundary) {
  const int full = mesh.full_dof_count();
  std::vector<bool> fixed(static_cast<std::size_t>(full), false);
  const int tip = mesh.element_count;
  switch (boundary) {
    case Boundary::clamped_free:
      for (NodeDof d : {NodeDof::axial, NodeDof::transverse, NodeDof::rotation}) fixed[full_dof(0, d)] = true;
      break;
    case Boundary::free_free: break;
    case Boundary::pinned_pinned:
      fixed[full_dof(0, NodeDof::axial)] = true;
      fixed[full_dof(0, NodeDof::transverse)] = true;
      fixed[full_dof(tip, NodeDof::transverse)] = true;
      break;
  }
  DofMap map;
  map.full_to_free.assign(static_cast<std::size_t>(full), -1);
  for (int i = 0; i < full; ++i) {
    if (!fixed[static_cast<std::size_t>(i)]) {
      map.full_to_free[static_cast<std::size_t>(i)] = map.free_count();
      map.free_to_full.push_back(i);
    }
  }
  return map;
}

Eigen::SparseMatrix<double> restrict_to_free(const Eigen::SparseMatrix<double>& full, const DofMap& map) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(full.nonZeros()));
  for (int col = 0; col < full.outerSize(); ++col) {
    const int free_col = map.full_to_free[static_cast<std::size_t>(col)];
    if (free_col < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(full, col); it; ++it) {
      const int free_row = map.full_to_free[static_cast<std::size_t>(it.row())];
      if (free_row >= 0) entries.emplace_back(free_row, free_col, it.value());
    }
  }
  Eigen::SparseMatrix<double> reduced(map.free_count(), map.free_count());
  reduced.setFromTriplets(entries.begin(), entries.end());
  return reduced;
}

Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& full, const DofMap& map) {
  Eigen::VectorXd reduced(map.free_count());
  for (int i = 0; i < map.free_count(); ++i) reduced(i) = full(map.free_to_full[static_cast<std::size_t>(i)]);
  return reduced;
}

Eigen::VectorXd extend_to_full(const Eigen::VectorXd& free, const DofMap& map) {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(map.full_count());
  for (int i = 0; i < map.free_count(); ++i) full(map.free_to_full[static_cast<std::size_t>(i)]) = free(i);
  return full;
}

}  // namespace ffrf::fem
