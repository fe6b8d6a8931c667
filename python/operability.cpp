// `ffrf.operability`: the operability table over sea states (Hs × Tp × heading, seeds per cell) —
// `ffrf operability` (app/command_operability.cpp) on threads only (MPI stays the command line's):
// the request from the keywords over the study's defaults (study::OperabilityRequest, checked by
// study::validate), the records on the task farm of one process, the command line's JSON and text
// (report/operability_report.hpp) and one row per cell. The farm's journal goes to `journal=DIR`
// (kept: a rerun with the same scene and settings resumes from it) or to a temporary directory that
// is removed however the call ends — a Ctrl-C included — so nothing is left behind.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "distributed/farm.hpp"
#include "distributed/session.hpp"
#include "python/bindings.hpp"
#include "report/operability_report.hpp"
#include "report/run_report.hpp"
#include "scene/scene_loader.hpp"
#include "study/operability.hpp"

namespace ffrf::python {
namespace {

std::atomic<int> journal_count{0};

// Removes a temporary journal directory when the call ends, however it ends.
struct TemporaryDirectory {
  std::filesystem::path path;
  ~TemporaryDirectory() {
    std::error_code ignored;
    if (!path.empty()) std::filesystem::remove_all(path, ignored);
  }
};

int whole_int(const Options& options, const char* key, int fallback) {
  return static_cast<int>(std::clamp(options.whole(key).value_or(fallback), -1L, 1L << 30));
}

study::OperabilityRequest operability_request(const Options& options) {
  study::OperabilityRequest request;
  request.significant_heights = options.numbers("hs").value_or(request.significant_heights);
  request.peak_periods = options.numbers("tp").value_or(request.peak_periods);
  if (options.given("headings")) {
    request.headings.clear();
    for (const std::string& heading : options.texts("headings")) request.headings.push_back(study::parse_heading(heading));
  }
  request.seeds = whole_int(options, "seeds", request.seeds);
  request.duration = options.number("duration").value_or(request.duration);
  request.peak_enhancement = options.number("gamma").value_or(request.peak_enhancement);
  request.components = whole_int(options, "components", request.components);
  request.variance_share = options.number("band_share").value_or(request.variance_share);
  request.verify_cells = whole_int(options, "verify", request.verify_cells);
  request.converged_elements = whole_int(options, "converged_elements", request.converged_elements);
  request.tolerance = options.number("tolerance").value_or(request.tolerance);
  study::OperabilityCriteria& c = request.criteria;
  c.daf_limit = options.number("daf_limit").value_or(c.daf_limit);
  c.slack_margin = options.number("slack_margin").value_or(c.slack_margin);
  c.cargo_motion_limit = options.number("cargo_motion_limit").value_or(c.cargo_motion_limit);
  c.root_moment_capacity = options.number("moment_capacity").value_or(c.root_moment_capacity);
  c.buckling_ratio = options.number("buckling_ratio").value_or(c.buckling_ratio);
  study::validate(request);
  return request;
}

py::dict operability(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  const scene::Scene& scene = value.scene;
  if (!scene.is_crane() || !scene.has_cargo()) {
    throw scene::SceneError({{value.path, 0, 0, "", "", "not a floating crane with a cargo: an operability table needs both"}});
  }
  const study::OperabilityRequest request = operability_request(options);
  const int threads = whole_int(options, "threads", 0);
  if (threads < 0) throw study::SettingError(study::Setting::jobs, std::to_string(threads), "not a thread count (valid range [0, inf), 0: one per core)");
  TemporaryDirectory temporary;
  std::filesystem::path journal = options.text("journal");
  if (journal.empty()) {
    temporary.path = std::filesystem::temp_directory_path() / fmt::format("ffrf-operability-{}-{}", ::getpid(), journal_count++);
    journal = temporary.path;
  }
  distributed::FarmOptions farm;
  farm.output_directory = journal;
  farm.study = fmt::format("ffrf.operability({})", value.path);
  std::string overrides;
  for (const std::string& item : scene.overrides) overrides += "\n" + item;
  // Everything besides the task keys that a record depends on (as the command line's journal).
  farm.settings = fmt::format("ffrf {}\n{}{}\nseeds={} duration={:.17g} gamma={:.17g} components={} band_share={:.17g} "
                              "tolerance={:.17g} converged={} verify={}\n",
                              report::ffrf_version(), value.text, overrides, request.seeds, request.duration,
                              request.peak_enhancement, request.components, request.variance_share, request.tolerance,
                              request.converged_elements, request.verify_cells);
  farm.threads = threads;
  farm.progress_on_terminal = false;
  study::OperabilityStudy result;
  run_interruptible([&] {
    modal::ModeCache modes;
    const study::OperabilityPlan plan = study::plan_operability(scene, request, &modes);
    distributed::Session session(distributed::LaunchInfo{});  // this process alone, MPI untouched
    std::filesystem::create_directories(journal);
    result = study::run_operability(session, scene, request, plan, farm);
  });
  const report::OperabilityContext context{value.path, farm.study, request.duration, request.seeds,
                                           request.peak_enhancement, request.tolerance, report::operability_sea_text(request)};
  py::list cells;
  for (const study::CellResult& cell : result.cells) {
    const bool judged = cell.ok;
    cells.append(py::dict(
        py::arg("hs") = cell.cell.significant_height, py::arg("tp") = cell.cell.peak_period,
        py::arg("heading") = cell.cell.heading == hydro::WaveHeading::head ? "head" : "following",
        py::arg("status") = std::string(study::to_string(cell.status())),
        py::arg("passed") = judged ? py::object(py::bool_(cell.verdict.pass)) : py::object(py::none()),
        py::arg("governing") = judged ? std::string(study::to_string(cell.verdict.governing)) : std::string(),
        py::arg("utilisation") = judged ? cell.verdict[cell.verdict.governing].utilisation : std::nan(""),
        py::arg("model") = cell.sea.physical() ? cell.model.label() : std::string(), py::arg("failure") = cell.failure));
  }
  return py::dict(py::arg("summary") = report::operability_json(result, context),
                  py::arg("text") = report::operability_text(result), py::arg("cells") = cells,
                  py::arg("warnings") = result.warnings, py::arg("journal") = temporary.path.empty() ? journal.string() : std::string());
}

}  // namespace

void bind_operability(py::module_& module) {
  module.def("operability", &operability, py::arg("scene"), py::arg("keywords"));
}

}  // namespace ffrf::python
