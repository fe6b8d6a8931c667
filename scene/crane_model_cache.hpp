// The shared crane models of one scene, built once and shared by threads: each distinct model — boom kind × mesh ×
// coordinates × mode set × solver × stiffening × the [bem] hull's radiation model — is built once,
// on its first request, and handed to every run and thread that asks for it; each run makes its own
// CraneEquations from it (workspace and run state, multibody/crane_model.hpp). The vibration modes
// come from a modal::ModeCache (one eigen solve per mesh). A model's static equilibrium in calm water
// (multibody/crane_statics.hpp) depends on the model alone — KINSOL from the rest-pose guess at
// its fixed tolerance, a deterministic solve — so it is solved once per model too and handed out as
// a copy. Thread-safe: concurrent requests for one model wait for the one build (or solve); requests
// for different models build in parallel. A build or solve that throws is not cached (the next
// request tries again and throws the same error).
#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <tuple>

#include "multibody/crane_model.hpp"
#include "multibody/crane_statics.hpp"
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

  // The scene as given (its own radiation model).
  const Scene& scene() const { return scene_; }
  // The scene with `radiation` as its [bem] radiation model (with_radiation, scene/bem_hull_model.hpp);
  // empty or the scene's own: the scene. Throws SceneError when radiation is given and the scene has
  // no [bem]. The reference stays valid as long as the cache.
  const Scene& scene(std::optional<hydro::RadiationKind> radiation);
  modal::ModeCache& modes() { return *modes_; }

  // The model of `choice` on scene(radiation) (build_crane_model), built on the first request.
  // Throws what build_crane_model throws (SceneError, EigenSolverError, std::runtime_error).
  std::shared_ptr<const multibody::CraneModel> model(const BoomChoice& choice,
                                                          std::optional<hydro::RadiationKind> radiation = std::nullopt);
  // The static equilibrium of that model (solve_static_equilibrium from its initial guess), solved on
  // the first request. Throws what model() throws and solve::SolverFailure.
  multibody::StaticEquilibrium static_equilibrium(const BoomChoice& choice,
                                                 std::optional<hydro::RadiationKind> radiation = std::nullopt);
  int models_built() const { return built_.load(); }          // successful builds so far
  int equilibria_solved() const { return solved_.load(); }   // successful static solves so far

 private:
  // kind, elements, modes, static modes, solver, stiffening (the fields that do not apply to the
  // kind are zero), radiation model (−1: the scene has no [bem]).
  using Key = std::tuple<int, int, int, bool, int, int, int>;
  struct Entry {
    std::mutex building;
    std::shared_ptr<const multibody::CraneModel> model;
    std::optional<multibody::StaticEquilibrium> statics;
  };
  std::optional<hydro::RadiationKind> effective(std::optional<hydro::RadiationKind> radiation) const;
  Key key_of(const BoomChoice& choice, std::optional<hydro::RadiationKind> radiation) const;
  // The entry of the model, built (its `building` mutex held by `lock`).
  Entry& built_entry(const BoomChoice& choice, std::optional<hydro::RadiationKind> radiation, std::unique_lock<std::mutex>& lock);

  Scene scene_;
  modal::ModeCache own_modes_;
  modal::ModeCache* modes_;
  std::mutex mutex_;  // guards entries_ and scenes_ (not the builds)
  std::map<Key, std::shared_ptr<Entry>> entries_;
  std::map<int, Scene> scenes_;  // scene_ with another radiation model, by kind
  std::atomic<int> built_{0}, solved_{0};
};

}  // namespace ffrf::scene
