// What the charts draw, against facts independent of the chart code: the time-history charts of a
// scene are those of the bodies it has (a hub scene without cargo, hull or wire gets none of the
// cargo, crane and wire charts — its TOML sections say so); the accuracy–speed chart labels exactly
// the Pareto-optimal runs (found here by brute force) with their id, model and integrator, tells
// integrators apart by marker and keys them; the mode-count chart's panels share one y-range and
// mark the tolerance and the reference's error floor; the verdict sentence names the cheapest
// passing configuration with its hand-computed speed-ups.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "report/crane_charts.hpp"
#include "report/sweep_csv.hpp"
#include "report/sweep_report.hpp"
#include "report/verdict_report.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace ffrf;
namespace fs = std::filesystem;

scene::Scene shipped(const std::string& name) { return scene::load_scene(FFRF_SOURCE_DIR "/cases/" + name); }

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CraneCharts, OnlyTheBodiesTheSceneHasAreCharted) {
  using Names = std::vector<std::string>;
  // spin_up_beam.toml: a [hub] and a [boom], no [hull], [cargo] or [wire].
  EXPECT_EQ(report::crane_chart_names(shipped("spin_up_beam.toml")), (Names{"tip_transverse", "tip_axial"}));
  // dropped_load.toml: a [hub] with [cargo] and [wire], no [hull].
  EXPECT_EQ(report::crane_chart_names(shipped("dropped_load.toml")),
            (Names{"cargo_heave", "cargo_pitch", "wire_tension", "tip_transverse", "tip_axial"}));
  // The floating crane has everything; tip transverse (~2 m) and axial (~8 mm) on separate charts.
  EXPECT_EQ(report::crane_chart_names(shipped("paper_floating_crane.toml")),
            (Names{"crane_heave", "crane_pitch", "cargo_heave", "cargo_pitch", "wire_tension", "tip_transverse", "tip_axial"}));
}

TEST(CraneCharts, ReferenceDrawnLastDashedBlackAndTheDifferencePanelReadsItsColumns) {
  report::ChartSet set;
  set.sources = {{"timeseries_rigid.csv", "rigid", false, false},
                 {"timeseries_nodal_N1.csv", "nodal N=1", true, false},
                 {"timeseries_reference.csv", "reference", true, true}};
  set.names = {"cargo_heave", "tip_transverse"};
  set.differences_csv = "differences.csv";
  set.difference_floors = {1e-6, 2e-6};
  const std::string heave = report::crane_chart_script("cargo_heave", set, "png");
  const std::size_t reference = heave.find("'timeseries_reference.csv'");
  ASSERT_NE(reference, std::string::npos);
  EXPECT_GT(reference, heave.find("'timeseries_nodal_N1.csv'")) << "the reference is drawn last";
  EXPECT_NE(heave.find("lc rgb 'black'", reference), std::string::npos);
  EXPECT_NE(heave.find("dt (8,6)", reference), std::string::npos);
  EXPECT_NE(heave.find("set multiplot"), std::string::npos);
  EXPECT_NE(heave.find("set logscale y"), std::string::npos);
  // differences.csv: chart 0, models 0 and 1 of 2 → columns 2 and 3; chart 1 → 4 and 5.
  EXPECT_NE(heave.find("floored($2)"), std::string::npos);
  EXPECT_NE(heave.find("floored($3)"), std::string::npos);
  const std::string tip = report::crane_chart_script("tip_transverse", set, "png");
  EXPECT_EQ(tip.find("'timeseries_rigid.csv'"), std::string::npos) << "a rigid boom has no tip deflection";
  EXPECT_EQ(tip.find("floored($4)"), std::string::npos);
  EXPECT_NE(tip.find("floored($5)"), std::string::npos);
  // Without a reference (ffrf run): one panel, the one model named in the subtitle, no key.
  report::ChartSet single;
  single.sources = {{"timeseries.csv", "nodal N=16", true, false}};
  single.names = {"cargo_heave"};
  const std::string run = report::crane_chart_script("cargo_heave", single, "png");
  EXPECT_EQ(run.find("multiplot"), std::string::npos);
  EXPECT_NE(run.find("unset key"), std::string::npos);
}

study::SweepResult result(int id, scene::BoomChoice choice, solve::Integrator integrator, double worst, double wall,
                          long steps, int state_size) {
  study::SweepResult r;
  r.config = {id, choice, integrator, integrator == solve::Integrator::generalized_alpha ? 0.0 : 1e-6,
              integrator == solve::Integrator::generalized_alpha ? 0.01 : 0.0, 0.0, std::nullopt};
  if (integrator == solve::Integrator::generalized_alpha) r.step = 0.01;
  for (auto& e : r.errors.channels) e.normalized_rms = worst;
  r.worst = {worst, multibody::OutputChannel::cargo_heave};
  r.stats.steps = steps;
  r.stats.function_evaluations = steps;  // one RHS evaluation per step: work = steps × state size here
  r.stats.wall_seconds = wall;
  r.state_size = state_size;
  return r;
}

std::vector<report::SweepRow> random_rows() {
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::string csv = report::sweep_csv_header();
  for (int id = 0; id < 40; ++id) {
    const auto integrator = id % 3 == 0 ? solve::Integrator::generalized_alpha : solve::Integrator::cvode;
    csv += report::sweep_csv_line(result(id, {scene::BoomKind::modal, 16, 1 + id % 4, id % 2 == 0}, integrator,
                                         std::pow(10.0, -6.0 * uniform(random)), 0.01 + uniform(random), 1000 + id, 20));
  }
  return report::read_sweep_csv(csv, "random.csv");
}

TEST(SweepCharts, TheParetoPointsAreLabelledWithTheirIdModelAndIntegrator) {
  const std::vector<report::SweepRow> rows = random_rows();
  std::set<int> front;  // brute force: no other row both faster and more accurate
  for (const report::SweepRow& a : rows) {
    bool dominated = false;
    for (const report::SweepRow& b : rows) {
      dominated = dominated || (&a != &b && *b.wall <= *a.wall && *b.worst <= *a.worst && (*b.wall < *a.wall || *b.worst < *a.worst));
    }
    if (!dominated) front.insert(a.id);
  }
  std::istringstream data(report::pareto_data(rows));
  std::set<int> labelled;
  for (std::string line; std::getline(data, line);) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t open = line.find('"'), close = line.rfind('"');
    ASSERT_LT(open, close) << line;
    const int id = std::stoi(line.substr(close + 1));
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const report::SweepRow& r) { return r.id == id; });
    ASSERT_NE(row, rows.end());
    // "#id k=K[+s] integrator ...": the id, the model (every row here is modal on N = 16), the integrator.
    const std::string label = line.substr(open + 1, close - open - 1);
    const std::string model = "k=" + std::to_string(row->modes) + (row->static_modes ? "+s" : "");
    EXPECT_EQ(label.rfind("#" + std::to_string(id) + " " + model + " " + (row->integrator == "cvode" ? "cvode" : "gα"), 0), 0u)
        << label;
    labelled.insert(id);
  }
  EXPECT_EQ(labelled, front);
  EXPECT_GE(front.size(), 2u);
}

TEST(SweepCharts, IntegratorsByMarkerSharedRangeToleranceAndReferenceFloor) {
  std::vector<report::SweepRow> rows = random_rows();
  report::SweepFacts facts;
  facts.duration = 40.0;
  facts.tolerance = 0.01;
  facts.reference = "reference (nodal N=16, rtol 1e-07)";
  facts.reference_change = 5.8e-5;
  const fs::path dir = fs::temp_directory_path() / ("ffrf-sweep-charts-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  {
    report::StagedDirectory out(dir, "done");
    report::draw_sweep_charts(out, rows, facts);
    out.write("done", "");
    out.commit();
  }
  // accuracy_speed.dat: the marker (third column) is the integrator's: cvode and generalized-α differ.
  std::istringstream points(read(dir / "accuracy_speed.dat"));
  std::set<std::pair<std::string, int>> markers;
  for (std::string line; std::getline(points, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double wall = 0, worst = 0;
    int point = 0, colour = 0, id = 0;
    std::string family, integrator;
    fields >> wall >> worst >> point >> colour >> id >> family >> integrator;
    markers.insert({integrator, point});
  }
  ASSERT_EQ(markers.size(), 2u);
  EXPECT_NE(markers.begin()->second, std::next(markers.begin())->second);
  const std::string speed = read(dir / "accuracy_speed.gp");
  EXPECT_NE(speed.find("keyentry with points pt 7 ps 1.5 lc rgb 'black' title 'cvode'"), std::string::npos);
  EXPECT_NE(speed.find("title 'generalized-alpha'"), std::string::npos);
  EXPECT_NE(speed.find("with labels"), std::string::npos);
  EXPECT_NE(speed.find("tolerance τ = 0.01"), std::string::npos);
  const std::string modes = read(dir / "mode_count.gp");
  std::size_t ranges = 0;
  for (std::size_t at = modes.find("set yrange"); at != std::string::npos; at = modes.find("set yrange", at + 1)) ++ranges;
  EXPECT_EQ(ranges, 1u) << "one y-range, set before both panels";
  EXPECT_LT(modes.find("set yrange"), modes.find("\nplot "));
  EXPECT_NE(modes.find("reference's own error floor 5.8e-05"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "accuracy_speed.png"));
  EXPECT_TRUE(fs::exists(dir / "mode_count.png"));
  fs::remove_all(dir);
}

TEST(SweepVerdict, CheapestPassingConfigurationWithHandComputedSpeedUps) {
  // Reference: 8 s and work 64 000. τ = 1 %: the rigid run fails; the two modal runs pass; the nodal
  // one passes too but costs more work (1000 × 60 = 60 000) than modal k=2+static (2000 × 20 = 40 000).
  std::string csv = report::sweep_csv_header();
  csv += report::sweep_csv_line(result(0, {scene::BoomKind::rigid, 1}, solve::Integrator::cvode, 2.5, 0.1, 500, 12));
  csv += report::sweep_csv_line(result(1, {scene::BoomKind::modal, 16, 2, true}, solve::Integrator::cvode, 3e-5, 0.4, 2000, 20));
  csv += report::sweep_csv_line(result(2, {scene::BoomKind::modal, 16, 4, true}, solve::Integrator::cvode, 2e-5, 0.3, 2100, 24));
  csv += report::sweep_csv_line(result(3, {scene::BoomKind::nodal, 8}, solve::Integrator::cvode, 1e-5, 2.0, 1000, 60));
  const std::vector<report::SweepRow> rows = report::read_sweep_csv(csv, "verdict.csv");
  report::SweepFacts facts;
  facts.tolerance = 0.01;
  facts.reference = "reference";
  facts.reference_wall_seconds = 8.0;
  facts.reference_work = 64000.0;
  const study::Verdict verdict = report::sweep_verdict(rows, facts);
  ASSERT_TRUE(verdict.cheapest.has_value());
  EXPECT_EQ(*verdict.cheapest, 1u);
  EXPECT_DOUBLE_EQ(verdict.models[1].wall_speedup, 20.0);
  EXPECT_DOUBLE_EQ(verdict.models[1].work_speedup, 1.6);
  const std::string sentence = report::sweep_verdict_sentence(rows, facts);
  // The decisive measure named, the wall time reported beside it and said not to decide.
  EXPECT_NE(sentence.find("Cheapest by solver work (RHS evaluations × state size) of the configurations at rtol 1e-06"),
            std::string::npos) << sentence;
  EXPECT_NE(sentence.find("modal k=2+static (N=16), cvode rtol 1e-06, error 3e-05"), std::string::npos) << sentence;
  EXPECT_NE(sentence.find("1.6× less solver work than the reference; wall time 20× less (measured; not decisive"),
            std::string::npos) << sentence;
  EXPECT_NE(sentence.find("3 of 4 configurations"), std::string::npos) << sentence;
  EXPECT_NE(sentence.find("Fail at every setting (best error): rigid (2.5)"), std::string::npos) << sentence;
}

}  // namespace
