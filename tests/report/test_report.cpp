// The report library against independent facts (no golden output): sweep.csv read back gives the
// values written (shortest exact form, never NaN text, failures with empty cells and their reason,
// quotes and commas inside a reason survive); the Pareto front equals the non-dominated set found
// by brute force; JSON documents parse back with NaN written as null; an output directory is
// complete or absent.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "report/json.hpp"
#include "report/output_directory.hpp"
#include "report/rao_report.hpp"
#include "report/sweep_csv.hpp"
#include "report/sweep_report.hpp"

namespace {

using namespace ffrf;
namespace fs = std::filesystem;

study::SweepResult ok_result(int id, double worst, double wall) {
  study::SweepResult r;
  r.config = {id, {scene::BoomKind::modal, 16, 2, true}, solve::Integrator::cvode, 1e-6, 0.0, 0.0, std::nullopt};
  for (std::size_t c = 0; c < r.errors.channels.size(); ++c) {
    r.errors.channels[c].normalized_rms = worst * std::pow(0.5, static_cast<double>(c));
    r.errors.channels[c].max_abs = 0.1 + static_cast<double>(c) / 3.0;  // 1/3: needs every digit to round-trip
  }
  r.errors.daf_error = 1.0 / 7.0;
  r.worst = {worst, multibody::OutputChannel::cargo_heave};
  r.stats.steps = 1234;
  r.stats.function_evaluations = 5678;
  r.stats.wall_seconds = wall;
  return r;
}

TEST(SweepCsv, RowsReadBackExactlyFailuresHaveEmptyCellsAndTheirReason) {
  study::SweepResult ok = ok_result(3, 1.0 / 3.0, 0.125);
  study::SweepResult failed;
  failed.config = {4, {scene::BoomKind::rigid, 1}, solve::Integrator::arkode, 0.0, 0.0, 2.0, std::nullopt};
  failed.status = study::RunStatus::failed;
  failed.reason = "ARKODE: unstable, \"h = 2x\", step too large\nsecond line";
  failed.errors.channels[0].normalized_rms = NAN;  // never written for a failed row
  const std::string csv = report::sweep_csv_header() + report::sweep_csv_line(ok) + report::sweep_csv_line(failed);
  std::string lower = csv;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  const std::vector<report::SweepRow> rows = report::read_sweep_csv(csv, "test.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].id, 3);
  EXPECT_EQ(rows[0].model, "modal k=2+static (N=16)");
  EXPECT_EQ(rows[0].family, "modal+static");
  EXPECT_EQ(rows[0].modes, 2);
  EXPECT_TRUE(rows[0].static_modes);
  EXPECT_EQ(*rows[0].worst, ok.errors.worst_normalized_rms());  // exact: shortest round-trip form
  EXPECT_EQ(*rows[0].cargo_heave, ok.errors.channels[0].normalized_rms);
  EXPECT_EQ(*rows[0].daf_error, 1.0 / 7.0);
  EXPECT_EQ(*rows[0].wall, 0.125);
  EXPECT_EQ(rows[0].steps, 1234);
  EXPECT_TRUE(rows[0].ok());
  EXPECT_FALSE(rows[1].ok());
  EXPECT_EQ(rows[1].status, "failed");
  EXPECT_FALSE(rows[1].worst.has_value());
  EXPECT_EQ(rows[1].reason, "ARKODE: unstable, \"h = 2x\", step too large second line");
  // A different header is refused, naming the file.
  EXPECT_THROW(report::read_sweep_csv("id,model\n0,rigid\n", "other.csv"), std::runtime_error);
}

TEST(SweepReport, ParetoFrontIsTheNonDominatedSet) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::string csv = report::sweep_csv_header();
  for (int id = 0; id < 60; ++id) {
    csv += report::sweep_csv_line(ok_result(id, std::pow(10.0, -6.0 * uniform(random)), 0.01 + uniform(random)));
  }
  const std::vector<report::SweepRow> rows = report::read_sweep_csv(csv, "random.csv");
  std::vector<std::size_t> brute;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < rows.size(); ++j) {
      dominated = dominated || (j != i && *rows[j].wall <= *rows[i].wall && *rows[j].worst <= *rows[i].worst &&
                                (*rows[j].wall < *rows[i].wall || *rows[j].worst < *rows[i].worst));
    }
    if (!dominated) brute.push_back(i);
  }
  std::vector<std::size_t> front = report::pareto_front(rows);
  std::sort(front.begin(), front.end());
  EXPECT_EQ(front, brute);
  EXPECT_GE(front.size(), 2u);
}

TEST(Json, DocumentsParseBackAndNaNIsNull) {
  report::Json json{{"finite", 0.1}, {"not_a_number", NAN}, {"infinite", INFINITY}, {"count", 3L}, {"text", "Ω = 4 rad/s"}};
  const nlohmann::json back = nlohmann::json::parse(report::json_text(json));
  EXPECT_EQ(back["finite"].get<double>(), 0.1);
  EXPECT_TRUE(back["not_a_number"].is_null());
  EXPECT_TRUE(back["infinite"].is_null());
  EXPECT_TRUE(back["count"].is_number_integer());
  EXPECT_EQ(back["text"].get<std::string>(), "Ω = 4 rad/s");
  // Keys keep the order they were written in.
  const std::string text = report::json_text(json);
  EXPECT_LT(text.find("finite"), text.find("not_a_number"));
  EXPECT_LT(text.find("not_a_number"), text.find("count"));
}

// A memory hull's mode Newton could not refine (study::NaturalMode::unrefined) is said in the text,
// the Markdown and the JSON, with its reason; a result whose modes all refined says nothing of it.
TEST(RaoReport, ModesNewtonDidNotRefineAreFlaggedWithTheReason) {
  study::RaoResult result;
  result.angular_frequencies = {0.5, 1.0};
  study::ModelRao model;
  model.choice = {scene::BoomKind::rigid, 1};
  model.coordinates = 6;
  model.modes = {{0.6, 0.05, "hull heave", ""}, {0.9, 0.02, "hull pitch", "did not converge in 0 steps"}};
  model.angular_frequencies = result.angular_frequencies;
  for (auto& values : model.response) values = {{1.0, 0.0}, {0.5, 0.1}};
  result.models.push_back(model);
  const report::RaoContext context{"barge.toml", "barge", 1.0};
  const std::string text = report::rao_text(result, {}, context);
  EXPECT_NE(text.find("hull pitch  (not refined)"), std::string::npos) << text;
  EXPECT_NE(text.find("rigid mode 2 (T = 6.981 s) is the constant system's, not refined: did not converge in 0 steps"),
            std::string::npos) << text;
  EXPECT_EQ(text.find("hull heave  (not refined)"), std::string::npos) << text;
  const std::string markdown = report::rao_markdown(result, {}, context, false);
  EXPECT_NE(markdown.find("hull pitch (not refined)"), std::string::npos);
  EXPECT_NE(markdown.find("did not converge in 0 steps"), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(report::rao_json(result, {}, context));
  const auto& modes = json["models"][0]["natural_modes"];
  EXPECT_FALSE(modes[0].contains("not_refined"));
  EXPECT_EQ(modes[1]["not_refined"].get<std::string>(), "did not converge in 0 steps");

  result.models[0].modes[1].unrefined.clear();
  EXPECT_EQ(report::rao_text(result, {}, context).find("not refined"), std::string::npos);
  EXPECT_EQ(report::rao_markdown(result, {}, context, false).find("not refined"), std::string::npos);
}

TEST(StagedDirectory, OutputIsCompleteOrAbsent) {
  const fs::path root = fs::temp_directory_path() / ("ffrf-report-test-" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path target = root / "out";
  {
    report::StagedDirectory out(target, "summary.json");
    out.write("data.csv", "a,b\n");
    out.write("summary.json", "{}\n");
  }  // no commit: an error happened
  EXPECT_FALSE(fs::exists(target));
  EXPECT_FALSE(fs::exists(root)) << "no staging directory is left behind, nor the parent it created";
  {
    report::StagedDirectory out(target, "summary.json");
    out.write("data.csv", "a,b\n");
    out.write("summary.json", "{}\n");
    out.commit();
  }
  EXPECT_TRUE(fs::exists(target / "data.csv"));
  EXPECT_TRUE(fs::exists(target / "summary.json"));
  {
    report::StagedDirectory again(target, "summary.json");  // a new run into the old directory
    EXPECT_FALSE(fs::exists(target / "summary.json")) << "the old marker no longer describes the directory";
  }
  fs::remove_all(root);
}

}  // namespace
