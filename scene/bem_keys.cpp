// Which [bem] keys go together (see bem_keys.hpp).
#include "scene/bem_keys.hpp"

#include <fmt/format.h>

namespace ffrf::scene {

void check_bem_keys(WrittenKeys& keys, int bem_line) {
  const bool wamit = keys.written("bem.radiation_file"), capytaine = keys.written("bem.capytaine_file");
  if (!wamit && !capytaine) {
    keys.report(bem_line, "bem.radiation_file | bem.capytaine_file", "",
                "missing: [bem] needs the WAMIT .1 file (bem.radiation_file) or a Capytaine NetCDF dataset "
                "(bem.capytaine_file); give exactly one");
    return;
  }
  if (capytaine) {
    for (const char* key : {"bem.radiation_file", "bem.excitation_file", "bem.hydrostatics_file", "bem.length_scale"}) {
      if (keys.written(key)) {
        keys.report(keys.line(key), key, keys.shown(key),
                    "belongs to WAMIT files; bem.capytaine_file gives A, B and the excitation in dimensional SI units "
                    "from one dataset: remove one of the two");
      }
    }
  } else if (keys.written("bem.infinite_frequency_added_mass")) {
    keys.report(keys.line("bem.infinite_frequency_added_mass"), "bem.infinite_frequency_added_mass",
                keys.shown("bem.infinite_frequency_added_mass"),
                "belongs to bem.capytaine_file: WAMIT's .1 file holds A∞ itself (PER = 0 rows); remove it");
  }
}

}  // namespace ffrf::scene
