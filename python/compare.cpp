// `ffrf.compare`: the converged reference, then the compared boom models on one scene, each judged
// against the tolerance — `ffrf compare` (app/command_compare.cpp) as a function: its request from
// the keywords over the study's defaults (study::compare), the command line's JSON summary and text
// (report/compare_report.hpp), and, for a scene with BEM coefficients, the radiation models compared
// on the chosen boom model as the command line does.
#include <optional>

#include "python/bindings.hpp"
#include "report/compare_report.hpp"
#include "study/compare.hpp"
#include "study/radiation_compare.hpp"

namespace ffrf::python {
namespace {

py::dict compare(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  scene::Scene scene = value.scene;
  study::CompareRequest request;
  request.stiffening = stiffening_keyword(options);
  request.tolerance = options.number("tolerance").value_or(request.tolerance);
  request.settings = study::integrator_settings(scene, dynamics_request(options));
  request.reference = reference_options(options);
  study::Comparison comparison;
  std::optional<study::RadiationComparison> radiation;
  run_interruptible([&] {
    comparison = study::compare(scene, request);
    if (scene.bem) {
      const study::Verdict& verdict = comparison.verdict;
      const std::size_t boom = verdict.cheapest ? *verdict.cheapest : verdict.most_accurate.value_or(0);
      radiation = study::compare_radiation(scene, comparison.runs[boom].choice, request.settings, request.tolerance);
    }
  });
  scene.boom.stiffening = comparison.stiffening;  // what every model ran with
  const report::RunContext context = report::make_context(value.path, scene, request.settings);
  return py::dict(py::arg("summary") = report::compare_json(context, comparison),
                  py::arg("text") = report::compare_text(context, comparison),
                  py::arg("radiation") = radiation ? study::radiation_comparison_text(*radiation) : std::string());
}

}  // namespace

void bind_compare(py::module_& module) { module.def("compare", &compare, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
