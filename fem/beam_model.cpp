// Assembly of the constant nodal-space beam model.
#include "fem/beam_model.hpp"

#include "fem/assembly.hpp"

namespace ffrf::fem {

BeamModel make_beam_model(const BeamMesh& mesh, Boundary boundary) {
  validate(mesh);
  BeamModel model{mesh, boundary, make_dof_map(mesh, boundary), {}, {}, {}, {}};
  model.invariants = nodal_invariants(mesh, model.dofs);
  model.mass = model.invariants.mass_ff;
  model.stiffness = restrict_to_free(assemble_stiffness(mesh), model.dofs);
  model.unit_geometric_stiffness = restrict_to_free(assemble_geometric_stiffness(mesh, 1.0), model.dofs);
  return model;
}

}  // namespace ffrf::fem
