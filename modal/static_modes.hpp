// Static correction modes: the static deflection shapes ψ = K⁻¹ f of the beam (clamped-free) under
// unit loads at chosen points (default: the three tip loads — axial force, transverse force and
// moment at x = L). They carry the quasi-static response to the loads that a truncated set of
// vibration modes misses (Craig 1968; Dickens & Wilson's mode-acceleration idea).
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <string_view>
#include <vector>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"

namespace ffrf::modal {

// Point loads act at `position`; distributed loads are uniform over the whole beam (per metre).
enum class UnitLoadKind { axial_force, transverse_force, moment, distributed_axial, distributed_transverse };
std::string_view to_string(UnitLoadKind kind);

struct UnitLoad {
  double position;  // x along the beam [m], 0 < x <= L (ignored for distributed loads)
  UnitLoadKind kind;
};

std::vector<UnitLoad> tip_unit_loads(const fem::BeamMesh& mesh);  // axial, transverse, moment at L
// The loads a floating-frame boom feels quasi-statically: the three tip loads (wire) and the
// uniform axial and transverse loads (gravity and the frame's translational acceleration).
std::vector<UnitLoad> tip_and_body_unit_loads(const fem::BeamMesh& mesh);

// Raw static modes (columns, free DOFs): K ψ_j = f_j for each unit load. K must be nonsingular
// on the free DOFs (a clamped reference condition); throws std::invalid_argument otherwise.
Eigen::MatrixXd static_modes(const fem::BeamMesh& mesh, const fem::DofMap& dofs,
                             const Eigen::SparseMatrix<double>& stiffness, const std::vector<UnitLoad>& loads);

}  // namespace ffrf::modal
