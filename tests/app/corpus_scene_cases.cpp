// The bad-input corpus, scene part, in process: every generated case (bad_input_corpus.hpp) goes
// through the loader — the path `ffrf check` and every command take before any work (a SceneError
// is exit 2) — and must come back as a problem naming the file, the line, the key, the value as
// written and the valid range (or the choices), with no other exception and within 30 s.
#include <chrono>
#include <fmt/format.h>

#include "bad_input_corpus.hpp"
#include "scene/scene_loader.hpp"

namespace ffrf::test {

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    if (end == text.size()) break;
    start = end + 1;
  }
  return lines;
}

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t");
  return first == std::string::npos ? std::string() : line.substr(first);
}

// The line declares `leaf` ("leaf = ..." or "leaf=...").
bool declares(const std::string& line, std::string_view leaf) {
  const std::string t = trimmed(line);
  if (t.rfind(leaf, 0) != 0 || t.size() == leaf.size()) return false;
  const char next = t[leaf.size()];
  return next == ' ' || next == '=' || next == '\t';
}

std::string number(double value) { return fmt::format("{:g}", value); }

// A value of the key's display unit ("\"900 deg\"" for an angle), else the plain SI number.
std::string in_unit(const scene::KeySpec& key, double si) {
  if (!scene::unit_required(key.dimension)) return number(si);
  return fmt::format("\"{} {}\"", number(si / scene::unit_factor(key.display_unit, key.dimension)), key.display_unit);
}

std::string case_name(std::string_view key, std::string_view kind) {
  std::string name = fmt::format("{}_{}", key, kind);
  for (char& c : name) c = c == '.' ? '_' : c;
  return name;
}

}  // namespace

std::string base_scene_for(const scene::KeySpec& key) {
  return read_text(source_file(key.section() == "hub" ? "cases/dropped_load.toml" : "cases/paper_floating_crane.toml"));
}

EditedScene with_key(const std::string& text, const scene::KeySpec& key, const std::string& value) {
  std::vector<std::string> lines = lines_of(text);
  const std::string header = "[" + std::string(key.section()) + "]";
  // Drop the other members of a one-of group (boom.mass_per_length when boom.density is written).
  if (key.presence == scene::Presence::one_of) {
    for (const scene::KeySpec& other : scene::scene_keys()) {
      if (other.one_of != key.one_of || other.name == key.name) continue;
      std::erase_if(lines, [&](const std::string& line) { return declares(line, other.leaf()); });
    }
  }
  const std::string written = std::string(key.leaf()) + " = " + value;
  std::size_t at = lines.size();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (trimmed(lines[i]).rfind(header, 0) == 0) at = i;
  }
  if (at == lines.size()) {
    lines.push_back(header);
    lines.push_back(written);
    at = lines.size() - 1;
  } else {
    std::size_t line = at + 1;
    while (line < lines.size() && trimmed(lines[line]).rfind('[', 0) != 0 && !declares(lines[line], key.leaf())) ++line;
    if (line < lines.size() && declares(lines[line], key.leaf())) {
      lines[line] = written;
      at = line;
    } else {
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at + 1), written);
      at = at + 1;
    }
  }
  std::string edited;
  for (const std::string& line : lines) edited += line + "\n";
  return {edited, static_cast<int>(at + 1), value};
}

std::vector<SceneCase> generated_scene_cases() {
  std::vector<SceneCase> cases;
  for (const scene::KeySpec& key : scene::scene_keys()) {
    const std::string base = base_scene_for(key);
    const std::string name(key.name);
    const auto add = [&](std::string_view kind, const std::string& value, std::string expected) {
      cases.push_back({case_name(name, kind), name, with_key(base, key, value), std::move(expected)});
    };
    const std::string range = "valid range " + scene::format_range(key);
    switch (key.kind) {
      case scene::ValueKind::number: {
        const scene::Range& r = key.range;
        add("above_range", in_unit(key, r.upper.value > 0.0 ? 10.0 * r.upper.value + 1.0 : r.upper.value + 1000.0), range);
        add("below_range", in_unit(key, r.lower.value - std::max(1.0, std::abs(r.lower.value))), range);
        add("nan", "nan", range);
        add("text", "\"abc\"", range);
        add("other_dimension", key.dimension == scene::Dimension::mass ? "\"5 m\"" : "\"5 kg\"", range);
        if (scene::unit_required(key.dimension)) add("bare_number", "1.0", range);
        break;
      }
      case scene::ValueKind::integer:
        add("two_to_the_32_plus_1", "4294967297", range);
        add("negative", "-1", range);
        add("fraction", "2.5", range);
        add("text", "\"x\"", range);
        break;
      case scene::ValueKind::choice: {
        std::string choices(key.choices);
        for (std::size_t bar = choices.find('|'); bar != std::string::npos; bar = choices.find('|')) {
          choices.replace(bar, 1, ", ");
        }
        add("unknown_keyword", "\"nonsense\"", "choose one of " + choices);
        add("number", "5", "choose one of " + choices);
        break;
      }
      case scene::ValueKind::text:
        add("number", "5", "expected a text string");
        break;
      case scene::ValueKind::number_list: {
        const scene::Range& r = key.range;
        add("element_above_range", fmt::format("[{}]", number(10.0 * r.upper.value + 1.0)), range);
        add("element_nan", "[nan]", range);
        add("element_text", "[\"abc\"]", range);
        add("not_an_array", "5", range);
        break;
      }
    }
  }
  return cases;
}

namespace {

class CorpusScene : public ::testing::TestWithParam<SceneCase> {};

TEST_P(CorpusScene, LoaderNamesFileLineKeyValueAndRange) {
  const SceneCase& bad = GetParam();
  const auto start = std::chrono::steady_clock::now();
  std::vector<scene::SceneProblem> problems;
  try {
    (void)scene::load_scene_text(bad.scene.text, "corpus.toml");
    ADD_FAILURE() << "accepted: " << bad.key << " = " << bad.scene.written;
  } catch (const scene::SceneError& error) {
    problems = error.problems();
  } catch (const std::exception& error) {
    ADD_FAILURE() << "not a SceneError (exit 2) but: " << error.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
  const auto found = std::find_if(problems.begin(), problems.end(), [&](const scene::SceneProblem& p) {
    return p.key == bad.key && p.message.find(bad.expected) != std::string::npos;
  });
  ASSERT_NE(found, problems.end()) << "no problem at " << bad.key << " with '" << bad.expected << "' in:\n"
                                   << (problems.empty() ? std::string("(none)") : scene::SceneError(problems).what());
  EXPECT_EQ(found->line, bad.scene.line);
  EXPECT_EQ(found->value, bad.scene.written);
  const std::string shown = scene::format_problem(*found);
  EXPECT_EQ(shown.rfind(fmt::format("corpus.toml:{}: {} = {}: ", bad.scene.line, bad.key, bad.scene.written), 0), 0u)
      << shown;
  for (const std::string& text : kBareLibraryText) EXPECT_EQ(shown.find(text), std::string::npos) << shown;
}

INSTANTIATE_TEST_SUITE_P(Generated, CorpusScene, ::testing::ValuesIn(generated_scene_cases()),
                         [](const ::testing::TestParamInfo<SceneCase>& case_info) { return case_info.param.name; });

TEST(CorpusScene, EveryKeyHasItsCases) {
  // Generated from the schema: a key added to the table gets its cases here without further work.
  const auto cases = generated_scene_cases();
  for (const scene::KeySpec& key : scene::scene_keys()) {
    const auto count = std::count_if(cases.begin(), cases.end(), [&](const SceneCase& c) { return c.key == key.name; });
    EXPECT_GE(count, 1) << key.name;
  }
  EXPECT_GE(cases.size(), 100u);
}

}  // namespace
}  // namespace ffrf::test
