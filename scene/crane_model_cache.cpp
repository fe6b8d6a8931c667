// Shared crane models built once per distinct choice (see header).
#include "scene/crane_model_cache.hpp"

namespace ffrf::scene {

CraneModelCache::CraneModelCache(Scene scene, modal::ModeCache* modes)
    : scene_(std::move(scene)), modes_(modes != nullptr ? modes : &own_modes_) {}

CraneModelCache::Key CraneModelCache::key_of(const BoomChoice& choice) const {
  const int stiffening = static_cast<int>(choice.stiffening.value_or(scene_.boom.stiffening));
  switch (choice.kind) {
    case BoomKind::rigid: return {static_cast<int>(choice.kind), 0, 0, false, 0, stiffening};
    case BoomKind::nodal: return {static_cast<int>(choice.kind), choice.elements, 0, false, 0, stiffening};
    case BoomKind::modal:
      return {static_cast<int>(choice.kind), choice.elements, choice.modes, choice.static_modes, static_cast<int>(choice.solver),
              stiffening};
  }
  return {};
}

std::shared_ptr<const coupling::SharedCraneModel> CraneModelCache::model(const BoomChoice& choice) {
  std::shared_ptr<Entry> entry;
  {
    const std::lock_guard lock(mutex_);
    std::shared_ptr<Entry>& slot = entries_[key_of(choice)];
    if (!slot) slot = std::make_shared<Entry>();
    entry = slot;
  }
  const std::lock_guard building(entry->building);  // one build per model; other models build meanwhile
  if (!entry->model) {
    entry->model = build_shared_crane(scene_, choice, modes_);
    ++built_;
  }
  return entry->model;
}

}  // namespace ffrf::scene
