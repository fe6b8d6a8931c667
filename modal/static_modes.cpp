// Static correction modes ψ = K⁻¹ f for unit loads, K factored once by a sparse LDLᵀ.
#include "modal/static_modes.hpp"

#include <Eigen/SparseCholesky>
#include <stdexcept>

#include "fem/point_shape.hpp"

namespace ffrf::modal {

std::string_view to_string(UnitLoadKind kind) {
  switch (kind) {
    case UnitLoadKind::axial_force: return "axial force";
    case UnitLoadKind::transverse_force: return "transverse force";
    case UnitLoadKind::moment: return "moment";
    case UnitLoadKind::distributed_axial: return "uniform axial load";
    case UnitLoadKind::distributed_transverse: return "uniform transverse load";
  }
  return "?";
}

std::vector<UnitLoad> tip_unit_loads(const fem::BeamMesh& mesh) {
  return {{mesh.length, UnitLoadKind::axial_force},
          {mesh.length, UnitLoadKind::transverse_force},
          {mesh.length, UnitLoadKind::moment}};
}

std::vector<UnitLoad> tip_and_body_unit_loads(const fem::BeamMesh& mesh) {
  std::vector<UnitLoad> loads = tip_unit_loads(mesh);
  loads.push_back({0.0, UnitLoadKind::distributed_axial});
  loads.push_back({0.0, UnitLoadKind::distributed_transverse});
  return loads;
}

Eigen::MatrixXd static_modes(const fem::BeamMesh& mesh, const fem::DofMap& dofs,
                             const Eigen::SparseMatrix<double>& stiffness, const std::vector<UnitLoad>& loads) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(stiffness);
  if (factor.info() != Eigen::Success || factor.vectorD().minCoeff() <= 0.0) {
    throw std::invalid_argument(
        "static correction modes need a stiffness that is positive definite on the free DOFs "
        "(a clamped reference condition); this boundary condition leaves rigid-body motion free");
  }
  Eigen::MatrixXd modes(dofs.free_count(), static_cast<Eigen::Index>(loads.size()));
  for (std::size_t j = 0; j < loads.size(); ++j) {
    const UnitLoad& load = loads[j];
    Eigen::VectorXd nodal_load;
    if (load.kind == UnitLoadKind::distributed_axial || load.kind == UnitLoadKind::distributed_transverse) {
      nodal_load = fem::distributed_load(mesh, dofs, Eigen::Vector2d(load.kind == UnitLoadKind::distributed_axial ? 1.0 : 0.0,
                                                                     load.kind == UnitLoadKind::distributed_transverse ? 1.0 : 0.0));
    } else {
      const Eigen::Vector2d force(load.kind == UnitLoadKind::axial_force ? 1.0 : 0.0,
                                  load.kind == UnitLoadKind::transverse_force ? 1.0 : 0.0);
      nodal_load = fem::point_load(mesh, dofs, load.position, force, load.kind == UnitLoadKind::moment ? 1.0 : 0.0);
    }
    modes.col(static_cast<Eigen::Index>(j)) = factor.solve(nodal_load);
  }
  return modes;
}

}  // namespace ffrf::modal
