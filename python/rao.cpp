// `ffrf.rao`: the frequency domain — RAOs and coupled natural modes of the crane linearised about
// its static equilibrium, rigid, nodal and modal booms side by side (or the one model the keywords
// name) — `ffrf rao` (app/command_rao.cpp) as a function. The frequencies are wave periods
// (`periods`, seconds) or angular frequencies (`frequencies`), else the study's default grid
// (study::default_rao_frequencies); each model's grid is refined at its resonance peaks unless
// refine_peaks=False; the scene's own sea spectrum weighs the responses (study::default_sea_spectrum)
// unless spectrum=False. Returns the command line's JSON and text (report/rao_report.hpp) and per
// model its frequencies and the complex response of every linear output (per metre of wave
// amplitude), named by the output-channel table.
#include <chrono>

#include "python/bindings.hpp"
#include "report/rao_report.hpp"
#include "scene/scene_loader.hpp"
#include "study/rao.hpp"

namespace ffrf::python {
namespace {

py::dict rao(const SceneValue& value, const py::dict& keywords) {
  const auto start = std::chrono::steady_clock::now();
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  study::RaoRequest request;
  if (boom_given(options)) request.models = {study::boom_choice(boom_request(options), study::default_boom_choice(scene))};
  if (const auto periods = options.numbers("periods")) {
    request.angular_frequencies = study::frequencies_of_periods(*periods);
  } else if (const auto frequencies = options.numbers("frequencies")) {
    study::validate_frequencies(*frequencies);
    request.angular_frequencies = *frequencies;
  } else {
    request.angular_frequencies = study::default_rao_frequencies();
  }
  request.refine_peaks = options.flag("refine_peaks").value_or(study::default_refine_peaks);
  if (options.flag("spectrum").value_or(true)) request.sea_spectrum = study::default_sea_spectrum(scene);
  if (!scene.is_crane()) {
    throw scene::SceneError({{value.path, 0, 0, "", "",
                              "the frequency domain needs a floating crane ([hull], [cargo], [wire]); this scene has a "
                              "[hub] and no water"}});
  }
  study::RaoResult result;
  run_interruptible([&] {
    modal::ModeCache modes;
    result = study::response_amplitude_operators(scene, request, {}, &modes);
  });
  const report::RaoContext context{value.path, scene.name,
                                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  py::list models;
  for (const study::ModelRao& model : result.models) {
    py::dict responses, units;
    for (int i = 0; i < multibody::linear_output_count; ++i) {
      const auto output = static_cast<multibody::LinearOutput>(i);
      const std::string name(multibody::to_string(output));
      responses[name.c_str()] = complex_array_of(model.response[static_cast<std::size_t>(i)]);
      units[name.c_str()] = std::string(multibody::unit_per_amplitude(output));
    }
    py::list natural;
    for (const study::NaturalMode& mode : model.modes) {
      natural.append(py::dict(py::arg("angular_frequency") = mode.angular_frequency, py::arg("period") = mode.period(),
                              py::arg("damping_ratio") = mode.damping_ratio, py::arg("dominant") = mode.dominant));
    }
    models.append(py::dict(py::arg("label") = model.choice.label(),
                           py::arg("angular_frequencies") = array_of(model.angular_frequencies),
                           py::arg("responses") = responses, py::arg("units") = units, py::arg("natural_modes") = natural));
  }
  return py::dict(py::arg("summary") = report::rao_json(result, {}, context), py::arg("text") = report::rao_text(result, {}, context),
                  py::arg("models") = models);
}

}  // namespace

void bind_rao(py::module_& module) { module.def("rao", &rao, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
