// `ffrf.stability`: the stability map — where each method fails (explicit step limits, constraint
// drift, spin divergence, slack wire and snap loads, BDF order, buckling margin), each failure named
// — `ffrf stability` (app/command_stability.cpp) as a function: the experiments that apply to the
// scene (study::stability_map), the command line's summary.json and report.md (report/
// stability_section.hpp). With out=DIR the report, its CSVs and charts are written there completely
// or not at all, as the command line's --out; without, they are drawn in a temporary directory that
// is removed.
#include <unistd.h>

#include <atomic>
#include <filesystem>

#include <fmt/format.h>

#include "python/bindings.hpp"
#include "report/chart_notes.hpp"
#include "report/gnuplot.hpp"
#include "report/stability_section.hpp"

namespace ffrf::python {
namespace {

std::atomic<int> temporary_count{0};

py::dict stability(const SceneValue& value, const py::dict& keywords) {
  const Options options(keywords);
  study::StabilityOptions settings;
  settings.quick = options.flag("quick").value_or(settings.quick);
  const std::string out = options.text("out");
  report::png_terminal();  // fail before the computation when gnuplot is missing
  const bool temporary = out.empty();
  const std::filesystem::path target =
      temporary ? std::filesystem::temp_directory_path() / fmt::format("ffrf-stability-{}-{}", ::getpid(), temporary_count++)
                : std::filesystem::path(out);
  report::StabilityReport result;
  run_interruptible([&] {
    report::StagedDirectory staged(target, "summary.json");
    result = report::stability_report(value.scene, value.path, settings.quick, study::stability_map(value.scene, settings), staged);
    result.markdown += report::charts_markdown(staged);
    result.json = report::with_charts_json(result.json, staged);
    staged.write("report.md", result.markdown);
    staged.write("summary.json", result.json);
    staged.commit();
  });
  if (temporary) std::filesystem::remove_all(target);
  return py::dict(py::arg("summary") = result.json, py::arg("text") = result.markdown);
}

}  // namespace

void bind_stability(py::module_& module) { module.def("stability", &stability, py::arg("scene"), py::arg("keywords")); }

}  // namespace ffrf::python
