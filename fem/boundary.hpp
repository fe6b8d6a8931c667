// Boundary conditions of the beam and the map between full nodal DOFs and free DOFs.
// clamped-free is the floating-frame reference condition (root clamped to the frame);
// free-free keeps all DOFs; pinned-pinned fixes u, v at the root and v at the tip.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fem/mesh.hpp"

namespace ffrf::fem {

enum class Boundary { clamped_free, free_free, pinned_pinned };

std::string_view to_string(Boundary boundary);                  // "clamped-free", ...
std::optional<Boundary> parse_boundary(std::string_view text);  // nullopt when unknown
std::string boundary_choices();                                 // "clamped-free|free-free|pinned-pinned"

// Free DOFs in ascending full-DOF order; free_index[full] = -1 when the DOF is fixed.
struct DofMap {
  std::vector<int> free_to_full;
  std::vector<int> full_to_free;
  int free_count() const { return static_cast<int>(free_to_full.size()); }
  int full_count() const { return static_cast<int>(full_to_free.size()); }
};

DofMap make_dof_map(const BeamMesh& mesh, Boundary boundary);

// Restrict a full-DOF matrix / vector to the free DOFs, and extend free values to full (zeros at
// fixed DOFs).
Eigen::SparseMatrix<double> restrict_to_free(const Eigen::SparseMatrix<double>& full, const DofMap& map);
Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& full, const DofMap& map);
Eigen::VectorXd extend_to_full(const Eigen::VectorXd& free, const DofMap& map);

}  // namespace ffrf::fem
