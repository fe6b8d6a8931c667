// Compiles (tests/scene/CMakeLists.txt): "hull.mass" is a key of the scene schema.
#include "scene/scene_key.hpp"

const char* hull_mass = ffrf::scene::scene_key("hull.mass");
