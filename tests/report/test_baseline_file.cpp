// The baseline file (report/baseline_file.hpp) against independent facts: a document read back
// gives every recorded double bit for bit (numbers that need all 17 digits included); each kind of
// malformed file is refused with an error naming the file, the key, the value and the problem; the
// scene fingerprint is FNV-1a 64 (published test vectors: "" → cbf29ce484222325, "a" →
// af63dc4c8601ec8c, "foobar" → 85944171f73967e8).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "report/baseline_file.hpp"

namespace {

using namespace ffrf;
namespace fs = std::filesystem;

report::BaselineFile sample_file() {
  report::BaselineFile file;
  file.provenance = {"0.1.0", "0123456789abcdef0123456789abcdef01234567", "2025-01-31T12:00:00Z", "cases/x.toml", "x",
                     "fnv1a64:0000000000000001"};
  study::Baseline& b = file.baseline;
  b.model.choice = {scene::BoomKind::modal, 16, 2, true};
  b.model.choice.stiffening = scene::Stiffening::static_load;
  b.model.integrator = solve::Integrator::ida;
  b.model.relative_tolerance = 1e-7;
  b.model.absolute_tolerance = 3e-8;
  b.model.duration = 40.0;
  b.model.output_interval = 0.05;
  b.model.fixed_step = 0.0;
  b.model.max_order = 4;
  b.cost.steps = 1234;
  b.cost.function_evaluations = 5678;
  b.cost.wall_seconds = 0.125;
  b.boom_elements = 16;
  b.boom_frequencies = {{1.0 / 3.0, "bending", 1}, {0.1 + 0.2, "axial", 1}};
  b.coupled_modes = {{1.0 / 35.6, 0.0196, "hull surge"}, {std::nextafter(0.7, 1.0), 1.0 / 3.0 * 0.1, "boom"}};
  b.window_start = 20.05;
  b.window_after_ramp = true;
  b.wire_amplification = 1.0 + 1.0 / 7.0;
  b.decimation = 3;
  b.history_time = {0.0, 0.15, 0.30000000000000004};
  study::ChannelBaseline c;
  c.name = "wire_tension_N";
  c.unit = "N";
  c.static_value = 12753000.000000002;
  c.min = -1e-300;
  c.max = 2.0 / 3.0 * 1e7;
  c.mean = std::nextafter(1.0, 2.0);
  c.rms = 5e-324;  // the smallest subnormal
  c.standard_deviation = 0.1;
  c.history = {1.0 / 9.0, -0.0, 6.02214076e23};
  b.channels = {c};
  return file;
}

// The error of parsing `text`, or "" when it parses.
std::string parse_error(const std::string& text) {
  try {
    report::parse_baseline(text, "base.json");
  } catch (const report::BaselineFileError& error) {
    return error.what();
  }
  return "";
}

// The sample document with `from` replaced by `to` (once; the test fails when `from` is absent).
std::string edited(const std::string& from, const std::string& to) {
  std::string text = report::baseline_json(sample_file());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(BaselineFile, ReadsBackEveryValueBitForBit) {
  const report::BaselineFile file = sample_file();
  const report::BaselineFile back = report::parse_baseline(report::baseline_json(file), "mem");
  EXPECT_EQ(back.provenance.git_commit, file.provenance.git_commit);
  EXPECT_EQ(back.provenance.scene_hash, file.provenance.scene_hash);
  const study::Baseline& a = file.baseline;
  const study::Baseline& b = back.baseline;
  EXPECT_EQ(b.model.choice.label(), a.model.choice.label());
  EXPECT_EQ(b.model.choice.stiffening, a.model.choice.stiffening);
  EXPECT_EQ(b.model.integrator, a.model.integrator);
  EXPECT_EQ(b.model.relative_tolerance, a.model.relative_tolerance);
  EXPECT_EQ(b.model.absolute_tolerance, a.model.absolute_tolerance);
  EXPECT_EQ(b.model.max_order, 4);
  EXPECT_EQ(b.cost.steps, 1234);
  ASSERT_EQ(b.boom_frequencies.size(), 2u);
  EXPECT_EQ(b.boom_frequencies[0].hz, 1.0 / 3.0);
  EXPECT_EQ(b.boom_frequencies[1].hz, 0.1 + 0.2);
  EXPECT_EQ(b.boom_frequencies[1].kind, "axial");
  ASSERT_EQ(b.coupled_modes.size(), 2u);
  EXPECT_EQ(b.coupled_modes[0].hz, 1.0 / 35.6);
  EXPECT_EQ(b.coupled_modes[1].hz, std::nextafter(0.7, 1.0));
  EXPECT_EQ(b.coupled_modes[1].damping_ratio, 1.0 / 3.0 * 0.1);
  EXPECT_EQ(b.coupled_modes[1].dominant, "boom");
  EXPECT_EQ(*b.wire_amplification, 1.0 + 1.0 / 7.0);
  EXPECT_EQ(b.decimation, 3);
  EXPECT_EQ(b.history_time, a.history_time);
  ASSERT_EQ(b.channels.size(), 1u);
  const study::ChannelBaseline& c = b.channels[0];
  EXPECT_EQ(c.static_value, a.channels[0].static_value);
  EXPECT_EQ(c.min, -1e-300);
  EXPECT_EQ(c.max, 2.0 / 3.0 * 1e7);
  EXPECT_EQ(c.mean, std::nextafter(1.0, 2.0));
  EXPECT_EQ(c.rms, 5e-324);
  EXPECT_EQ(c.history, a.channels[0].history);
  EXPECT_TRUE(std::signbit(c.history[1])) << "-0.0 keeps its sign";

  report::BaselineFile measured = file;
  measured.baseline.integration_error = study::IntegrationError{1e-8, 1e-8, 0.0, 2313, 2.0 / 3.0 * 1e-5, "wire_tension_N", "min", ""};
  const auto error = report::parse_baseline(report::baseline_json(measured), "mem").baseline.integration_error;
  ASSERT_TRUE(error.has_value());
  EXPECT_TRUE(error->measured());
  EXPECT_EQ(error->largest, 2.0 / 3.0 * 1e-5);
  EXPECT_EQ(error->steps, 2313);
  EXPECT_EQ(error->quantity, "min");
  report::BaselineFile failed = file;
  failed.baseline.integration_error = study::IntegrationError{};
  failed.baseline.integration_error->problem = "the tighter runs failed: CVODE ...";
  const auto unmeasured = report::parse_baseline(report::baseline_json(failed), "mem").baseline.integration_error;
  ASSERT_TRUE(unmeasured.has_value());
  EXPECT_FALSE(unmeasured->measured());
  EXPECT_EQ(unmeasured->problem, "the tighter runs failed: CVODE ...");

  report::BaselineFile calm = file;
  calm.baseline.wire_amplification.reset();
  EXPECT_FALSE(report::parse_baseline(report::baseline_json(calm), "mem").baseline.wire_amplification.has_value());
}

// A baseline of format version 1 (before the coupled modes were recorded) still reads: the same
// document without "coupled_modes", with no coupled modes to check; a hub scene's (null) neither.
TEST(BaselineFile, ReadsFormatVersionOneWithoutCoupledModes) {
  report::BaselineFile file = sample_file();
  std::string text = report::baseline_json(file);
  const std::size_t start = text.find("  \"coupled_modes\": {");
  const std::size_t end = text.find("  \"integration_error\"");
  ASSERT_NE(start, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  text.erase(start, end - start);
  text.replace(text.find("\"format_version\": 2"), 19, "\"format_version\": 1");
  const report::BaselineFile old = report::parse_baseline(text, "old.json");
  EXPECT_TRUE(old.baseline.coupled_modes.empty());
  EXPECT_EQ(old.baseline.boom_frequencies.size(), 2u);
  EXPECT_EQ(old.baseline.channels.size(), 1u);
  // Version 2 requires the key (null without a hull).
  EXPECT_NE(parse_error(text.replace(text.find("\"format_version\": 1"), 19, "\"format_version\": 2")).find("coupled_modes"),
            std::string::npos);
  file.baseline.coupled_modes.clear();
  EXPECT_TRUE(report::parse_baseline(report::baseline_json(file), "hub.json").baseline.coupled_modes.empty());
}

TEST(BaselineFile, MalformedFilesAreNamedWithKeyValueAndProblem) {
  EXPECT_EQ(parse_error(report::baseline_json(sample_file())), "");
  EXPECT_EQ(parse_error("{\"format\": \"ffrf-baseline\", ").substr(0, 52), "base.json: not a JSON document (parse error at byte ");
  EXPECT_EQ(parse_error("[1, 2]"), "base.json: not a baseline: the document is not a JSON object");
  EXPECT_EQ(parse_error(edited("\"ffrf-baseline\"", "\"ffrf-summary\"")),
            "base.json: format = \"ffrf-summary\": not an ffrf baseline (expected \"ffrf-baseline\")");
  EXPECT_EQ(parse_error(edited("\"format_version\": 2", "\"format_version\": 3")),
            "base.json: format_version = 3: this ffrf reads baseline format versions 1 to 2; record the baseline again");
  EXPECT_EQ(parse_error(edited("\"rtol\": 1e-07,", "")), "base.json: model.rtol = (missing): a required key is missing");
  EXPECT_EQ(parse_error(edited("\"rtol\": 1e-07", "\"rtol\": 2.0")),
            "base.json: model.rtol = 2.0: out of range (valid range (0, 1))");
  EXPECT_EQ(parse_error(edited("\"integrator\": \"ida\"", "\"integrator\": \"euler\"")),
            "base.json: model.integrator = \"euler\": unknown integrator (valid: " + solve::integrator_choices() + ")");
  EXPECT_EQ(parse_error(edited("\"max_bdf_order\": 4", "\"max_bdf_order\": 6")),
            "base.json: model.max_bdf_order = 6: out of range (valid range [1, 5])");
  EXPECT_EQ(parse_error(edited("\"mean\": 1.0000000000000002", "\"mean\": \"abc\"")),
            "base.json: channels[0].mean = \"abc\": not a number");
  EXPECT_EQ(parse_error(edited("\"name\": \"wire_tension_N\"", "\"name\": \"wire_tension_kN\"")).substr(0, 78),
            "base.json: channels[0].name = \"wire_tension_kN\": not an output column (valid: ");
  EXPECT_EQ(parse_error(edited("\"min\": -1e-300", "\"min\": 1e300")),
            "base.json: channels[0].min = 1e+300: larger than max = 6666666.666666666");
  EXPECT_EQ(parse_error(edited("0.30000000000000004\n", "0.1\n")), "base.json: history.time_s[2] = 0.1: times must increase");
  EXPECT_EQ(parse_error(edited("6.02214076e+23\n", "6.02214076e+23, 1.0\n")),
            "base.json: channels[0].history = [0.1111111111111111,-0.0,6.02214076e+23,1.0]: 4 samples, but "
            "history.time_s has 3");
  EXPECT_EQ(parse_error(edited("\"integration_error\": null", "\"integration_error\": {\"problem\": \"\"}")),
            "base.json: integration_error.problem = \"\": empty: say why the error was not measured");
  EXPECT_EQ(parse_error(edited("\"integration_error\": null", "\"integration_error\": {\"rtol\": 1e-8}")),
            "base.json: integration_error.atol = (missing): a required key is missing");
  EXPECT_EQ(parse_error(edited("\"hz\": 0.3333333333333333", "\"hz\": -1")),
            "base.json: boom_frequencies.modes[0].hz = -1: out of range (valid range (0, inf) Hz)");
}

TEST(BaselineFile, MissingFileIsNamed) {
  const std::string path = (fs::temp_directory_path() / ("ffrf-no-such-" + std::to_string(::getpid()) + ".json")).string();
  try {
    report::read_baseline(path);
    FAIL() << "read a missing file";
  } catch (const report::BaselineFileError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(std::string(error.what()), path + ": no such baseline file");
  }
}

TEST(BaselineFile, WrittenFileReadsBackAndLeavesNothingElse) {
  const fs::path dir = fs::temp_directory_path() / ("ffrf-baseline-file-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "b.json").string();
  report::write_baseline(path, report::baseline_json(sample_file()));
  EXPECT_EQ(report::read_baseline(path).baseline.channels[0].max, 2.0 / 3.0 * 1e7);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "no temporary file left";
  EXPECT_THROW(report::write_baseline((dir / "missing" / "b.json").string(), "{}"), std::runtime_error);
  fs::remove_all(dir);
}

TEST(BaselineFile, SceneHashIsFnv1a64) {
  const fs::path dir = fs::temp_directory_path() / ("ffrf-hash-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto hash_of = [&](const std::string& content) {
    std::ofstream(dir / "scene.toml", std::ios::binary) << content;
    return report::scene_file_hash((dir / "scene.toml").string());
  };
  EXPECT_EQ(hash_of(""), "fnv1a64:cbf29ce484222325");
  EXPECT_EQ(hash_of("a"), "fnv1a64:af63dc4c8601ec8c");
  EXPECT_EQ(hash_of("foobar"), "fnv1a64:85944171f73967e8");
  fs::remove_all(dir);
  EXPECT_THROW(report::scene_file_hash((dir / "scene.toml").string()), report::BaselineFileError);
}

}  // namespace
