// End-to-end: `ffrf run` and `ffrf compare` on the reference scene with short durations and few
// elements. The CSV header is the documented one and its first row is the static equilibrium (wire
// tension = cargo weight); the JSON summary has the documented fields; the charts are PNG files;
// compare's report names the models and the reference and embeds the charts.
#include <numbers>
#include <cmath>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace cli_run_test {

const std::string kScene = source_file("cases/paper_floating_crane.toml");
constexpr double kCargoWeight = 1.3e6 * 9.81;  // [N], the reference scene's cargo
const char* const kCharts[] = {"crane_heave",    "crane_pitch", "cargo_heave", "cargo_pitch",
                               "wire_tension",   "tip_transverse", "tip_axial", "boom_stress"};
const char* const kHeader =
    "time_s,crane_surge_m,crane_heave_m,crane_pitch_deg,cargo_surge_m,cargo_heave_m,cargo_pitch_deg,tip_axial_m,"
    "tip_transverse_m,wire_tension_N,luffing_tension_N,luffing_line_pull_N,backstay_tension_N,a_frame_rotation_deg,joint_force_x_N,joint_force_y_N,joint_moment_Nm,boom_peak_stress_MPa,"
    "boom_peak_stress_x_m,boom_stress_utilisation,constraint_residual_m,"
    "kinetic_energy_J,gravity_energy_J,strain_energy_J,wire_energy_J,spring_energy_J";

bool is_png(const fs::path& path) {
  const std::string bytes = read_text(path);
  return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

std::size_t column(const std::string& header, const std::string& name) {
  const auto names = split(header, ',');
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return i;
  }
  ADD_FAILURE() << "no column " << name;
  return 0;
}

void expect_mentions(const std::string& text, const std::vector<std::string>& parts) {
  for (const std::string& part : parts) EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in:\n" << text;
}

TEST(CliRun, WritesTheDocumentedCsvJsonAndCharts) {
  TempDir dir;
  const fs::path out = dir / "run out";
  const RunResult r = run_ffrf("run " + kScene + " --elements 3 --duration 3 --json --out '" + out.string() + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto rows = split(read_text(out / "timeseries.csv"), '\n');
  ASSERT_EQ(rows.size(), 1u + 61u);  // header, t = 0, 0.05, ..., 3
  EXPECT_EQ(rows[0], kHeader);
  const auto first = split(rows[1], ',');
  ASSERT_EQ(first.size(), split(kHeader, ',').size());
  EXPECT_EQ(std::stod(first[0]), 0.0);
  EXPECT_NEAR(std::stod(first[column(kHeader, "wire_tension_N")]) / kCargoWeight, 1.0, 1e-6) << "t = 0 is static equilibrium";
  for (const char* motion : {"crane_heave_m", "cargo_heave_m", "crane_pitch_deg"}) {
    EXPECT_EQ(std::stod(first[column(kHeader, motion)]), 0.0) << motion << ": displacement from static equilibrium";
  }
  EXPECT_NEAR(std::stod(split(rows.back(), ',')[0]), 3.0, 1e-12);
  // The stresses along the boom: one row per section of the 3-element mesh (its nodes and the quarters
  // of each element: 40 m / 4 apart), the envelope holding the peak.
  const auto stress = split(read_text(out / "boom_stress.csv"), '\n');
  ASSERT_EQ(stress.size(), 1u + 13u);
  EXPECT_EQ(stress[0],
            "x_m,axial_min_N,axial_max_N,moment_min_Nm,moment_max_Nm,stress_min_MPa,stress_max_MPa,peak_axial_N,peak_moment_Nm,"
            "peak_top_MPa,peak_bottom_MPa");
  EXPECT_EQ(std::stod(split(stress[1], ',')[0]), 0.0);
  EXPECT_EQ(std::stod(split(stress[2], ',')[0]), 10.0);
  EXPECT_EQ(std::stod(split(stress[13], ',')[0]), 120.0);

  const Json json = JsonParser(r.out).parse();
  // --json prints summary.json as the run made it; the file adds which charts were drawn (the
  // charts are drawn after the results are printed).
  const std::string summary = read_text(out / "summary.json");
  const std::size_t charts = summary.rfind(",\n  \"charts\": {");
  ASSERT_NE(charts, std::string::npos) << summary;
  EXPECT_EQ(summary.substr(0, charts) + "\n}\n", r.out) << "--json prints summary.json";
  const Json& provenance = json["provenance"];
  EXPECT_EQ(provenance["scene"].text, kScene);
  EXPECT_EQ(provenance["integrator"].text, "cvode");
  EXPECT_EQ(provenance["rtol"].number, 1e-6);
  EXPECT_EQ(provenance["atol"].number, 1e-6);
  EXPECT_EQ(provenance["duration_s"].number, 3.0);
  EXPECT_EQ(provenance["output_interval_s"].number, 0.05);
  EXPECT_FALSE(provenance["ffrf_version"].text.empty());
  EXPECT_EQ(provenance["date"].text.size(), 20u);  // 2026-01-01T00:00:00Z
  EXPECT_EQ(json["model"].text, "nodal N=3");
  EXPECT_EQ(json["elastic_dof"].number, 9);
  const Json& statics = json["static_equilibrium"];
  EXPECT_NEAR(statics["wire_tension_N"].number / kCargoWeight, 1.0, 1e-8);
  EXPECT_NEAR(statics["wire_stretch_m"].number, kCargoWeight / 2.0e8, 1e-9);
  EXPECT_GT(statics["hull_draft_mid_length_m"].number, 0.0);
  EXPECT_LT(std::abs(statics["hull_trim_deg"].number), 1.0);
  EXPECT_LT(statics["tip_transverse_m"].number, 0.0);
  EXPECT_EQ(statics["geometric_stiffening"].text, "none");
  // The stresses: recovered from the nodal displacements, the peak of the run at least the one at rest.
  const Json& stresses = json["boom_stress"];
  EXPECT_EQ(stresses["recovery"].text, "the nodal displacements");
  EXPECT_NEAR(stresses["fibre_distance_m"].number, std::sqrt(11.4 / 1.27), 1e-12);
  EXPECT_GE(stresses["peak_MPa"].number, stresses["static_peak_MPa"].number);
  EXPECT_NEAR(stresses["static_peak_MPa"].number, statics["boom_peak_stress_MPa"].number, 1e-9);
  // Beam statics of the boom: the root carries the axial components of its weight and the (vertical)
  // wire's pull, (1 200 t g + T) sin(60° + trim), in compression (the deflection changes it by < 0.1 %).
  const double elevation = std::numbers::pi / 3.0 + statics["hull_trim_deg"].number * std::numbers::pi / 180.0;
  const double axial = (1.2e6 * 9.81 + statics["wire_tension_N"].number) * std::sin(elevation);
  EXPECT_NEAR(statics["root_axial_force_N"].number / -axial, 1.0, 1e-3);
  for (const auto& name : split(kHeader, ',')) {
    if (name == "time_s") continue;
    const Json& stats = json["outputs"][name];
    EXPECT_LE(stats["min"].number, stats["max"].number) << name;
    EXPECT_GE(stats["rms_about_static"].number, 0.0) << name;
  }
  EXPECT_FALSE(json["statistics_window"]["after_ramp"].flag) << "3 s ends within the 20 s ramp";
  EXPECT_GE(json["wire"]["dynamic_amplification_factor"].number, 1.0);
  EXPECT_EQ(json["wire"]["slack_events"].number, 0.0);
  EXPECT_EQ(json["max_constraint_residual_m"].number, 0.0) << "minimal coordinates";
  const Json& solver = json["solver"];
  for (const char* counter : {"steps", "function_evaluations", "jacobian_evaluations", "newton_iterations"}) {
    EXPECT_GT(solver[counter].number, 0.0) << counter;
  }
  EXPECT_GE(solver["error_test_failures"].number, 0.0);
  EXPECT_GE(solver["convergence_failures"].number, 0.0);
  EXPECT_GT(solver["wall_time_s"].number, 0.0);
  EXPECT_NEAR(solver["real_time_factor"].number * solver["wall_time_s"].number, 3.0, 1e-9);

  for (const char* chart : kCharts) {
    EXPECT_TRUE(is_png(out / (std::string(chart) + ".png"))) << chart;
    EXPECT_GT(fs::file_size(out / (std::string(chart) + ".gp")), 0u) << chart;
  }
}

TEST(CliRun, TextReportShowsTheStaticEquilibriumAndSaysTheModelIsLinear) {
  TempDir dir;
  const RunResult r = run_ffrf("run " + kScene + " --boom rigid --integrator ida --duration 2", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_mentions(r.out, {"static equilibrium", "draft", "trim", "stretch", "tension", "joint B",
                          "geometric stiffening off", "dynamic amplification factor", "rigid (0 elastic DOFs)",
                          "ida", "wall time"});
}

TEST(CliRun, ABemSceneRecordsItsRadiationModelAndTheOptionOverridesIt) {
  TempDir dir;
  const std::string scene = source_file("cases/bem_barge_crane.toml");
  const RunResult text = run_ffrf("run " + scene + " --boom rigid --duration 2", dir.path());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  expect_mentions(text.out, {"hydro       radiation convolution T_c = 34.9 s (698 samples)",
                             "excitation BEM (Froude-Krylov + diffraction), pressure hydrostatic only"});
  const RunResult json = run_ffrf("run " + scene + " --boom rigid --duration 2 --radiation constant --json", dir.path());
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const Json summary = JsonParser(json.out).parse();
  EXPECT_EQ(summary["provenance"]["radiation"].text, "constant A, B at T = 8 s");
  EXPECT_EQ(summary["provenance"]["excitation"].text, "bem");
}

TEST(CliRun, LagrangeMultiplierRunKeepsTheConstraint) {
  TempDir dir;
  const RunResult r = run_ffrf("run " + kScene + " --elements 2 --integrator ida --duration 2 --json", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json json = JsonParser(r.out).parse();
  EXPECT_EQ(json["provenance"]["integrator"].text, "ida");
  EXPECT_LT(json["max_constraint_residual_m"].number, 1e-6);
  EXPECT_NEAR(json["static_equilibrium"]["wire_tension_N"].number / kCargoWeight, 1.0, 1e-8);
}

TEST(CliRun, ProjectionIntegratorRunsAndKeepsTheConstraint) {
  TempDir dir;
  const RunResult r = run_ffrf("run " + kScene + " --boom rigid --integrator projection --duration 2 --json", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json json = JsonParser(r.out).parse();
  EXPECT_EQ(json["provenance"]["integrator"].text, "projection");
  EXPECT_LT(json["max_constraint_residual_m"].number, 1e-6) << "projected onto C = 0 after every step";
  EXPECT_NEAR(json["static_equilibrium"]["wire_tension_N"].number / kCargoWeight, 1.0, 1e-8);
}

TEST(CliCompare, WritesReportWithTheModelsTheReferenceAndTheCharts) {
  TempDir dir;
  const fs::path out = dir / "compare";
  const RunResult r = run_ffrf("compare " + kScene + " --duration 3 --out '" + out.string() + "'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = read_text(out / "report.md");
  expect_mentions(report, {"rigid", "nodal N=1", "nodal N=16", "modal k=2+static (N=16)", "Converged reference",
                           "Not checked for convergence", "Static equilibrium", "Errors against the reference",
                           "Solver costs", "real-time factor"});
  for (const char* chart : kCharts) {
    std::string link = "(";  // not "(" + std::string(chart): GCC 12 -Wrestrict false positive
    link += chart;
    link += ".png)";
    expect_mentions(report, {link});
    EXPECT_TRUE(is_png(out / (std::string(chart) + ".png"))) << chart;
  }
  for (const char* csv : {"timeseries_rigid.csv", "timeseries_nodal_N1.csv", "timeseries_nodal_N16.csv",
                          "timeseries_modal_k1_N16.csv", "timeseries_modal_k4_static_N16.csv", "timeseries_reference.csv"}) {
    EXPECT_EQ(split(read_text(out / csv), '\n').at(0), kHeader) << csv;
  }
  const Json json = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(json["reference"]["model"].text, "nodal N=8");  // 3 s end within the wave ramp: one level only
  EXPECT_FALSE(json["reference"]["converged"].flag);
  ASSERT_EQ(json["models"].items.size(), 15u);  // rigid, nodal N=1 and 16, modal k=1,2,4 ± static in two mode sets
  EXPECT_EQ(json["models"][0]["model"].text, "rigid");
  EXPECT_EQ(json["models"][14]["model"].text, "modal k=4+static free-free (N=16)");
  EXPECT_EQ(json["models"][1]["model"].text, "nodal N=1");
  EXPECT_EQ(json["models"][2]["elastic_dof"].number, 48);
  EXPECT_EQ(json["models"][4]["model"].text, "modal k=2 (N=16)");
  EXPECT_GT(json["models"][0]["errors_to_reference"]["cargo_heave"]["normalized_rms"].number, 0.0);
  expect_mentions(r.out, {"rigid", "nodal N=1", "nodal N=16", "modal k=4+static (N=16)", "(reference)", "verdict",
                          "x wall", "x work", "static", "dynamic"});
  // The verdict (default tolerance 1 %), the static and dynamic errors, the difference panels' data.
  expect_mentions(report, {"## Verdict", "τ = 0.01", "speed-up (wall)", "speed-up (work)", "Static error", "Dynamic error",
                           "Static offset", "differences.csv"});
  EXPECT_EQ(json["verdict"]["tolerance"].number, 0.01);
  EXPECT_EQ(json["verdict"]["passed"].number + static_cast<double>(json["verdict"]["failed"].items.size()), 15.0);
  const Json& pitch = json["models"][0]["errors_to_reference"]["crane_pitch"];
  EXPECT_EQ(pitch["unit"].text, "deg") << "angles in degrees where a human reads them";
  EXPECT_GE(pitch["static_error"].number, 0.0);
  EXPECT_GE(pitch["dynamic_error"].number, 0.0);
  EXPECT_GT(fs::file_size(out / "differences.csv"), 0u);
}

TEST(CliRun, AHubSceneWithoutCargoHullOrWireGetsOnlyTheBoomCharts) {
  // cases/spin_up_beam.toml has a [hub] and a [boom], no [hull], [cargo] or [wire].
  TempDir dir;
  const fs::path out = dir / "spin";
  const RunResult r = run_ffrf("run '" + source_file("cases/spin_up_beam.toml") + "' --duration 1 --out '" + out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(is_png(out / "tip_transverse.png"));
  EXPECT_TRUE(is_png(out / "tip_axial.png"));
  for (const char* chart : {"crane_heave", "crane_pitch", "cargo_heave", "cargo_pitch", "wire_tension"}) {
    EXPECT_FALSE(fs::exists(out / (std::string(chart) + ".png"))) << chart;
    EXPECT_FALSE(fs::exists(out / (std::string(chart) + ".gp"))) << chart;
  }
}

// The mode set on the command line: the free-free set runs on the paper's clamped crane to a complete
// output named by its label; the chord frame's set is refused there, naming the key that decides it,
// and nothing is written.
TEST(CliRun, TheModeSetIsAnOptionOfTheModalBoom) {
  TempDir dir;
  const fs::path out = dir / "free";
  const RunResult r = run_ffrf("run " + kScene + " --boom modal --modes 2 --mode-set free-free --duration 2 --out '" +
                                   out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(split(read_text(out / "timeseries.csv"), '\n').at(0), kHeader);
  const Json json = JsonParser(read_text(out / "summary.json")).parse();
  EXPECT_EQ(json["model"].text, "modal k=2+static free-free (N=16)");
  EXPECT_TRUE(is_png(out / "cargo_heave.png"));

  const fs::path refused = dir / "chord";
  const RunResult chord = run_ffrf("run " + kScene + " --boom modal --mode-set pinned-pinned --duration 2 --out '" +
                                       refused.string() + "'",
                                   dir.path());
  EXPECT_EQ(chord.exit_code, 2);
  expect_mentions(chord.err, {"boom.heel", "\"clamped\"", "pinned-pinned", "free-free"});
  EXPECT_FALSE(fs::exists(refused));
}

TEST(CliCompare, ToleranceOutOfRangeIsBadInputBeforeAnythingRuns) {
  TempDir dir;
  for (const std::string command : {"compare", "sweep"}) {
    for (const std::string value : {"0", "150%", "abc", "1"}) {
      const RunResult r = run_ffrf(command + " " + kScene + " --tolerance " + value, dir.path());
      EXPECT_EQ(r.exit_code, 2) << command << " --tolerance " << value;
      EXPECT_NE(r.err.find("--tolerance " + value), std::string::npos) << r.err;
    }
  }
}

}  // namespace cli_run_test
}  // namespace ffrf::test
