// The operability chart (operability.png, its gnuplot script operability.gp and data
// operability.dat): one Hs–Tp panel per heading, each cell a filled box whose fill says the verdict
// before anything else — light green pass, dark red fail (light against dark, so the verdict reads in
// greyscale too), grey hatching for a sea too steep to exist, white for a cell whose record failed —
// and whose label names the governing criterion and its utilisation; a thick black line is the limit
// contour, the level u = 1 of the governing utilisation interpolated linearly between the cells'
// centres (marching squares; a square with a cell without a verdict at a corner is left out).
#pragma once

#include <cstddef>
#include <vector>

#include "report/output_directory.hpp"
#include "study/operability.hpp"

namespace ffrf::report {

struct ContourSegment {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

// The level line value = level of a field sampled on the grid x[i] × y[j] (values[j * x.size() + i];
// NaN: no value there), by marching squares with linear interpolation along the edges; a saddle
// square is resolved by the mean of its corners. Exact for a field linear in x and y.
std::vector<ContourSegment> level_contour(const std::vector<double>& x, const std::vector<double>& y,
                                          const std::vector<double>& values, double level);

// Writes operability.dat, operability.gp and operability.png into the staged directory.
void draw_operability_chart(const StagedDirectory& out, const study::OperabilityStudy& study);

}  // namespace ffrf::report
