// Shared crane models built once per distinct choice (see header).
#include "scene/crane_model_cache.hpp"

#include "scene/bem_hull_model.hpp"

namespace ffrf::scene {

CraneModelCache::CraneModelCache(Scene scene, modal::ModeCache* modes)
    : scene_(std::move(scene)), modes_(modes != nullptr ? modes : &own_modes_) {}

std::optional<hydro::RadiationKind> CraneModelCache::effective(std::optional<hydro::RadiationKind> radiation) const {
  if (radiation) return radiation;
  if (scene_.bem) return scene_.bem->radiation_model;
  return std::nullopt;
}

const Scene& CraneModelCache::scene(std::optional<hydro::RadiationKind> radiation) {
  if (!radiation || (scene_.bem && scene_.bem->radiation_model == *radiation)) return scene_;
  const std::lock_guard lock(mutex_);
  const auto found = scenes_.find(static_cast<int>(*radiation));
  if (found != scenes_.end()) return found->second;
  return scenes_.emplace(static_cast<int>(*radiation), with_radiation(scene_, *radiation)).first->second;
}

CraneModelCache::Key CraneModelCache::key_of(const BoomChoice& choice, std::optional<hydro::RadiationKind> radiation) const {
  const int stiffening = static_cast<int>(choice.stiffening.value_or(scene_.boom.stiffening));
  const std::optional<hydro::RadiationKind> kind = effective(radiation);
  const int hull = kind ? static_cast<int>(*kind) : -1;
  switch (choice.kind) {
    case BoomKind::rigid: return {static_cast<int>(choice.kind), 0, 0, false, 0, stiffening, hull};
    case BoomKind::nodal: return {static_cast<int>(choice.kind), choice.elements, 0, false, 0, stiffening, hull};
    case BoomKind::modal:
      return {static_cast<int>(choice.kind), choice.elements, choice.modes, choice.static_modes,
              static_cast<int>(choice.solver) + 16 * static_cast<int>(choice.mode_set), stiffening, hull};
  }
  return {};
}

CraneModelCache::Entry& CraneModelCache::built_entry(const BoomChoice& choice, std::optional<hydro::RadiationKind> radiation,
                                                     std::unique_lock<std::mutex>& lock) {
  const Scene& modelled = scene(radiation);  // throws SceneError before anything is cached
  std::shared_ptr<Entry> entry;
  {
    const std::lock_guard guard(mutex_);
    std::shared_ptr<Entry>& slot = entries_[key_of(choice, radiation)];
    if (!slot) slot = std::make_shared<Entry>();
    entry = slot;  // entries are never erased: the reference outlives this scope
  }
  lock = std::unique_lock(entry->building);  // one build per model; other models build meanwhile
  if (!entry->model) {
    entry->model = build_crane_model(modelled, choice, modes_);
    ++built_;
  }
  return *entry;
}

std::shared_ptr<const multibody::CraneModel> CraneModelCache::model(const BoomChoice& choice,
                                                                         std::optional<hydro::RadiationKind> radiation) {
  std::unique_lock<std::mutex> lock;
  return built_entry(choice, radiation, lock).model;
}

multibody::StaticEquilibrium CraneModelCache::static_equilibrium(const BoomChoice& choice,
                                                                std::optional<hydro::RadiationKind> radiation) {
  std::unique_lock<std::mutex> lock;
  Entry& entry = built_entry(choice, radiation, lock);
  if (!entry.statics) {
    const std::unique_ptr<multibody::CraneEquations> equations = entry.model->equations();
    entry.statics = multibody::solve_static_equilibrium(*equations, equations->initial_guess());
    ++solved_;
  }
  return *entry.statics;
}

}  // namespace ffrf::scene
