// `ffrf.modes`: natural frequencies and mode shapes of the scene's boom next to the analytic
// Euler–Bernoulli values — `ffrf modes` (app/command_modes.cpp) without the spinning beam and the
// charts: the mesh, boundary, solver and count from the keywords over the scene and the study's
// defaults (study::modes_setup), the command line's JSON and table (report/modes_report.hpp), and
// the frequencies, kinds and M-normalised shapes (free DOFs × modes) as numpy arrays.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "python/bindings.hpp"
#include "report/modes_report.hpp"
#include "study/modes.hpp"

namespace ffrf::python {
namespace {

py::dict modes(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  study::ModesRequest request;
  if (const auto elements = options.whole("elements")) request.elements = static_cast<int>(std::clamp(*elements, -1L, 1L << 30));
  if (const auto count = options.whole("count")) request.count = static_cast<int>(std::clamp(*count, -1L, 1L << 30));
  request.boundary = options.text("boundary");
  if (options.given("solver")) request.solver = options.text("solver");
  const study::ModesSetup setup = study::modes_setup(value.scene, request);
  study::ModesResult result;
  run_interruptible([&] {
    result = study::solve_modes(setup.mesh, setup.boundary, setup.solver, setup.count);
    study::add_supported_boom(value.scene, setup.count, result);
  });
  const report::ModesContext context{value.path, value.scene.name};
  std::vector<double> hz, analytic_hz;
  std::vector<std::string> kinds;
  std::vector<int> orders;
  for (const modal::ClassifiedMode& mode : result.modes) {
    hz.push_back(mode.angular_frequency / (2.0 * std::numbers::pi));
    analytic_hz.push_back(mode.analytic_frequency ? *mode.analytic_frequency / (2.0 * std::numbers::pi) : std::nan(""));
    kinds.emplace_back(fem::to_string(mode.kind));
    orders.push_back(mode.order);
  }
  return py::dict(py::arg("summary") = report::modes_json(result, context, {}), py::arg("text") = report::modes_table(result, context),
                  py::arg("frequencies_hz") = array_of(hz), py::arg("analytic_hz") = array_of(analytic_hz),
                  py::arg("kinds") = kinds, py::arg("orders") = orders, py::arg("shapes") = matrix_of(result.pairs.eigenvectors),
                  py::arg("warnings") = result.warnings);
}

}  // namespace

void bind_modes(py::module_& module) { module.def("modes", &modes, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
