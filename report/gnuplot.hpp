// Charts drawn with gnuplot: the scripts (kept next to each PNG so users can restyle and rerun
// them with `gnuplot NAME.gp` inside the output directory) and running them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/modes_analysis.hpp"

namespace ffrf::app {

// "pngcairo" when this gnuplot has it, else "png"; throws std::runtime_error when gnuplot is
// not installed.
std::string png_terminal();

// Runs `gnuplot script` in `directory`; throws std::runtime_error with gnuplot's message on failure.
void run_gnuplot(const std::filesystem::path& directory, const std::string& script);

// Transverse shape v(x) of each bending mode, from mode_shapes_sampled.csv.
std::string mode_shapes_script(const ModesResult& result, const std::string& terminal);
// Relative error of f1..f4 against N on log–log axes, from frequency_convergence.csv.
std::string convergence_script(const ModesResult& result, const std::string& terminal);

}  // namespace ffrf::app
