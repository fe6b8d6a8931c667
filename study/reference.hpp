// A converged reference for a scene (issue 4): the nodal model refined until its outputs stop
// changing. Level i uses N = N0·2^i elements and rtol = rtol0·10^(−i) (CVODE, minimal coordinates);
// the change between two levels is the worst normalized RMS difference over the output channels
// (coupling/error_metrics.hpp) after the wave ramp. The finest level is the reference once the
// change falls below the bound; every error ffrf reports is measured against it.
#pragma once

#include <vector>

#include "cases/crane_builder.hpp"
#include "cases/scene.hpp"
#include "coupling/simulation.hpp"

namespace ffrf::cases {

struct ReferenceRequest {
  int start_elements = 8;
  double start_relative_tolerance = 1e-7;
  double bound = 1e-4;  // worst normalized RMS change between successive levels
  int max_levels = 4;
  double duration = 0.0;  // 0: the scene's
};

struct ReferenceLevel {
  int elements = 0;
  double relative_tolerance = 0.0;
  double change = 0.0;  // vs the previous level (0 for the first)
  coupling::SolverStats stats;
};

struct ConvergedReference {
  BoomChoice choice;
  coupling::IntegratorSettings settings;
  coupling::RunResult run;
  std::vector<ReferenceLevel> levels;
  double bound = 0.0;
  bool converged = false;
  double window_start = 0.0;  // end of the wave ramp [s]
};

// Time after which errors are measured: the end of the wave ramp (0 in calm water).
double ramp_end(const Scene& scene);

ConvergedReference converged_reference(const Scene& scene, const ReferenceRequest& request);

}  // namespace ffrf::cases
