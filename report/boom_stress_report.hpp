// What the reports say about the stresses along the boom (multibody/boom_stress.hpp): the line of
// the static report, the line of a run's summary, the JSON block of a model, the envelope along the
// boom as CSV (boom_stress.csv: each section's extremes over the run and the profile at the run's
// peak) and its chart (boom_stress.png: the fibre-stress envelopes of one or more models along the
// boom, the allowable stress marked).
#pragma once

#include <string>
#include <vector>

#include "multibody/boom_stress_profile.hpp"
#include "report/json.hpp"
#include "report/output_directory.hpp"
#include "scene/scene.hpp"
#include "study/run_pipeline.hpp"

namespace ffrf::report {

// How the model's stresses were recovered: "mode acceleration", "mode displacement", "the nodal
// displacements", "quasi-static (rigid boom, by mode acceleration)".
std::string stress_recovery_name(const scene::BoomChoice& choice);

// "  stress    peak fibre stress 52.1 MPa at x = 60.0 m (c = 3.00 m), utilisation 0.22 of 235 MPa\n"
std::string boom_stress_static_line(const scene::Scene& scene, const multibody::CraneOutputs& at_rest);
// The run's peak over time, where and when, and its utilisation; empty without stresses.
std::string boom_stress_text(const scene::Scene& scene, const study::ModelRun& run);
// {recovery, fibre_distance_m, allowable_stress_MPa, sections, peak_MPa, peak_position_m, peak_time_s,
//  utilisation, static_peak_MPa}
Json boom_stress_json(const scene::Scene& scene, const study::ModelRun& run);

// x_m, axial_min_N, axial_max_N, moment_min_Nm, moment_max_Nm, stress_min_MPa, stress_max_MPa,
// then the profile at the peak: peak_axial_N, peak_moment_Nm, peak_top_MPa, peak_bottom_MPa.
std::string boom_stress_csv(const multibody::BoomStressEnvelope& envelope);

struct StressChartSource {
  std::string csv;    // a boom_stress.csv in the output directory
  std::string label;  // the model
  bool reference = false;
};
// boom_stress.png: each source's most tensile and most compressive fibre stress along the boom over
// the run (one source: also its profile at the peak), ± the allowable stress when the scene gives one.
// Left out when no source has stresses.
void draw_boom_stress_chart(const StagedDirectory& out, const std::vector<StressChartSource>& sources, const scene::Scene& scene,
                            const std::string& subtitle, const std::string& command);

}  // namespace ffrf::report
