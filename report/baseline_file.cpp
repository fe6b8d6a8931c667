// The regression-baseline file: JSON writer and reader with named errors (see baseline_file.hpp).
#include "report/baseline_file.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "report/git_commit.hpp"
#include "report/json.hpp"
#include "report/run_report.hpp"

namespace ffrf::report {

namespace {

constexpr const char* format_name = "ffrf-baseline";

// One value of the document being read, with its key path for errors ("channels[2].min").
class Node {
 public:
  Node(const Json& json, std::string key, const std::string& file) : json_(json), key_(std::move(key)), file_(file) {}

  [[noreturn]] void fail(const std::string& problem) const {
    std::string value = json_.dump();
    if (value.size() > 60) value = value.substr(0, 57) + "...";
    throw BaselineFileError(file_, key_, value, problem);
  }
  Node at(const std::string& name) const {
    if (!json_.is_object()) fail("not an object");
    const auto found = json_.find(name);
    const std::string key = key_.empty() ? name : key_ + "." + name;
    if (found == json_.end()) throw BaselineFileError(file_, key, "(missing)", "a required key is missing");
    return Node(*found, key, file_);
  }
  Node at(std::size_t index) const { return Node(json_[index], fmt::format("{}[{}]", key_, index), file_); }
  std::size_t size() const {
    if (!json_.is_array()) fail("not an array");
    return json_.size();
  }
  bool is_null() const { return json_.is_null(); }
  bool has(const std::string& name) const { return json_.is_object() && json_.contains(name); }
  double number() const {
    if (!json_.is_number()) fail("not a number");
    return json_.get<double>();
  }
  // A number in [low, high] (open ends when `open`).
  double number(double low, double high, bool open, const char* unit = "") const {
    const double v = number();
    const bool inside = open ? (v > low && v < high) : (v >= low && v <= high);
    if (!inside || !std::isfinite(v)) fail(fmt::format("out of range (valid range {}{:g}, {:g}{}{}{})", open ? "(" : "[", low, high,
                                                       open ? ")" : "]", *unit ? " " : "", unit));
    return v;
  }
  int integer(int low, int high) const {
    if (!json_.is_number_integer()) fail("not an integer");
    const auto v = json_.get<long long>();
    if (v < low || v > high) fail(fmt::format("out of range (valid range [{}, {}])", low, high));
    return static_cast<int>(v);
  }
  long count() const {
    if (!json_.is_number_integer() || json_.get<long long>() < 0) fail("not a count (valid range [0, inf))");
    return static_cast<long>(json_.get<long long>());
  }
  std::string text() const {
    if (!json_.is_string()) fail("not a string");
    return json_.get<std::string>();
  }
  bool boolean() const {
    if (!json_.is_boolean()) fail("not true or false");
    return json_.get<bool>();
  }

 private:
  const Json& json_;
  std::string key_;
  const std::string& file_;
};

Json model_json(const study::BaselineModel& m) {
  Json model = Json{{"label", m.choice.label()},
              {"boom", scene::to_string(m.choice.kind)},
              {"elements", m.choice.elements},
              {"modes", m.choice.modes},
              {"static_modes", m.choice.static_modes},
              {"stiffening", scene::to_string(m.choice.stiffening.value_or(scene::Stiffening::none))},
              {"integrator", solve::to_string(m.integrator)},
              {"rtol", m.relative_tolerance},
              {"atol", m.absolute_tolerance},
              {"max_bdf_order", m.max_order},
              {"fixed_step_s", m.fixed_step},
              {"duration_s", m.duration},
              {"output_interval_s", m.output_interval}};
  // The mode set only when it is not the default (clamped-free): older files stay as they were.
  if (m.choice.mode_set != fem::Boundary::clamped_free) model["mode_set"] = std::string(fem::to_string(m.choice.mode_set));
  return model;
}

study::BaselineModel read_model(const Node& n) {
  study::BaselineModel m;
  const Node boom = n.at("boom");
  const auto kind = scene::parse_boom_kind(boom.text());
  if (!kind) boom.fail("unknown boom model (valid: " + scene::boom_kind_choices() + ")");
  m.choice.kind = *kind;
  m.choice.elements = n.at("elements").integer(1, 1'000'000);
  m.choice.modes = n.at("modes").integer(1, 3'000'000);
  m.choice.static_modes = n.at("static_modes").boolean();
  if (n.has("mode_set")) {
    const Node set = n.at("mode_set");
    const auto boundary = fem::parse_boundary(set.text());
    if (!boundary) set.fail("unknown mode set (valid: " + fem::boundary_choices() + ")");
    m.choice.mode_set = *boundary;
  }
  const Node stiffening = n.at("stiffening");
  m.choice.stiffening = scene::parse_stiffening(stiffening.text());
  if (!m.choice.stiffening) stiffening.fail("unknown stiffening (valid: none, static, centrifugal, both)");
  const Node integrator = n.at("integrator");
  const auto parsed = solve::parse_integrator(integrator.text());
  if (!parsed) integrator.fail("unknown integrator (valid: " + solve::integrator_choices() + ")");
  m.integrator = *parsed;
  m.relative_tolerance = n.at("rtol").number(0.0, 1.0, true);
  m.absolute_tolerance = n.at("atol").number(0.0, 1.0, true);
  m.max_order = n.at("max_bdf_order").integer(1, 5);
  m.fixed_step = n.at("fixed_step_s").number(0.0, INFINITY, false, "s");
  m.duration = n.at("duration_s").number(0.0, INFINITY, true, "s");
  m.output_interval = n.at("output_interval_s").number(0.0, INFINITY, true, "s");
  return m;
}

Json cost_json(const solve::SolverStats& s) {
  return Json{{"wall_time_s", s.wall_seconds},
              {"steps", s.steps},
              {"function_evaluations", s.function_evaluations},
              {"jacobian_evaluations", s.jacobian_evaluations},
              {"newton_iterations", s.newton_iterations},
              {"error_test_failures", s.error_test_failures},
              {"convergence_failures", s.convergence_failures}};
}

solve::SolverStats read_cost(const Node& n) {
  solve::SolverStats s;
  s.wall_seconds = n.at("wall_time_s").number(0.0, INFINITY, false, "s");
  s.steps = n.at("steps").count();
  s.function_evaluations = n.at("function_evaluations").count();
  s.jacobian_evaluations = n.at("jacobian_evaluations").count();
  s.newton_iterations = n.at("newton_iterations").count();
  s.error_test_failures = n.at("error_test_failures").count();
  s.convergence_failures = n.at("convergence_failures").count();
  return s;
}

Json channel_json(const study::ChannelBaseline& c) {
  return Json{{"name", c.name}, {"unit", c.unit}, {"about_static", c.about_static}, {"static_value", c.static_value},
              {"min", c.min},   {"max", c.max},   {"mean", c.mean},                 {"rms", c.rms},
              {"std", c.standard_deviation},      {"history", c.history}};
}

std::vector<double> read_numbers(const Node& n) {
  std::vector<double> values(n.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    values[i] = n.at(i).number();
    if (!std::isfinite(values[i])) n.at(i).fail("not a finite number");
  }
  return values;
}

study::ChannelBaseline read_channel(const Node& n, std::size_t samples) {
  study::ChannelBaseline c;
  const Node name = n.at("name");
  c.name = name.text();
  const std::optional<std::string> column = study::output_column(c.name);
  if (!column || *column != c.name) name.fail("not an output column (valid: " + study::output_columns() + ")");
  c.unit = n.at("unit").text();
  c.about_static = n.at("about_static").boolean();
  c.static_value = n.at("static_value").number();
  c.min = n.at("min").number();
  c.max = n.at("max").number();
  c.mean = n.at("mean").number();
  c.rms = n.at("rms").number(0.0, INFINITY, false);
  c.standard_deviation = n.at("std").number(0.0, INFINITY, false);
  if (c.min > c.max) n.at("min").fail(fmt::format("larger than max = {}", c.max));
  const Node history = n.at("history");
  c.history = read_numbers(history);
  if (c.history.size() != samples) history.fail(fmt::format("{} samples, but history.time_s has {}", c.history.size(), samples));
  return c;
}

study::Baseline read_baseline_body(const Node& root, long long version) {
  study::Baseline b;
  b.model = read_model(root.at("model"));
  b.cost = read_cost(root.at("cost"));
  const Node frequencies = root.at("boom_frequencies");
  b.boom_elements = frequencies.at("elements").integer(1, 1'000'000);
  const Node modes = frequencies.at("modes");
  for (std::size_t j = 0; j < modes.size(); ++j) {
    const Node mode = modes.at(j);
    b.boom_frequencies.push_back({mode.at("hz").number(0.0, INFINITY, true, "Hz"), mode.at("kind").text(),
                                  mode.at("order").integer(0, 1'000'000)});
  }
  if (version >= 2) {  // format 1 had no coupled modes
    const Node coupled = root.at("coupled_modes");
    if (!coupled.is_null()) {
      const Node list = coupled.at("modes");
      for (std::size_t j = 0; j < list.size(); ++j) {
        const Node mode = list.at(j);
        b.coupled_modes.push_back({mode.at("hz").number(0.0, INFINITY, true, "Hz"), mode.at("damping_ratio").number(-1.0, 1.0, false),
                                   mode.at("dominant").text()});
      }
    }
  }
  const Node error = root.at("integration_error");
  if (!error.is_null() && error.has("problem")) {
    study::IntegrationError e;
    e.problem = error.at("problem").text();
    if (e.problem.empty()) error.at("problem").fail("empty: say why the error was not measured");
    b.integration_error = e;
  } else if (!error.is_null()) {
    study::IntegrationError e;
    e.relative_tolerance = error.at("rtol").number(0.0, 1.0, true);
    e.absolute_tolerance = error.at("atol").number(0.0, 1.0, true);
    e.fixed_step = error.at("fixed_step_s").number(0.0, INFINITY, false, "s");
    e.steps = error.at("steps").count();
    e.largest = error.at("largest_deviation").number(0.0, INFINITY, false);
    e.channel = error.at("channel").text();
    e.quantity = error.at("quantity").text();
    b.integration_error = e;
  }
  const Node window = root.at("statistics_window");
  b.window_start = window.at("start_s").number(0.0, INFINITY, false, "s");
  b.window_after_ramp = window.at("after_ramp").boolean();
  const Node amplification = root.at("wire_amplification");
  if (!amplification.is_null()) b.wire_amplification = amplification.number(0.0, INFINITY, false);
  const Node history = root.at("history");
  b.decimation = history.at("decimation").integer(1, 1'000'000'000);
  const Node time = history.at("time_s");
  b.history_time = read_numbers(time);
  for (std::size_t i = 1; i < b.history_time.size(); ++i) {
    if (!(b.history_time[i] > b.history_time[i - 1])) time.at(i).fail("times must increase");
  }
  const Node channels = root.at("channels");
  if (channels.size() == 0) channels.fail("no channel recorded");
  for (std::size_t i = 0; i < channels.size(); ++i) {
    study::ChannelBaseline channel = read_channel(channels.at(i), b.history_time.size());
    if (b.channel(channel.name)) channels.at(i).at("name").fail("recorded twice");
    b.channels.push_back(std::move(channel));
  }
  return b;
}

}  // namespace

BaselineFileError::BaselineFileError(std::string file, std::string key, std::string value, std::string problem)
    : std::runtime_error(key.empty() ? fmt::format("{}: {}", file, problem) : fmt::format("{}: {} = {}: {}", file, key, value, problem)),
      file_(std::move(file)),
      key_(std::move(key)),
      value_(std::move(value)),
      problem_(std::move(problem)) {}

std::string git_commit() { return built_git_commit(); }

std::string scene_file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BaselineFileError(path, "", "", fmt::format("cannot read the scene file: {}", std::strerror(errno)));
  // FNV-1a, 64 bit (offset basis 14695981039346656037, prime 1099511628211).
  std::uint64_t hash = 14695981039346656037ULL;
  for (char c; in.get(c);) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ULL;
  }
  return fmt::format("fnv1a64:{:016x}", hash);
}

BaselineProvenance baseline_provenance(const std::string& scene_path, const std::string& scene_name) {
  BaselineProvenance p;
  p.ffrf_version = ffrf_version();
  p.git_commit = git_commit();
  p.date = utc_date();
  p.scene_path = scene_path;
  p.scene_name = scene_name;
  p.scene_hash = scene_file_hash(scene_path);
  return p;
}

std::string baseline_json(const BaselineFile& file) {
  const BaselineProvenance& p = file.provenance;
  const study::Baseline& b = file.baseline;
  Json doc;
  doc["format"] = format_name;
  doc["format_version"] = baseline_format_version;
  doc["provenance"] = Json{{"ffrf_version", p.ffrf_version},
                           {"git_commit", p.git_commit},
                           {"date", p.date},
                           {"scene", Json{{"path", p.scene_path}, {"name", p.scene_name}, {"content_hash", p.scene_hash}}}};
  doc["model"] = model_json(b.model);
  doc["cost"] = cost_json(b.cost);
  Json modes = Json::array();
  for (const study::BoomFrequency& f : b.boom_frequencies) modes.push_back(Json{{"hz", f.hz}, {"kind", f.kind}, {"order", f.order}});
  doc["boom_frequencies"] = Json{{"boundary", "clamped-free"}, {"elements", b.boom_elements}, {"solver", "arpack"}, {"modes", modes}};
  if (b.coupled_modes.empty()) {
    doc["coupled_modes"] = nullptr;
  } else {
    Json coupled = Json::array();
    for (const study::CoupledFrequency& f : b.coupled_modes) {
      coupled.push_back(Json{{"hz", f.hz}, {"damping_ratio", f.damping_ratio}, {"dominant", f.dominant}});
    }
    doc["coupled_modes"] = Json{{"linearised_about", "static equilibrium, calm water"}, {"modes", coupled}};
  }
  if (b.integration_error && !b.integration_error->measured()) {
    doc["integration_error"] = Json{{"problem", b.integration_error->problem}};
  } else if (b.integration_error) {
    const study::IntegrationError& e = *b.integration_error;
    doc["integration_error"] = Json{{"rtol", e.relative_tolerance}, {"atol", e.absolute_tolerance},
                                    {"fixed_step_s", e.fixed_step},  {"steps", e.steps},
                                    {"largest_deviation", e.largest}, {"channel", e.channel},
                                    {"quantity", e.quantity}};
  } else {
    doc["integration_error"] = nullptr;
  }
  doc["statistics_window"] = Json{{"start_s", b.window_start}, {"after_ramp", b.window_after_ramp}};
  doc["wire_amplification"] = b.wire_amplification ? Json(*b.wire_amplification) : Json(nullptr);
  doc["history"] = Json{{"decimation", b.decimation},
                        {"interval_s", b.model.output_interval * b.decimation},
                        {"points_per_period", study::history_points_per_period},
                        {"time_s", b.history_time}};
  Json channels = Json::array();
  for (const study::ChannelBaseline& c : b.channels) channels.push_back(channel_json(c));
  doc["channels"] = channels;
  return json_text(doc);
}

BaselineFile parse_baseline(const std::string& text, const std::string& file) {
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    throw BaselineFileError(file, "", "", fmt::format("not a JSON document (parse error at byte {})", error.byte));
  }
  const Node root(doc, "", file);
  if (!doc.is_object()) root.fail("not a baseline: the document is not a JSON object");
  const Node format = root.at("format");
  if (format.text() != format_name) format.fail(fmt::format("not an ffrf baseline (expected \"{}\")", format_name));
  const Node version = root.at("format_version");
  const bool known_version = doc["format_version"].is_number_integer() &&
                             doc["format_version"].get<long long>() >= oldest_baseline_format_version &&
                             doc["format_version"].get<long long>() <= baseline_format_version;
  if (!known_version) {
    version.fail(fmt::format("this ffrf reads baseline format versions {} to {}; record the baseline again",
                             oldest_baseline_format_version, baseline_format_version));
  }
  BaselineFile result;
  const Node provenance = root.at("provenance");
  result.provenance.ffrf_version = provenance.at("ffrf_version").text();
  result.provenance.git_commit = provenance.at("git_commit").text();
  result.provenance.date = provenance.at("date").text();
  const Node scene = provenance.at("scene");
  result.provenance.scene_path = scene.at("path").text();
  result.provenance.scene_name = scene.at("name").text();
  result.provenance.scene_hash = scene.at("content_hash").text();
  result.baseline = read_baseline_body(root, doc["format_version"].get<long long>());
  return result;
}

BaselineFile read_baseline(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw BaselineFileError(path, "", "",
                            std::filesystem::exists(path, error) ? "not a regular file" : "no such baseline file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BaselineFileError(path, "", "", fmt::format("cannot read the baseline: {}", std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_baseline(text.str(), path);
}

void write_baseline(const std::string& path, const std::string& text) {
  const std::string partial = fmt::format("{}.partial-{}", path, ::getpid());
  {
    std::ofstream out(partial, std::ios::binary);
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write: {}", path, std::strerror(errno)));
    out << text;
    out.flush();
    if (!out) {
      const std::string reason = std::strerror(errno);
      std::filesystem::remove(partial);
      throw std::runtime_error(fmt::format("{}: cannot write: {}", path, reason));
    }
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::filesystem::remove(partial);
    throw std::runtime_error(fmt::format("{}: cannot write: {}", path, error.message()));
  }
}

}  // namespace ffrf::report
