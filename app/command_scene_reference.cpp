// `ffrf scene-reference`: prints the Markdown reference of every scene key, generated from the
// scene schema (docs/scenes.md is this output).
#include <fmt/format.h>

#include "app/commands.hpp"
#include "scene/scene_schema.hpp"

namespace ffrf::app {

Command add_scene_reference_command(CLI::App& parent) {
  CLI::App* sub = parent.add_subcommand(
      "scene-reference", "Print the Markdown reference of all scene keys (the source of docs/scenes.md)");
  return {sub, [] {
            fmt::print("{}", scene::scene_reference_markdown());
            return exit_ok;
          }};
}

}  // namespace ffrf::app
