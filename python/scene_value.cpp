// Scenes as values (see bindings.hpp): a scene file's text read once, and each value made from it
// with the values given beside it, through the loader's one path (scene/scene_loader.hpp), so that
// `with_values` checks the whole scene again exactly as `ffrf check --set` does.
#include "python/bindings.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::python {
namespace {

SceneValue make_scene(const std::string& path, const std::string& text,
                      const std::vector<std::pair<std::string, std::string>>& values, const std::string& origin) {
  SceneValue value{path, text, {{}, origin}, {}};
  for (const auto& [key, given] : values) value.overrides.values.push_back({key, given});
  value.scene = scene::load_scene_text(value.text, value.path, value.overrides);
  return value;
}

py::dict scene_facts(const SceneValue& value) {
  const scene::Scene& s = value.scene;
  const char* kind = s.is_crane() ? "crane" : s.hub ? "hub" : "beam";
  return py::dict(py::arg("path") = value.path, py::arg("name") = s.name, py::arg("description") = s.description,
                  py::arg("kind") = kind, py::arg("has_cargo") = s.has_cargo(),
                  py::arg("pinned") = s.boom.mount && s.boom.mount->pinned, py::arg("bem") = s.bem.has_value(),
                  py::arg("irregular_sea") = s.sea.has_value(), py::arg("elements") = s.boom.mesh.element_count,
                  py::arg("duration") = s.simulation.duration, py::arg("output_interval") = s.simulation.output_interval,
                  py::arg("warnings") = s.warnings, py::arg("overrides") = s.overrides);
}

}  // namespace

void bind_scene(py::module_& module) {
  py::class_<SceneValue>(module, "SceneValue", "A scene and its source (use ffrf.load_scene)");
  module.def("read_scene_file", &scene::read_scene_file, py::arg("path"),
             "The text of a scene file (refused as ffrf check refuses it)");
  module.def("make_scene", &make_scene, py::arg("path"), py::arg("text"), py::arg("values"), py::arg("origin"),
             "The scene of a file's text with values given beside it, checked as the file's own");
  module.def("scene_facts", &scene_facts, py::arg("scene"), "What the scene is, as a dict");
}

}  // namespace ffrf::python
