// `ffrf check SCENE [--set KEY=VALUE]`: validates a scene file (with the values set beside it) against the scene schema and prints every problem
// as `FILE:LINE: key = value: message (valid range ...)` (exit 2), or a one-line summary (exit 0).
#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "scene/irregular_sea.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::app {
namespace {

std::string summary(const scene::Scene& scene) {
  const fem::BeamMesh& mesh = scene.boom.mesh;
  std::string text = fmt::format("boom {:g} m, {:g} t, {} elements", mesh.length, mesh.total_mass() / 1e3,
                                 mesh.element_count);
  if (scene.hub) {
    const scene::Hub& hub = *scene.hub;
    const char* motion = hub.motion == scene::HubMotion::spin_up         ? "spin-up"
                         : hub.motion == scene::HubMotion::constant_spin ? "constant spin"
                                                                         : "fixed";
    text = fmt::format("hub: {}, radius {:g} m, {} to {:g} rad/s{}", text, hub.radius, motion, hub.spin_rate,
                       scene.cargo ? fmt::format(", cargo {:g} t on a {:g} m wire", scene.cargo->mass / 1e3,
                                                 scene.wire->unstretched_length)
                                   : std::string());
    return text + fmt::format(", stiffening {}", scene::to_string(scene.boom.stiffening));
  }
  if (!scene.is_crane()) return fmt::format("single beam: {}, {}", text, fem::to_string(scene.boom.boundary));
  text = fmt::format("crane: hull {:g} t, {} at {:g} deg, cargo {:g} t, wire {:g} m", scene.hull->mass / 1e3, text,
                     scene.boom.mount->angle * 180.0 / 3.14159265358979323846, scene.cargo->mass / 1e3,
                     scene.wire->unstretched_length);
  if (scene.boom.mount->pinned && scene.luffing) {
    text += fmt::format(", heel pinned on {} luffing wire{} of {:g} N/m", scene.luffing->wires, scene.luffing->wires == 1 ? "" : "s",
                        scene.luffing->stiffness);
    if (scene.luffing->parts > 1) text += fmt::format(" per part, {} parts of line", scene.luffing->parts);
    if (scene.a_frame && scene.backstay) {
      text += fmt::format(", A-frame {:g} t on its deck pin with {} backstay{} of {:g} N/m", scene.a_frame->mass / 1e3,
                          scene.backstay->wires, scene.backstay->wires == 1 ? "" : "s", scene.backstay->stiffness);
    }
  }
  if (scene.wave) {
    text += fmt::format(", wave {:g} m / {:g} s {}", scene.wave->height, scene.wave->period,
                        scene.wave->direction == hydro::WaveHeading::following ? "following" : "head");
  } else if (scene.sea) {
    const scene::IrregularSea& sea = *scene.sea;
    const char* heading = sea.heading == hydro::WaveHeading::following ? "following" : "head";
    if (sea.spectrum == scene::SeaSpectrum::components) {
      text += fmt::format(", {} wave components {}", sea.component_frequencies.size(), heading);
    } else {
      const hydro::WaveComponents components = scene::sea_components(scene);
      text += fmt::format(", {} sea Hs {:g} m / Tp {:g} s {}, seed {}, {} components (repeats after {:.6g} s)",
                          sea.spectrum == scene::SeaSpectrum::jonswap ? fmt::format("JONSWAP (γ {:g})", sea.peak_enhancement)
                                                                      : std::string("Pierson-Moskowitz"),
                          sea.significant_height, sea.peak_period, heading, sea.seed, components.size(),
                          components.repeat_period());
    }
  } else {
    text += ", calm water";
  }
  return text;
}

}  // namespace

Command add_check_command(CLI::App& parent) {
  auto scene_path = std::make_shared<std::string>();
  auto set = std::make_shared<std::vector<std::string>>();
  CLI::App* sub = parent.add_subcommand("check", "Validate a scene file and list every problem");
  sub->add_option("scene", *scene_path, "Scene file (TOML)")->required();
  add_set_option(*sub, *set);
  return {sub, [scene_path, set] {
            try {
              const scene::Scene scene = scene::load_scene(*scene_path, scene_overrides(*set));
              for (const std::string& warning : scene.warnings) fmt::print(stderr, "warning: {}\n", warning);
              fmt::print("{}: OK ({}{})\n", *scene_path, scene.name.empty() ? "" : scene.name + ": ", summary(scene));
              return exit_ok;
            } catch (const scene::SceneError& error) {
              for (const scene::SceneProblem& problem : error.problems()) {
                fmt::print(stderr, "{}\n", scene::format_problem(problem));
              }
              fmt::print(stderr, "{}: {} problem{}\n", *scene_path, error.problems().size(),
                         error.problems().size() == 1 ? "" : "s");
              return exit_bad_input;
            }
          }};
}

}  // namespace ffrf::app
