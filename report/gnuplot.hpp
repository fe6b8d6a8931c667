// Charts drawn with gnuplot: its scripts are kept next to each PNG so users can restyle and rerun
// them with `gnuplot NAME.gp` inside the output directory. This file runs them (never with the
// user's terminal on gnuplot's standard input), quotes text for them, and draws a chart into an
// output directory so that a chart never costs a command its results: a chart with nothing to draw
// is left out (no script, the reason recorded), and one whose gnuplot run fails is recorded with
// gnuplot's message (its script kept, no PNG) instead of throwing.
#pragma once

#include <filesystem>
#include <string>

#include "report/output_directory.hpp"

namespace ffrf::report {

// "pngcairo" when this gnuplot has it, else "png"; throws std::runtime_error when gnuplot is
// not installed. Asked once per process (the commands ask before they compute, so a missing gnuplot
// stops them early).
std::string png_terminal();

// Runs `gnuplot script` in `directory`; throws std::runtime_error with gnuplot's message on failure.
void run_gnuplot(const std::filesystem::path& directory, const std::string& script);

// Writes NAME.gp into `out` and runs gnuplot on it, which draws NAME.png; records the chart in
// `out.charts()` as drawn, or as failed with gnuplot's message (a partial NAME.png removed). Never
// throws for gnuplot's sake (only OutputError when the script cannot be written).
void draw_chart(const StagedDirectory& out, const std::string& name, const std::string& script);
// Records NAME.png as left out: the chart has nothing to draw, for `reason` ("a rigid boom has no
// elastic tip deflection"); no script is written.
void leave_out_chart(const StagedDirectory& out, const std::string& name, const std::string& reason);

// A gnuplot single-quoted string (a quote doubled).
std::string gnuplot_quoted(const std::string& text);
// A gnuplot double-quoted string of one or two lines (\n a line break).
std::string gnuplot_lines(const std::string& first, const std::string& second);

}  // namespace ffrf::report
