// `ffrf.run`: one crane model, static equilibrium then dynamics — `ffrf run` (app/command_run.cpp)
// as a function. The boom model and the integrator settings come from the keywords over the
// study's defaults (study::boom_choice, study::integrator_settings); the summary is the command
// line's JSON (report::run_json, `ffrf run --json`) and the time series are the columns of its
// timeseries.csv, one numpy array per channel of the output-channel table, in the CSV's units.
#include "python/bindings.hpp"
#include "report/run_report.hpp"
#include "study/model_warnings.hpp"
#include "study/output_series.hpp"

namespace ffrf::python {
namespace {

py::object vector_array(const Eigen::VectorXd& values) {
  return array_of(std::vector<double>(values.data(), values.data() + values.size()));
}

// The boom's stress envelope over the run (boom_stress.csv's columns): None without a boom.
py::object boom_stress(const multibody::BoomStressEnvelope& envelope) {
  if (envelope.empty()) return py::none();
  return py::dict(py::arg("position") = vector_array(envelope.position),
                  py::arg("axial_force_min") = vector_array(envelope.axial_min),
                  py::arg("axial_force_max") = vector_array(envelope.axial_max),
                  py::arg("bending_moment_min") = vector_array(envelope.moment_min),
                  py::arg("bending_moment_max") = vector_array(envelope.moment_max),
                  py::arg("stress_min") = vector_array(envelope.stress_min / 1e6),
                  py::arg("stress_max") = vector_array(envelope.stress_max / 1e6),
                  py::arg("peak_time") = envelope.peak_time);
}

py::dict run(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  const scene::BoomChoice choice = study::boom_choice(boom_request(options), study::default_boom_choice(scene));
  const multibody::RunSettings settings = study::integrator_settings(scene, dynamics_request(options));
  report::RunContext context = report::make_context(value.path, scene, settings);
  std::vector<std::string> notes;
  study::ModelRun model;
  run_interruptible([&] {
    try {
      context.warnings = study::model_warnings(scene, choice);
    } catch (const std::exception& error) {  // the boom's modes could not be solved: no advice, the run decides
      notes.push_back(std::string("no modelling advice (") + error.what() + ")");
    }
    model = study::run_model(scene, choice, settings);
  });
  for (const study::ModelWarning& w : context.warnings.below) notes.push_back("modelled below need: " + report::warning_line(w));
  for (const study::ModelWarning& w : context.warnings.above) notes.push_back("modelled above need: " + report::warning_line(w));

  py::dict outputs, columns, units;
  for (const study::SeriesSpec& spec : study::crane_series()) {
    std::vector<double> series;
    series.reserve(model.result.samples.size());
    for (const multibody::CraneOutputs& sample : model.result.samples) {
      series.push_back(study::series_value(spec, sample, model.statics.outputs));
    }
    const std::string name(spec.name);
    outputs[name.c_str()] = array_of(series);
    columns[name.c_str()] = std::string(spec.column);
    units[name.c_str()] = std::string(spec.unit);
  }
  return py::dict(py::arg("model") = model.choice.label(), py::arg("state_size") = model.state_size,
                  py::arg("work") = model.work(), py::arg("time") = array_of(model.result.time),
                  py::arg("outputs") = outputs, py::arg("columns") = columns, py::arg("units") = units,
                  py::arg("summary") = report::run_json(context, model),
                  py::arg("text") = report::run_header_text(context, model) + report::static_report(scene, model) +
                                    report::dynamics_text(scene, model),
                  py::arg("boom_stress") = boom_stress(model.result.boom_stress), py::arg("warnings") = notes);
}

}  // namespace

void bind_run(py::module_& module) { module.def("run", &run, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
