// The boom's clamped–free vibration modes, computed once per mesh and shared (issue 4: "mode
// shapes are computed once per scene and cached"). A request for k modes of a mesh returns the k
// lowest of one eigen solve that computed max(k, 12) — enough for a mode-count sweep k = 1…12 —
// and a later, larger request recomputes once with the larger count. Thread-safe, so the workers
// of a parallel sweep share one cache. One cache belongs to one scene.
#pragma once

#include <map>
#include <mutex>
#include <utility>

#include "cases/scene.hpp"
#include "modal/eigen_solver.hpp"

namespace ffrf::cases {

class ModeCache {
 public:
  // The k lowest modes (ω² ascending, M-normalized vectors on the free DOFs) of the boom with
  // `elements` elements, clamped at the root.
  modal::EigenPairs lowest_modes(const Scene& scene, int elements, int k, modal::EigenSolverKind solver);
  int eigen_solves() const;  // how many eigen solves the cache has run

 private:
  mutable std::mutex mutex_;
  std::map<std::pair<int, int>, modal::EigenPairs> modes_;  // (elements, solver) → modes
  int eigen_solves_ = 0;
};

}  // namespace ffrf::cases
