// A uniform mesh of N two-node frame elements along the beam axis x in [0, L] (the boom frame's
// x axis, root at x = 0). Node i sits at x = i L / N and carries the DOFs (u, v, phi): axial,
// transverse and small rotation (docs/architecture.md, "Conventions"), stored at full-DOF index 3 i + {0, 1, 2}.
#pragma once

#include "fem/element_space.hpp"
#include "fem/section.hpp"

namespace ffrf::fem {

enum class NodeDof : int { axial = 0, transverse = 1, rotation = 2 };

struct BeamMesh {
  double length;      // L [m]
  int element_count;  // N
  BeamSection section;

  int node_count() const { return element_count + 1; }
  int full_dof_count() const { return node_dofs * node_count(); }
  double element_length() const { return length / element_count; }
  double node_position(int node) const { return length * node / element_count; }
  double total_mass() const { return section.mass_per_length * length; }
};

// The free DOFs of a mesh of `element_count` elements clamped at its root (the root node's DOFs fixed).
inline int clamped_free_dof_count(int element_count) { return node_dofs * element_count; }

// Full-DOF index of one DOF of one node.
inline int full_dof(int node, NodeDof dof) { return node_dofs * node + static_cast<int>(dof); }

// Throws std::invalid_argument naming the offending quantity when the mesh or section is not
// physical (non-positive or non-finite length, N < 1, E, A, I or mass per length).
void validate(const BeamMesh& mesh);

}  // namespace ffrf::fem
