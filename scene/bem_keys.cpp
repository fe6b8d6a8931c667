// Which [bem] keys go together (see bem_keys.hpp).
#include "scene/bem_keys.hpp"

#include "scene/scene_key.hpp"

#include <fmt/format.h>

namespace ffrf::scene {

void check_bem_keys(WrittenKeys& keys, int bem_line) {
  const bool wamit = keys.written(scene_key("bem.radiation_file")), capytaine = keys.written(scene_key("bem.capytaine_file"));
  if (!wamit && !capytaine) {
    keys.report(bem_line, "bem.radiation_file | bem.capytaine_file", "",
                "missing: [bem] needs the WAMIT .1 file (bem.radiation_file) or a Capytaine NetCDF dataset "
                "(bem.capytaine_file); give exactly one");
    return;
  }
  if (capytaine) {
    for (const char* key : {scene_key("bem.radiation_file"), scene_key("bem.excitation_file"), scene_key("bem.hydrostatics_file"), scene_key("bem.length_scale")}) {
      if (keys.written(key)) {
        keys.report(keys.line(key), key, keys.shown(key),
                    "belongs to WAMIT files; bem.capytaine_file gives A, B and the excitation in dimensional SI units "
                    "from one dataset: remove one of the two");
      }
    }
  } else if (keys.written(scene_key("bem.infinite_frequency_added_mass"))) {
    keys.report(keys.line(scene_key("bem.infinite_frequency_added_mass")), scene_key("bem.infinite_frequency_added_mass"),
                keys.shown(scene_key("bem.infinite_frequency_added_mass")),
                "belongs to bem.capytaine_file: WAMIT's .1 file holds A∞ itself (PER = 0 rows); remove it");
  }
}

}  // namespace ffrf::scene
