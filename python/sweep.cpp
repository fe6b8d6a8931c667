// `ffrf.sweep`: the accuracy–speed study — the converged reference, then every configuration of a
// grid (boom model × integrator × tolerance or step) on threads — `ffrf sweep` (app/command_sweep.cpp)
// without the MPI engine, the journal and the charts: its request from the keywords over the study's
// defaults (grid, duration study::default_sweep_duration, threads study::worker_threads, the scene's
// axes study::add_scene_axes), each configuration's row as the command line's sweep.csv holds it,
// and its JSON summary and Pareto text (report/sweep_report.hpp).
#include <algorithm>

#include "python/bindings.hpp"
#include "report/sweep_csv.hpp"
#include "report/sweep_report.hpp"
#include "study/sweep.hpp"

namespace ffrf::python {
namespace {

py::object optional_number(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

py::dict sweep(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  study::SweepRequest request;
  if (options.given("grid")) request.grid = study::parse_sweep_grid(options.text("grid"));
  request.stiffening = stiffening_keyword(options);
  request.tolerance = options.number("tolerance").value_or(request.tolerance);
  request.reference = reference_options(options);
  request.jobs = study::worker_threads(static_cast<int>(std::clamp(options.whole("jobs").value_or(0), -1L, 1L << 20)));
  study::add_scene_axes(request, scene, false);
  study::DynamicsRequest dynamics;  // checks the duration against the scene
  dynamics.duration = options.number("duration").value_or(study::default_sweep_duration(scene, request.grid));
  request.duration = study::integrator_settings(scene, dynamics).duration;
  study::SweepStudy result;
  run_interruptible([&] { result = study::sweep(scene, request); });
  std::string csv = report::sweep_csv_header();
  for (const study::SweepResult& row : result.results) csv += report::sweep_csv_line(row);
  const std::vector<report::SweepRow> rows = report::read_sweep_csv(csv, "sweep.csv");
  const report::SweepFacts facts = report::context_facts(report::sweep_context(value.path, scene, request.grid, request.duration, result));
  py::list table;
  for (const report::SweepRow& row : rows) {
    table.append(py::dict(py::arg("id") = row.id, py::arg("model") = row.model, py::arg("family") = row.family,
                          py::arg("integrator") = row.integrator, py::arg("radiation") = row.radiation,
                          py::arg("elements") = row.elements, py::arg("modes") = row.modes,
                          py::arg("static_modes") = row.static_modes, py::arg("rtol") = optional_number(row.rtol),
                          py::arg("step") = optional_number(row.step), py::arg("status") = row.status,
                          py::arg("reason") = row.reason, py::arg("worst_error") = optional_number(row.worst),
                          py::arg("cargo_heave_error") = optional_number(row.cargo_heave),
                          py::arg("wall_seconds") = optional_number(row.wall), py::arg("steps") = row.steps,
                          py::arg("rhs_evaluations") = row.rhs_evaluations, py::arg("state_size") = row.state_size,
                          py::arg("work") = row.work()));
  }
  return py::dict(py::arg("summary") = report::sweep_json(rows, facts), py::arg("text") = report::pareto_text(rows, facts),
                  py::arg("rows") = table, py::arg("csv") = csv);
}

}  // namespace

void bind_sweep(py::module_& module) { module.def("sweep", &sweep, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
