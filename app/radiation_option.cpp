// The --radiation option (see the header).
#include "app/radiation_option.hpp"

#include <fmt/format.h>

#include "app/cli_options.hpp"

namespace ffrf::app {

void add_radiation_option(CLI::App& sub, std::string& radiation) {
  sub.add_option("--radiation", radiation,
                 "Hull radiation model constant|state-space|convolution of a scene with [bem] (default: "
                 "bem.radiation_model): constant A, B at one frequency, the state-space fit of K(t), or the Cummins "
                 "convolution (the reference)");
}

void apply_radiation_option(scene::Scene& scene, const std::string& radiation) {
  if (radiation.empty()) return;
  hydro::RadiationKind kind;
  if (!hydro::parse_radiation_kind(radiation, kind)) {
    throw BadOption(fmt::format("--radiation {}: unknown radiation model; choose one of constant, state-space, convolution",
                                radiation));
  }
  if (!scene.bem) {
    throw BadOption(fmt::format("--radiation {}: the scene has no [bem] section (radiation from WAMIT files); its "
                                "[radiation] coefficients are constant",
                                radiation));
  }
  scene.bem->radiation_model = kind;
}

}  // namespace ffrf::app
