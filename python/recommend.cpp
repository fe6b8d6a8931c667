// `ffrf.recommend`: the cheapest boom model and integrator within a tolerance, reasoned from the
// physics and proved by verification runs — `ffrf recommend` (app/command_recommend.cpp) as a
// function: the request from the keywords over the study's defaults (study::recommend), the command
// line's JSON and text (report/recommend_report.hpp), and a [bem] scene's radiation models compared
// on the chosen model as the command line does.
#include <optional>

#include "python/bindings.hpp"
#include "report/recommend_report.hpp"
#include "study/error_measure.hpp"
#include "study/radiation_compare.hpp"
#include "study/recommend.hpp"

namespace ffrf::python {
namespace {

py::dict recommend(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  study::RecommendRequest request;
  request.tolerance = options.number("tolerance").value_or(request.tolerance);
  if (options.given("outputs")) request.outputs = study::channels_named(options.texts("outputs"));
  study::DynamicsRequest dynamics;  // checks the duration against the scene
  dynamics.duration = options.number("duration");
  const multibody::RunSettings radiation_settings = study::integrator_settings(scene, dynamics);
  request.duration = radiation_settings.duration;
  request.reference = reference_options(options);
  study::Recommendation rec;
  std::optional<study::RadiationComparison> radiation;
  run_interruptible([&] {
    rec = study::recommend(scene, request);
    if (scene.bem && rec.chosen) {
      radiation = study::compare_radiation(scene, rec.candidates[*rec.chosen].choice, radiation_settings, request.tolerance);
    }
  });
  const report::RecommendContext context{value.path, &scene, request.tolerance};
  py::object chosen = py::none();
  if (rec.chosen) {
    const study::Candidate& c = rec.candidates[*rec.chosen];
    chosen = py::dict(py::arg("label") = c.label(), py::arg("boom") = std::string(scene::to_string(c.choice.kind)),
                      py::arg("elements") = c.choice.elements, py::arg("modes") = c.choice.modes,
                      py::arg("static_modes") = c.choice.static_modes,
                      py::arg("stiffening") = std::string(scene::to_string(
                          c.choice.stiffening.value_or(rec.reference_scene.boom.stiffening))),
                      py::arg("integrator") = std::string(solve::to_string(c.integrator)),
                      py::arg("rtol") = rec.reasoning.relative_tolerance, py::arg("error") = c.error,
                      py::arg("work") = c.work(), py::arg("wall_seconds") = c.wall_seconds,
                      py::arg("command") = report::run_command_line(value.path, c, rec.reasoning.relative_tolerance,
                                                                    rec.duration, rec.reference_scene));
  }
  return py::dict(py::arg("summary") = report::recommend_json(context, rec),
                  py::arg("text") = report::recommend_text(context, rec), py::arg("chosen") = chosen,
                  py::arg("radiation") = radiation ? study::radiation_comparison_text(*radiation) : std::string());
}

}  // namespace

void bind_recommend(py::module_& module) { module.def("recommend", &recommend, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
