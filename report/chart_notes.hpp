// What a command says about its charts (StagedDirectory::charts()): which were left out because they
// had nothing to draw and which gnuplot failed on, with the reason, in report.md (a "Charts not
// drawn" section), in summary.json (a "charts" object listing every chart) and as lines for the
// console. A chart that is not drawn is named, never silent; the command's results stand.
#pragma once

#include <string>
#include <string_view>

#include "report/output_directory.hpp"

namespace ffrf::report {

// "## Charts not drawn" with one line per chart left out or failed; empty when every chart was drawn.
std::string charts_markdown(const StagedDirectory& out);
// The summary JSON text with a "charts" object added: {"drawn": [png, ...], "left_out": [{"chart",
// "reason"}], "failed": [{"chart", "reason"}]}. `summary` must be one JSON object.
std::string with_charts_json(const std::string& summary, const StagedDirectory& out);
// "ffrf COMMAND: note: chart X.png left out: REASON" and "ffrf COMMAND: warning: chart X.png not
// drawn (gnuplot failed; X.gp is kept): MESSAGE" lines, for stderr; empty when every chart was drawn.
std::string chart_notes_text(std::string_view command, const StagedDirectory& out);

}  // namespace ffrf::report
