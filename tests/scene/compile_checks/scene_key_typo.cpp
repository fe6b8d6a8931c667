// Does not compile on purpose (tests/scene/CMakeLists.txt): "hull.mas" is not a key of the scene
// schema, and scene_key() checks its argument at compile time.
#include "scene/scene_key.hpp"

const char* misspelt = ffrf::scene::scene_key("hull.mas");
