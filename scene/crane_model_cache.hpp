// The shared crane models of one scene (issue 12.3): each distinct model — boom kind × mesh ×
// coordinates × mode set × solver × stiffening — is built once, on its first request, and handed
// to every run and thread that asks for it; each run makes its own CraneEquations from it
// (workspace and run state, coupling/crane_system.hpp). The vibration modes come from a
// modal::ModeCache (one eigen solve per mesh). Thread-safe: concurrent requests for one model wait
// for the one build; requests for different models build in parallel. A build that throws is not
// cached (the next request tries again and throws the same error).
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include "coupling/crane_system.hpp"
#include "modal/mode_cache.hpp"
#include "scene/crane_builder.hpp"
#include "scene/scene.hpp"

namespace ffrf::scene {

class CraneModelCache {
 public:
  // Models of (a copy of) `scene`; modes from `modes` (not owned; must outlive the cache) or, when
  // null, from a mode cache of its own.
  explicit CraneModelCache(Scene scene, modal::ModeCache* modes = nullptr);
  CraneModelCache(const CraneModelCache&) = delete;
  CraneModelCache& operator=(const CraneModelCache&) = delete;

  const Scene& scene() const { return scene_; }
  modal::ModeCache& modes() { return *modes_; }

  // The model of `choice` on the scene (build_shared_crane), built on the first request. Throws
  // what build_shared_crane throws (SceneError, EigenSolverError, std::runtime_error).
  std::shared_ptr<const coupling::SharedCraneModel> model(const BoomChoice& choice);
  int models_built() const { return built_.load(); }  // successful builds so far

 private:
  // kind, elements, modes, static modes, solver, stiffening (the fields that do not apply to the
  // kind are zero).
  using Key = std::tuple<int, int, int, bool, int, int>;
  struct Entry {
    std::mutex building;
    std::shared_ptr<const coupling::SharedCraneModel> model;
  };
  Key key_of(const BoomChoice& choice) const;

  Scene scene_;
  modal::ModeCache own_modes_;
  modal::ModeCache* modes_;
  std::mutex mutex_;  // guards entries_ (not the builds)
  std::map<Key, std::shared_ptr<Entry>> entries_;
  std::atomic<int> built_{0};
};

}  // namespace ffrf::scene
