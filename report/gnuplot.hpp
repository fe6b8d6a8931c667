// Charts drawn with gnuplot: its scripts are kept next to each PNG so users can restyle and rerun
// them with `gnuplot NAME.gp` inside the output directory. This file runs them (never with the
// user's terminal on gnuplot's standard input) and quotes text for them.
#pragma once

#include <filesystem>
#include <string>

namespace ffrf::report {

// "pngcairo" when this gnuplot has it, else "png"; throws std::runtime_error when gnuplot is
// not installed.
std::string png_terminal();

// Runs `gnuplot script` in `directory`; throws std::runtime_error with gnuplot's message on failure.
void run_gnuplot(const std::filesystem::path& directory, const std::string& script);

// A gnuplot single-quoted string (a quote doubled).
std::string gnuplot_quoted(const std::string& text);
// A gnuplot double-quoted string of one or two lines (\n a line break).
std::string gnuplot_lines(const std::string& first, const std::string& second);

}  // namespace ffrf::report
