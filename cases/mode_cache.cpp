// Cached clamped–free vibration modes of the boom (see header).
#include "cases/mode_cache.hpp"

#include <algorithm>

#include "cases/crane_builder.hpp"

namespace ffrf::cases {

modal::EigenPairs ModeCache::lowest_modes(const Scene& scene, int elements, int k, modal::EigenSolverKind solver) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const auto key = std::make_pair(elements, static_cast<int>(solver));
  auto found = modes_.find(key);
  if (found == modes_.end() || found->second.eigenvalues.size() < k) {
    auto beam = boom_beam(scene, elements);
    modal::EigenRequest request;
    request.nev = std::min(std::max(k, 12), beam->dofs.free_count() - 1);
    request.nev = std::max(request.nev, k);  // an impossible k is reported by the solver's own check
    found = modes_.insert_or_assign(key, modal::solve_generalized(beam->stiffness, beam->mass, request, solver)).first;
    ++eigen_solves_;
  }
  modal::EigenPairs lowest;
  lowest.eigenvalues = found->second.eigenvalues.head(k);
  lowest.eigenvectors = found->second.eigenvectors.leftCols(k);
  lowest.stats = found->second.stats;
  return lowest;
}

int ModeCache::eigen_solves() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return eigen_solves_;
}

}  // namespace ffrf::cases
