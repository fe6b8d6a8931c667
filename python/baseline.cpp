// `ffrf.baseline_record` and `ffrf.baseline_check`: regression baselines — `ffrf baseline record`
// and `ffrf baseline check` (app/command_baseline.cpp) as functions. record runs one model
// (study::record_baseline) and returns the baseline file's document (report/baseline_file.hpp),
// written to `out` when given; check reads a baseline file, runs its model again — or the one the
// keywords name — with the baseline's integrator settings unless the keywords say otherwise
// (study::dynamics_request), judges every recorded quantity (study::check_baseline) and returns the
// command line's JSON and text.
#include <filesystem>

#include <fmt/format.h>

#include "python/bindings.hpp"
#include "report/baseline_file.hpp"
#include "report/baseline_report.hpp"
#include "study/baseline_check.hpp"

namespace ffrf::python {
namespace {

py::dict record(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  study::BaselineRequest request;
  request.choice = study::boom_choice(boom_request(options), study::default_boom_choice(scene));
  request.settings = study::integrator_settings(scene, dynamics_request(options));
  request.outputs = options.texts("outputs");
  const std::string out = options.text("out");
  if (!out.empty()) {
    const std::filesystem::path directory = std::filesystem::absolute(out).parent_path();
    if (!std::filesystem::is_directory(directory)) {
      throw std::invalid_argument(fmt::format("out={}: the directory {} does not exist", out, directory.string()));
    }
  }
  report::BaselineFile file;
  file.provenance = report::baseline_provenance(value.path, scene.name);
  run_interruptible([&] { file.baseline = study::record_baseline(scene, request); });
  const std::string document = report::baseline_json(file);
  if (!out.empty()) report::write_baseline(out, document);
  return py::dict(py::arg("summary") = document, py::arg("text") = report::baseline_record_text(file));
}

py::dict check(const SceneValue& value, const std::string& baseline_path, const py::dict& keywords) {
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  const report::BaselineFile baseline = report::read_baseline(baseline_path);
  const std::string scene_hash = report::scene_file_hash(value.path);
  study::BaselineTolerances limits;
  limits.relative = options.number("response_rtol");
  limits.absolute = options.number("response_atol").value_or(limits.absolute);
  limits.frequency = options.number("frequency_rtol");
  if (options.given("tolerances")) {
    for (const auto& [name, tolerance] : keywords["tolerances"].cast<py::dict>()) {
      limits.per_name[py::str(name)] = tolerance.cast<double>();
    }
  }
  study::validate(limits, baseline.baseline);
  const scene::BoomChoice choice = study::boom_choice(boom_request(options), baseline.baseline.model.choice);
  const multibody::RunSettings settings =
      study::integrator_settings(scene, dynamics_request(options, study::dynamics_request(baseline.baseline.model)));
  study::BaselineCheck result;
  run_interruptible([&] { result = study::check_baseline(scene, baseline.baseline, choice, settings, limits); });
  const report::BaselineCheckContext context{baseline_path, &baseline, value.path, scene_hash};
  return py::dict(py::arg("summary") = report::baseline_check_json(context, result),
                  py::arg("text") = report::baseline_check_text(context, result), py::arg("passed") = result.passed(),
                  py::arg("failures") = result.failures());
}

}  // namespace

void bind_baselines(py::module_& module) {
  module.def("baseline_record", &record, py::arg("scene"), py::arg("keywords"));
  module.def("baseline_check", &check, py::arg("scene"), py::arg("baseline"), py::arg("keywords"));
}

}  // namespace ffrf::python
