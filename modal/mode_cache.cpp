// Cached vibration modes of a beam mesh (see header).
#include "modal/mode_cache.hpp"

#include <algorithm>

#include "fem/analytic_beam.hpp"
#include "fem/beam_model.hpp"
#include "fem/boundary.hpp"

namespace ffrf::modal {

double rigid_mode_shift(const fem::BeamMesh& mesh, fem::Boundary boundary) {
  if (fem::rigid_mode_count(boundary) == 0) return 0.0;
  const fem::BeamSection& s = mesh.section;
  return -s.bending_rigidity() / (s.mass_per_length * mesh.length * mesh.length * mesh.length * mesh.length);
}

int ModeCache::solve_count(int k, int free_dofs) {
  constexpr int block = 12;  // a mode-count sweep k = 1…12 in one solve
  const int wanted = block * ((std::max(k, 1) + block - 1) / block);
  // An impossible k (k ≥ n) is left to the solver's own check, which names the valid range.
  return std::max(std::min(wanted, free_dofs - 1), k);
}

EigenPairs ModeCache::lowest_modes(const fem::BeamMesh& mesh, fem::Boundary boundary, int k, EigenSolverKind solver) {
  const int count = solve_count(k, fem::make_dof_map(mesh, boundary).free_count());
  const fem::BeamSection& s = mesh.section;
  const Key key{mesh.length,         s.youngs_modulus,          s.area, s.second_moment, s.mass_per_length,
                mesh.element_count, static_cast<int>(boundary), static_cast<int>(solver), count};
  const std::lock_guard<std::mutex> lock(mutex_);
  auto found = modes_.find(key);
  if (found == modes_.end()) {
    const fem::BeamModel beam = fem::make_beam_model(mesh, boundary);
    EigenRequest request;
    request.nev = count;
    request.sigma = rigid_mode_shift(mesh, boundary);
    found = modes_.emplace(key, solve_generalized(beam.stiffness, beam.mass, request, solver)).first;
    ++eigen_solves_;
  }
  EigenPairs lowest;
  lowest.eigenvalues = found->second.eigenvalues.head(k);
  lowest.eigenvectors = found->second.eigenvectors.leftCols(k);
  lowest.stats = found->second.stats;
  return lowest;
}

int ModeCache::eigen_solves() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return eigen_solves_;
}

}  // namespace ffrf::modal
