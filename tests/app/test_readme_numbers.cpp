// The README quotes the main job's verdict (the block "main-job-verdict", written by
// scripts/regenerate-docs.sh from a run of the main job). This test reruns the main job's compare —
// exactly `ffrf compare cases/paper_floating_crane.toml` as scripts/main-job.sh runs it — and checks
// every number of the block against the fresh summary.json to the precision it is printed with (a
// cell "2.46e-03" must be within half a unit of its last digit, 5e-06, of the computed value): the
// verdict sentence, and per model the elastic DOFs, the worst error and output, its static and
// dynamic parts, pass/fail and the solver-work speed-up. Wall times and the wall-time speed-ups vary
// with the machine's load and are not checked. A new column the test does not know fails it.
#include <cmath>
#include <regex>

#include "cli_harness.hpp"

namespace ffrf::test {
namespace readme_numbers_test {

// The lines between the block's BEGIN and END marks.
std::vector<std::string> readme_block(const std::string& id) {
  std::istringstream readme(read_text(source_file("README.md")));
  std::vector<std::string> lines;
  bool inside = false, found = false;
  for (std::string line; std::getline(readme, line);) {
    if (line.rfind("<!-- END generated: " + id + " ", 0) == 0) inside = false;
    if (inside) lines.push_back(line);
    if (line.rfind("<!-- BEGIN generated: " + id + " ", 0) == 0) inside = found = true;
  }
  EXPECT_TRUE(found) << "README.md has no block " << id;
  return lines;
}

std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string cell;
  for (std::size_t i = 1; i < row.size(); ++i) {
    if (row[i] == '|') {
      const auto first = cell.find_first_not_of(' '), last = cell.find_last_not_of(' ');
      out.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
      cell.clear();
    } else {
      cell += row[i];
    }
  }
  return out;
}

// The printed number of a cell ("2.46e-03", "7.5×", "14") and half a unit of its last digit.
struct Printed {
  double value = NAN;
  double half_unit = NAN;
};

Printed printed(std::string text) {
  const std::string times = "×";
  if (text.size() > times.size() && text.compare(text.size() - times.size(), times.size(), times) == 0) {
    text.resize(text.size() - times.size());
  }
  Printed p;
  std::size_t used = 0;
  p.value = std::stod(text, &used);
  EXPECT_EQ(used, text.size()) << "not a number: " << text;
  const std::size_t e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
  const std::size_t dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  p.half_unit = 0.5 * std::pow(10.0, exponent - decimals);
  return p;
}

void expect_printed(const std::string& cell, double computed, const std::string& what) {
  const Printed p = printed(cell);
  EXPECT_LE(std::abs(computed - p.value), p.half_unit * (1.0 + 1e-9))
      << what << ": README says " << cell << ", the main job gives " << computed;
}

// The sentence with every "N× less/more wall time" replaced by a mark (timings vary).
std::string without_wall_time(const std::string& sentence) {
  static const std::regex wall(R"([0-9.]+× (less|more) wall time|wall time [0-9.]+× (less|more))");
  return std::regex_replace(sentence, wall, "(wall time)");
}

TEST(ReadmeNumbers, TheMainJobsCompareGivesEveryNumberTheReadmeQuotes) {
  const std::vector<std::string> block = readme_block("main-job-verdict");
  ASSERT_FALSE(block.empty());
  TempDir dir;
  const fs::path out = dir / "compare";
  const RunResult r = run_ffrf("compare '" + source_file("cases/paper_floating_crane.toml") + "' --out '" + out.string() + "'",
                               dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json json = JsonParser(read_text(out / "summary.json")).parse();
  const Json& verdict = json["verdict"];

  // The verdict sentence, word for word but the wall-time ratio.
  std::string sentence;
  for (const std::string& line : block) {
    if (line.size() > 4 && line.rfind("**", 0) == 0) sentence = line.substr(2, line.size() - 4);
  }
  ASSERT_FALSE(sentence.empty()) << "no verdict sentence in the README block";
  EXPECT_EQ(without_wall_time(sentence), without_wall_time(verdict["sentence"].text));

  // The table: header, rule, one row per model and the reference.
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : block) {
    if (line.rfind("|", 0) == 0) rows.push_back(cells(line));
  }
  ASSERT_GE(rows.size(), 3u);
  const std::vector<std::string> header = rows[0];
  std::size_t checked_models = 0;
  for (std::size_t i = 2; i < rows.size(); ++i) {
    const std::vector<std::string>& row = rows[i];
    ASSERT_EQ(row.size(), header.size()) << row[0];
    std::string label = row[0];
    if (label.rfind("**", 0) == 0) label = label.substr(2, label.size() - 4);
    const bool reference = label.rfind("reference", 0) == 0;
    const Json* model = nullptr;
    for (const Json& m : json["models"].items) {
      if (m["model"].text == label) model = &m;
    }
    if (!reference) {
      ASSERT_NE(model, nullptr) << "the README names a model the main job does not run: " << label;
      ++checked_models;
    } else {
      EXPECT_EQ(label, "reference (" + json["reference"]["model"].text + ", rtol " + row[0].substr(row[0].find("rtol ") + 5));
    }
    for (std::size_t c = 1; c < header.size(); ++c) {
      const std::string& name = header[c];
      const std::string& cell = row[c];
      const std::string what = label + ", " + name;
      if (name.find("wall") != std::string::npos) continue;  // timings: not checked
      if (reference) {
        if (name == "elastic DOFs") EXPECT_EQ(std::stoi(cell), 3 * static_cast<int>(json["reference"]["levels"].items.back()["elements"].number));
        else if (name == "speed-up (work)") EXPECT_EQ(cell, "1×");
        else EXPECT_EQ(cell, "-") << what;
        continue;
      }
      const Json& errors = (*model)["errors_to_reference"];
      const std::string worst = errors["worst_output"].text;
      if (name == "elastic DOFs") {
        EXPECT_EQ(std::stoi(cell), static_cast<int>((*model)["elastic_dof"].number)) << what;
      } else if (name == "worst error") {
        expect_printed(cell, errors["worst_normalized_rms"].number, what);
      } else if (name == "worst output") {
        EXPECT_EQ(cell, worst) << what;
      } else if (name == "its static error") {
        expect_printed(cell, errors[worst]["static_error"].number, what);
      } else if (name == "its dynamic error") {
        expect_printed(cell, errors[worst]["dynamic_error"].number, what);
      } else if (name.rfind("τ = ", 0) == 0) {
        expect_printed(name.substr(std::string("τ = ").size()), verdict["tolerance"].number, "the tolerance");
        EXPECT_EQ(cell, (*model)["verdict"]["passed"].flag ? "pass" : "FAIL") << what;
      } else if (name == "speed-up (work)") {
        expect_printed(cell, (*model)["verdict"]["work_speedup"].number, what);
      } else {
        ADD_FAILURE() << "the README's verdict table has a column this test does not check: " << name;
      }
    }
  }
  EXPECT_EQ(checked_models, json["models"].items.size()) << "every model of the main job is in the README's table";
}

}  // namespace readme_numbers_test
}  // namespace ffrf::test
