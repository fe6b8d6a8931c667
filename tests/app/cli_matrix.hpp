// The command-line matrix: every command that takes --out, run on each kind of shipped scene (a
// floating crane, a hub, a hull with BEM coefficients, an irregular sea, a pinned boom on luffing wires,
// and on an A-frame held by backstays) with each boom kind where the
// command takes one, must exit 0 and leave a complete output directory. "Complete" is checked against
// what the command itself says it wrote, not against a list kept here:
//   * every file is non-empty, and nothing of a staging directory is left beside the target;
//   * summary.json's "charts": every chart drawn is a PNG; a chart left out has neither script nor
//     PNG; a chart gnuplot failed on keeps its script and has no PNG; every NAME.gp in the directory
//     has its NAME.png unless the chart is listed as failed;
//   * every chart left out or failed is named on stderr, and in report.md where the command writes one;
//   * every file report.md (or recommendation.md) links or quotes in backticks exists and is
//     non-empty, unless it is a chart the report lists under "Charts not drawn";
//   * no console line and no report's prose says nan or inf (a number ffrf has not got is printed
//     as "-"; the hidden context comments of a report are data, not prose).
// A combination that is not meaningful (a frequency-domain or sea-state study of a hub, which has no
// water) is a cell too: the command must refuse it with exit 2 and write nothing.
#pragma once

#include <regex>
#include <set>
#include <string>
#include <vector>

#include "cli_harness.hpp"

namespace ffrf::test {

struct MatrixScene {
  const char* kind;  // "crane", "hub", "bem", "irregular", "pinned", "a_frame"
  const char* file;  // under cases/
};

inline const std::vector<MatrixScene>& matrix_scenes() {
  static const std::vector<MatrixScene> scenes{{"crane", "paper_floating_crane.toml"},
                                               {"hub", "spin_up_beam.toml"},
                                               {"bem", "bem_barge_crane.toml"},
                                               {"irregular", "irregular_sea_crane.toml"},
                                               {"pinned", "pinned_luffing_crane.toml"},
                                               {"a_frame", "a_frame_crane.toml"}};
  return scenes;
}

struct MatrixCell {
  std::string command;  // "run", "baseline record", ...
  MatrixScene scene;
  std::string boom;     // "rigid", "nodal", "modal"; empty: the command has no boom option
  std::string args;     // short durations, small grids
  bool refused = false; // not meaningful for this scene: exit 2, nothing written
  bool out_is_file = false;  // baseline record --out FILE
};

inline std::string cell_name(const MatrixCell& c) {
  std::string name = c.command + "_" + c.scene.kind + (c.boom.empty() ? "" : "_" + c.boom);
  for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name;
}

inline void PrintTo(const MatrixCell& c, std::ostream* os) {
  *os << c.command << ' ' << c.scene.file << (c.boom.empty() ? "" : " --boom " + c.boom) << ' ' << c.args;
}

// Appends every cell of `command` over the scenes: with each boom kind when `booms`, else once per scene.
inline void add_cells(std::vector<MatrixCell>& cells, const std::string& command, bool booms, const std::string& args,
                      const std::set<std::string>& refused_kinds = {}, bool out_is_file = false) {
  for (const MatrixScene& scene : matrix_scenes()) {
    const bool refused = refused_kinds.count(scene.kind) > 0;
    if (!booms || refused) {
      cells.push_back({command, scene, "", args, refused, out_is_file});
      continue;
    }
    for (const char* boom : {"rigid", "nodal", "modal"}) cells.push_back({command, scene, boom, args, false, out_is_file});
  }
}

inline bool is_png_file(const fs::path& path) {
  const std::string bytes = read_text(path);
  return bytes.size() > 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

inline void expect_no_nan(const std::string& text, const std::string& where) {
  static const std::regex not_a_number(R"((^|[^A-Za-z_])(-?nan|-?inf)([^A-Za-z_]|$))", std::regex::icase);
  std::smatch match;
  if (std::regex_search(text, match, not_a_number)) {
    const auto at = static_cast<std::size_t>(match.position(0));
    const std::size_t line_start = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
    ADD_FAILURE() << where << " prints '" << match.str(2) << "': " << text.substr(line_start, text.find('\n', at) - line_start);
  }
}

// The output directory of a finished command against what it says it wrote (see the file comment).
inline void expect_complete_output(const fs::path& out, const RunResult& run) {
  ASSERT_TRUE(fs::is_directory(out)) << out << " missing";
  for (const auto& entry : fs::directory_iterator(out.parent_path())) {
    EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << "staging left: " << entry.path();
  }
  std::set<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    if (!entry.is_regular_file()) continue;
    files.insert(fs::relative(entry.path(), out).string());
    EXPECT_GT(entry.file_size(), 0u) << entry.path() << " is empty";
  }
  std::set<std::string> drawn, left_out, failed;
  if (files.count("summary.json")) {
    const Json summary = JsonParser(read_text(out / "summary.json")).parse();
    bool has_charts = false;
    for (const auto& [key, value] : summary.members) has_charts = has_charts || key == "charts";
    if (has_charts) {
      const Json& charts = summary["charts"];
      for (const Json& png : charts["drawn"].items) drawn.insert(png.text);
      for (const Json& c : charts["left_out"].items) left_out.insert(c["chart"].text);
      for (const Json& c : charts["failed"].items) failed.insert(c["chart"].text);
    }
  }
  const std::string report = files.count("report.md") ? read_text(out / "report.md") : std::string();
  for (const std::string& png : drawn) EXPECT_TRUE(is_png_file(out / png)) << png << " listed as drawn is not a PNG";
  for (const std::string& png : left_out) {
    const std::string script = png.substr(0, png.size() - 4) + ".gp";
    EXPECT_FALSE(files.count(png) || files.count(script)) << png << " is listed as left out but has a file";
    EXPECT_NE(run.err.find("chart " + png + " left out"), std::string::npos) << "stderr does not name " << png << ":\n" << run.err;
    if (!report.empty()) {
      EXPECT_NE(report.find("`" + png + "` left out"), std::string::npos) << "report.md does not name " << png;
    }
  }
  for (const std::string& png : failed) {
    EXPECT_FALSE(files.count(png)) << png << " failed but a PNG is there";
    EXPECT_NE(run.err.find("chart " + png + " not drawn"), std::string::npos) << "stderr does not name " << png;
  }
  for (const std::string& file : files) {
    if (file.size() < 3 || file.compare(file.size() - 3, 3, ".gp") != 0) continue;
    const std::string png = file.substr(0, file.size() - 3) + ".png";
    EXPECT_TRUE(files.count(png) || failed.count(png)) << file << " has no " << png << " and the report does not say why";
  }
  // The files the reports name (links and `quoted` names of this directory).
  static const std::regex named(R"((?:`|\]\()([A-Za-z0-9_.+=-]+\.(?:png|csv|json|gp|dat|md|tsv|txt))(?:`|\)))");
  for (const char* name : {"report.md", "recommendation.md"}) {
    if (!files.count(name)) continue;
    const std::string text = read_text(out / name);
    for (std::sregex_iterator it(text.begin(), text.end(), named), end; it != end; ++it) {
      const std::string file = (*it)[1].str();
      if (left_out.count(file) || failed.count(file)) continue;
      if (file.rfind("NAME.", 0) == 0) continue;  // a pattern the report explains (`NAME.gp`), not a file
      EXPECT_TRUE(files.count(file)) << name << " names " << file << ", which is not in " << out;
    }
    // The hidden context lines (<!-- key: value -->) are data read back by `sweep --merge`, not prose.
    expect_no_nan(std::regex_replace(text, std::regex(R"(<!--[^>]*-->)"), ""), name);
  }
  expect_no_nan(run.out, "stdout");
  expect_no_nan(run.err, "stderr");
}

inline void run_matrix_cell(const MatrixCell& c) {
  TempDir dir;
  const fs::path out = dir / (c.out_is_file ? "baseline.json" : "out");
  const std::string args = c.command + " '" + source_file("cases/" + std::string(c.scene.file)) + "'" +
                           (c.boom.empty() ? "" : " --boom " + c.boom) + " " + c.args + " --out '" + out.string() + "'";
  const RunResult run = run_ffrf(args, dir.path());
  if (c.refused) {
    EXPECT_EQ(run.exit_code, 2) << "ffrf " << args << " should refuse this scene\n" << run.err;
    EXPECT_FALSE(fs::exists(out)) << "a refused command wrote " << out;
    return;
  }
  ASSERT_EQ(run.exit_code, 0) << "ffrf " << args << "\nstderr:\n" << run.err << "\nstdout:\n" << run.out;
  if (c.out_is_file) {
    ASSERT_TRUE(fs::is_regular_file(out)) << out << " missing";
    EXPECT_GT(fs::file_size(out), 0u);
    EXPECT_NO_THROW(JsonParser(read_text(out)).parse()) << out << " is not one JSON document";
    expect_no_nan(run.out, "stdout");
    expect_no_nan(run.err, "stderr");
    return;
  }
  expect_complete_output(out, run);
}

}  // namespace ffrf::test
