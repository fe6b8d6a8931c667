// The clamped (or otherwise held) beam's vibration modes, computed once per mesh and shared (a
// study reuses a scene's mode shapes rather than solve them again, and a sweep solves each mesh's
// eigenproblem once). A request for k modes returns the k lowest of one eigen solve of
// min(12·⌈k/12⌉, n − 1) modes: k = 1…12 — a whole mode-count sweep — share one solve, and which
// solve serves k never depends on the order of requests, so a parallel sweep and a single run get
// bit-identical bases. Thread-safe: the workers of a sweep share one cache. The key is the whole
// mesh (length, section, element count), the boundary condition and the solver, so one cache can
// serve scenes that share a boom.
#pragma once

#include <map>
#include <mutex>
#include <tuple>

#include "fem/boundary.hpp"
#include "fem/mesh.hpp"
#include "modal/eigen_solver.hpp"

namespace ffrf::modal {

// Shift for the shift-invert solvers: 0 when the boundary condition suppresses the rigid modes;
// for free–free −EI/(ρA L⁴) (the ω² of "βL = 1"), which makes K − σM positive definite while the
// rigid modes (ω² = 0) stay ~500 times nearer σ than the first elastic mode (βL = 4.73).
double rigid_mode_shift(const fem::BeamMesh& mesh, fem::Boundary boundary);

class ModeCache {
 public:
  // The k lowest modes (ω² ascending, M-normalized vectors on the free DOFs) of the mesh under the
  // boundary condition (shift: rigid_mode_shift). Throws EigenSolverError.
  EigenPairs lowest_modes(const fem::BeamMesh& mesh, fem::Boundary boundary, int k, EigenSolverKind solver);
  int eigen_solves() const;  // how many eigen solves the cache has run

  // How many modes the solve that serves a request for k modes computes (n free DOFs).
  static int solve_count(int k, int free_dofs);

 private:
  using Key = std::tuple<double, double, double, double, double, int, int, int, int>;  // mesh, boundary, solver, count
  mutable std::mutex mutex_;
  std::map<Key, EigenPairs> modes_;
  int eigen_solves_ = 0;
};

}  // namespace ffrf::modal
