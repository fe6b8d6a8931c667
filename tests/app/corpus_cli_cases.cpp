// The bad-input corpus through the program: a representative share of the generated scene cases
// (every fifth, through `ffrf check`, every tenth also through `ffrf run --out`), the cross-key
// physics, command-line misuse and output paths. Each case asserts the exit code, that stderr names
// what is wrong (file, line, key or option, value and valid range, or the physical reason), that no
// bare library text reaches the user, that it ends within 30 s (under `timeout`), and that nothing
// is left beside --out.
#include <chrono>
#include <fmt/format.h>
#include <unistd.h>

#include "bad_input_corpus.hpp"

namespace ffrf::test {

TimedRun run_ffrf_timed(const std::string& args, const fs::path& scratch, const std::string& prefix) {
  const fs::path out = scratch / "stdout.txt";
  const fs::path err = scratch / "stderr.txt";
  const std::string command = prefix + " timeout -k 5 30 " + FFRF_BINARY_DIR "/app/ffrf " + args + " </dev/null >'" +
                              out.string() + "' 2>'" + err.string() + "'";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err), seconds};
}

namespace {

struct CliCase {
  std::string name;
  std::string args;        // {scene} {crane} {hub} {cantilever} {out} {dir} are filled in
  int exit_code = 2;
  std::vector<std::string> words;  // {dir} filled in
  std::string scene_text = {};     // written to {dir}/scene.toml
  bool as_nobody = false;          // run without write permission where the test is root
  std::vector<std::pair<std::string, std::string>> files = {};  // more files written to {dir}: name, text
};

std::ostream& operator<<(std::ostream& out, const CliCase& c) { return out << c.name; }

std::string filled(std::string text, const fs::path& dir) {
  const std::vector<std::pair<std::string, std::string>> fields{
      {"{scene}", "'" + (dir / "scene.toml").string() + "'"},
      {"{crane}", source_file("cases/paper_floating_crane.toml")},
      {"{hub}", source_file("cases/dropped_load.toml")},
      {"{sea}", source_file("cases/irregular_sea_crane.toml")},
      {"{cantilever}", source_file("cases/cantilever.toml")},
      {"{out}", "'" + (dir / "out").string() + "'"},
      {"{dir}", dir.string()}};
  for (const auto& [field, value] : fields) {
    for (auto at = text.find(field); at != std::string::npos; at = text.find(field, at + value.size())) {
      text.replace(at, field.size(), value);
    }
  }
  return text;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::vector<CliCase> scene_cases_through_the_program() {
  std::vector<CliCase> cases;
  const auto generated = generated_scene_cases();
  for (std::size_t i = 0; i < generated.size(); i += 5) {
    const SceneCase& c = generated[i];
    const std::vector<std::string> words{fmt::format("scene.toml:{}: {} = {}", c.scene.line, c.key, c.scene.written),
                                         c.expected};
    cases.push_back({"check_" + c.name, "check {scene}", 2, words, c.scene.text});
    if (i % 10 == 0) cases.push_back({"run_" + c.name, "run {scene} --out {out}", 2, words, c.scene.text});
  }
  return cases;
}

std::vector<CliCase> physics_cases() {
  const std::string crane = read_text(source_file("cases/paper_floating_crane.toml"));
  const std::string sea = read_text(source_file("cases/irregular_sea_crane.toml"));
  const std::string no_mooring = crane.substr(0, crane.find("[mooring]")) + crane.substr(crane.find("[simulation]"));
  const auto run = [](std::string name, std::string text, std::vector<std::string> words) {
    return CliCase{std::move(name), "run {scene} --duration 2 --out {out}", 2, std::move(words), std::move(text)};
  };
  return {
      run("hook_off_the_cargo", replaced(crane, "hook_x = 0.0 ", "hook_x = 30.0 "),
          {"scene.toml:36: cargo.hook_x = 30.0", "on or inside", "valid range [-10, 10] m"}),
      run("root_off_the_hull", replaced(crane, "root_x = 35.0 ", "root_x = 135.0 "),
          {"scene.toml:22: boom.root_x = 135.0", "valid range [-32, 58] m"}),
      run("g1_above_the_deck", replaced(crane, "g1_above_keel = 6.0 ", "g1_above_keel = 9.0 "),
          {"hull.g1_above_keel = 9.0", "below the deck", "valid range [0, 8) m"}),
      run("no_mooring", no_mooring, {"mooring.surge_stiffness = 0 N/m (default)", "surge has no restoring force"}),
      run("deck_under_water", replaced(crane, "mass = 1.3e6 ", "mass = 14.0e6 "),
          {"cargo.mass = 14.0e6", "the deck would be under water at rest"}),
      run("cargo_in_the_water", replaced(crane, "unstretched_length = 20.0 ", "unstretched_length = 200.0 "),
          {"wire.unstretched_length = 200.0", "the cargo would hang in the water", "at most 103.6 m"}),
      run("irregular_sea_too_steep", replaced(replaced(sea, "significant_height = 2.0 ", "significant_height = 5.0 "),
                                              "peak_period = 8.0 ", "peak_period = 6.0 "),
          {"wave.significant_height = 5.0", "the sea is too steep", "DNV-RP-C205", "valid range (0, 3.747] m"}),
      run("irregular_sea_negative_hs", replaced(sea, "significant_height = 2.0 ", "significant_height = -2.0 "),
          {"wave.significant_height = -2.0", "valid range (0, 30] m"}),
      run("irregular_sea_zero_tp", replaced(sea, "peak_period = 8.0 ", "peak_period = 0 "),
          {"wave.peak_period = 0", "valid range [1, 40] s"}),
      run("irregular_sea_gamma_below_one", replaced(sea, "peak_enhancement = 3.3 ", "peak_enhancement = 0.5 "),
          {"wave.peak_enhancement = 0.5", "valid range [1, 20]"}),
      run("irregular_sea_without_hs", replaced(sea, "significant_height = 2.0 ", "# no Hs "),
          {"wave.significant_height", "wave.spectrum = \"jonswap\" needs it", "valid range (0, 30] m"}),
      run("regular_key_in_an_irregular_sea", replaced(sea, "peak_period = 8.0 ", "peak_period = 8.0\nheight = 1.0 "),
          {"wave.height = 1.0", "belongs to wave.spectrum = \"regular\""}),
      run("breaking_wave", replaced(crane, "height = 1.0 ", "height = 25.0 "),
          {"wave.height = 25.0", "the wave breaks", "valid range [0, 22.3) m"}),
      run("depth_below_draft", replaced(replaced(crane, "water_depth = inf ", "water_depth = 3.0 "), "height = 1.0 ",
                                        "height = 0.5 "),
          {"environment.water_depth = 3.0", "the hull would ground", "valid range (4.092, 11000] m or inf"}),
      run("no_gravity", replaced(crane, "gravity = 9.81 ", "gravity = 0.0 "), {"environment.gravity = 0.0", "needs gravity"}),
      run("radius_of_gyration_beyond_the_hull",
          replaced(crane, "pitch_radius_of_gyration = 22.5", "pitch_radius_of_gyration = 100"),
          {"hull.pitch_radius_of_gyration = 100", "valid range [0.1, 58.31] m"}),
      run("too_many_samples", replaced(replaced(crane, "duration = 120.0 ", "duration = 1e5 "), "output_interval = 0.05 ",
                                       "output_interval = 0.01 "),
          {"simulation.output_interval = 0.01", "more than the limit of 1e+06"}),
      run("sinking_hull", replaced(crane, "mass = 12.6e6 ", "mass = 40e6 "), {"hull.mass = 40e6", "would sink"}),
      run("unit_slip_gpa", replaced(crane, "youngs_modulus = 2.1e11 ", "youngs_modulus = 210 "),
          {"boom.youngs_modulus = 210", "valid range [1, 1500] GPa", "did you mean \"210 GPa\"?"}),
      run("unit_slip_tonnes", replaced(crane, "mass = 12.6e6 ", "mass = \"12.6e6 t\" "),
          {"hull.mass = \"12.6e6 t\"", "did you mean \"12.6e6 kg\""}),
      run("bare_angle", replaced(crane, "angle = \"60 deg\"", "angle = 60"),
          {"boom.angle = 60", "an angle needs its unit", "did you mean \"60 deg\"?", "valid range (0, 90) deg"}),
      run("integer_wrap", replaced(crane, "elements = 16 ", "elements = 3000000000 "),
          {"boom.elements = 3000000000", "valid range [1, 10000]"}),
      run("integer_beyond_int64", replaced(crane, "elements = 16 ", "elements = 99999999999999999999 "),
          {"boom.elements = 99999999999999999999", "valid range [1, 10000]"}),
  };
}

std::vector<CliCase> misuse_cases() {
  const auto run = [](std::string name, std::string options, std::vector<std::string> words) {
    return CliCase{std::move(name), "run {crane} --duration 2 " + options + " --out {out}", 2, std::move(words)};
  };
  const auto command = [](std::string name, std::string args, std::vector<std::string> words) {
    return CliCase{std::move(name), std::move(args), 2, std::move(words)};
  };
  return {
      run("typo_model_for_boom", "--model modal", {"--model: unknown option", "did you mean --boom modal"}),
      run("typo_elements", "--elemnts 4", {"--elemnts", "did you mean --elements?"}),
      command("unknown_command", "rnu {crane}", {"rnu: unknown command", "did you mean run?"}),
      command("no_command", "", {"give a command"}),
      command("missing_scene", "run", {"scene is required"}),
      command("empty_out", "run {crane} --out ''", {"--out \"\"", "an empty value"}),
      command("empty_scene", "check ''", {"scene \"\"", "an empty value"}),
      command("scene_is_a_directory", "check {dir}", {"{dir}: is a directory"}),
      command("scene_is_missing", "check {dir}/nope.toml", {"{dir}/nope.toml", "cannot open", "No such file"}),
      command("scene_is_a_device", "check /dev/zero", {"/dev/zero", "larger than"}),
      command("extra_argument", "check {crane} {cantilever}", {"not expected"}),
      run("elements_wrap", "--elements 3000000000", {"--elements 3000000000", "valid range [1, 10000]"}),
      run("elements_two_to_the_32_plus_1", "--elements 4294967297", {"--elements 4294967297", "valid range [1, 10000]"}),
      run("elements_negative", "--elements -1", {"--elements -1", "valid range [1, 10000]"}),
      run("elements_fraction", "--elements 2.5", {"--elements 2.5", "not a whole number", "valid range [1, 10000]"}),
      run("elements_text", "--elements abc", {"--elements abc", "not a whole number"}),
      run("elements_beyond_memory", "--elements 5000", {"--elements 5000", "GiB", "valid range [1, 2226]"}),
      run("modes_zero", "--boom modal --modes 0", {"--modes 0", "valid range [1, 1000]"}),
      run("modes_huge", "--boom modal -k 1000000", {"--modes 1000000", "valid range [1, 1000]"}),
      run("rtol_nan", "--rtol nan", {"--rtol nan", "not a finite number", "valid range [1e-12, 0.1]"}),
      run("rtol_inf", "--rtol inf", {"--rtol inf", "valid range [1e-12, 0.1]"}),
      run("rtol_zero", "--rtol 0", {"--rtol 0", "valid range [1e-12, 0.1]"}),
      run("rtol_tiny", "--rtol 1e-20", {"--rtol 1e-20", "valid range [1e-12, 0.1]"}),
      run("rtol_text", "--rtol tight", {"--rtol tight", "not a number"}),
      run("atol_above", "--atol 2", {"--atol 2", "valid range [1e-12, 0.1]"}),
      CliCase{"duration_zero", "run {crane} --duration 0 --out {out}", 2, {"--duration 0", "valid range (0, 1e+06] s"}},
      CliCase{"duration_negative", "run {crane} --duration -1 --out {out}", 2, {"--duration -1", "valid range"}},
      CliCase{"duration_huge", "run {crane} --duration 1e9 --out {out}", 2, {"--duration 1e9", "valid range (0, 1e+06] s"}},
      CliCase{"duration_inf", "run {crane} --duration inf --out {out}", 2, {"--duration inf", "not a finite number"}},
      CliCase{"duration_too_many_samples", "run {crane} --duration 100000 --out {out}", 2,
              {"--duration 100000", "output samples", "valid range [0.05, 50000] s"}},
      run("step_too_small", "--integrator generalized-alpha --step 1e-9", {"--step 1e-09", "steps", "valid range"}),
      run("step_negative", "--step -1", {"--step -1", "valid range [0, 3600] s"}),
      run("max_order_zero", "--max-order 0", {"--max-order 0", "valid range [1, 5]"}),
      run("max_order_nine", "--max-order 9", {"--max-order 9", "valid range [1, 5]"}),
      run("unknown_boom", "--boom elastic", {"--boom elastic", "rigid|nodal|modal"}),
      run("unknown_integrator", "--integrator rk4", {"--integrator rk4", "cvode"}),
      run("unknown_stiffening", "--stiffening hard", {"--stiffening hard", "none, static, centrifugal, both"}),
      run("static_modes_both_ways", "--static-modes --no-static-modes", {"exclude each other"}),
      run("spin_rate_without_hub", "--spin-rate 5", {"--spin-rate 5", "no [hub]"}),
      CliCase{"spin_rate_huge", "run {hub} --spin-rate 1e308 --out {out}", 2,
              {"--spin-rate 1e308", "valid range [-1000, 1000] rad/s"}},
      run("unknown_option_of_run", "--jobs 2", {"--jobs: unknown option of `ffrf run`"}),
      command("reference_levels", "compare {crane} --reference-levels 7 --out {out}", {"--reference-levels 7", "valid range [1, 6]"}),
      command("reference_elements", "compare {crane} --reference-elements 5000 --out {out}",
              {"--reference-elements 5000", "valid range [1, 556]"}),
      command("reference_bound_zero", "compare {crane} --reference-bound 0 --out {out}",
              {"--reference-bound 0", "valid range (0, 1]"}),
      command("reference_rtol", "compare {crane} --reference-rtol 1e-12 --out {out}",
              {"--reference-rtol 1e-12", "valid range [1e-10, 0.1]"}),
      command("tolerance_zero", "recommend {crane} --tolerance 0 --out {out}", {"--tolerance 0", "valid range (0, 1)"}),
      command("tolerance_percent", "recommend {crane} --tolerance 150% --out {out}", {"--tolerance 150%", "valid range"}),
      command("unknown_output", "recommend {crane} --outputs bogus --out {out}", {"--outputs bogus", "unknown output 'bogus'"}),
      command("recommend_duration", "recommend {crane} --duration -5 --out {out}", {"--duration -5", "valid range"}),
      command("jobs_negative", "sweep {crane} --jobs -1 --out {out}", {"--jobs -1", "valid range [0, 1024]"}),
      command("jobs_huge", "sweep {crane} --jobs 2000 --out {out}", {"--jobs 2000", "valid range [0, 1024]"}),
      command("shard_beyond", "sweep {crane} --shard 3/2 --out {out}", {"--shard 3/2"}),
      command("shard_text", "sweep {crane} --shard abc --out {out}", {"--shard abc"}),
      command("grids_together", "sweep {crane} --quick --full --out {out}", {"exclude each other"}),
      command("merge_without_out", "sweep --merge {dir}/a.csv", {"--merge needs --out"}),
      command("spin_negative", "modes {cantilever} --spin -1 --out {out}", {"--spin -1", "valid range [0, 1000] rad/s"}),
      command("spin_huge", "modes {cantilever} --spin 1e308 --out {out}", {"--spin 1e308", "valid range [0, 1000] rad/s"}),
      command("spin_range_count", "modes {cantilever} --spin-range 0:1:1 --out {out}", {"--spin-range 0:1:1", "count n = 1"}),
      command("axial_force_huge", "modes {cantilever} --axial-force 1e300 --out {out}",
              {"--axial-force 1e300", "valid range [-1e+13, 1e+13] N"}),
      command("unknown_boundary", "modes {cantilever} --boundary hinged --out {out}",
              {"--boundary hinged", "clamped-free|free-free|pinned-pinned"}),
      command("unknown_solver", "modes {cantilever} --solver lapack --out {out}", {"--solver lapack", "arpack"}),
      command("modes_elements", "modes {cantilever} --elements 20000 --out {out}", {"--elements 20000", "valid range [1, 10000]"}),
      command("modes_count", "modes {cantilever} --modes 5000 --out {out}", {"--modes 5000", "valid range [1, 1000]"}),
      command("stability_of_a_beam", "stability {cantilever} --out {out}", {"not a crane scene"}),
      command("unknown_global_option", "--frobnicate", {"--frobnicate: unknown option"}),
      command("scene_reference_extra", "scene-reference extra", {"not expected"}),
      // `ffrf rao`: the frequency grid, the time-domain check's options, a scene without water.
      command("rao_periods_malformed", "rao {crane} --periods 3:30 --out {out}", {"--periods 3:30", "three fields", "a:b:n"}),
      command("rao_periods_reversed", "rao {crane} --periods 30:3:10 --out {out}", {"--periods 30:3:10", "0 < a < b <= 1000"}),
      command("rao_frequency_negative", "rao {crane} --frequencies 0.5,-1 --out {out}",
              {"--frequencies 0.5,-1", "-1 is out of range", "(0, 100] rad/s"}),
      command("rao_frequency_text", "rao {crane} --frequencies fast --out {out}", {"--frequencies fast", "not a finite number"}),
      command("rao_check_wave_height_zero", "rao {crane} --check-time-domain --check-wave-height 0 --out {out}",
              {"--check-wave-height 0", "valid range"}),
      command("rao_without_water", "rao {hub} --out {out}", {"needs a floating crane", "[hub]"}),
      // Output paths: the user's path and the operating system's reason, exit 2.
      command("out_under_a_file", "run {crane} --duration 2 --out {dir}/stdout.txt/sub",
              {"{dir}/stdout.txt/sub", "Not a directory"}),
      command("out_is_a_file", "run {crane} --duration 2 --out {dir}/stdout.txt", {"{dir}/stdout.txt", "is not a directory"}),
      CliCase{"out_not_writable", "run {crane} --duration 2 --out {dir}/locked/out", 2,
              {"{dir}/locked/out", "Permission denied"}, "", true},
      // A solver failure is exit 3 and named; nothing is written either.
      CliCase{"explicit_instability", "run {crane} --duration 2 --integrator arkode --step 0.05 --elements 2 --out {out}",
              3, {"solver failure (explicit instability)", "reduce the fixed step", "options: --step"}},
  };
}

// Scenes with WAMIT files ([bem]): the files beside the scene, each case with one file or key wrong.
std::vector<CliCase> bem_cases() {
  const std::string scene = replaced(replaced(replaced(read_text(source_file("cases/bem_barge_crane.toml")),
                                                       "\"../tests/hydro/data/barge.1\"", "\"barge.1\""),
                                              "\"../tests/hydro/data/barge.3\"", "\"barge.3\""),
                                     "\"../tests/hydro/data/barge.hst\"", "\"barge.hst\"");
  const std::string radiation = read_text(source_file("tests/hydro/data/barge.1"));
  const std::vector<std::pair<std::string, std::string>> fixture{
      {"barge.1", radiation},
      {"barge.3", read_text(source_file("tests/hydro/data/barge.3"))},
      {"barge.hst", read_text(source_file("tests/hydro/data/barge.hst"))}};
  const auto with_radiation_file = [&](std::string text) {
    auto files = fixture;
    files[0].second = std::move(text);
    return files;
  };
  std::string no_infinite, no_heave, reordered;
  std::vector<std::string> lines;
  for (std::size_t at = 0, end = 0; at < radiation.size(); at = end + 1) {
    end = std::min(radiation.find('\n', at), radiation.size());
    lines.push_back(radiation.substr(at, end - at));
  }
  for (const std::string& line : lines) {
    if (line.rfind("  0.000000E+00", 0) != 0) no_infinite += line + "\n";
    if (line.rfind("  9.000000E-01     3     3", 0) != 0) no_heave += line + "\n";
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {  // the 1.05 s rows before the 0.9 s rows
    if (lines[i].rfind("  9.000000E-01", 0) == 0) continue;
    if (lines[i].rfind("  1.200000E+00", 0) == 0 && reordered.find("  9.000000E-01") == std::string::npos) {
      for (const std::string& row : lines) {
        if (row.rfind("  9.000000E-01", 0) == 0) reordered += row + "\n";
      }
    }
    reordered += lines[i] + "\n";
  }
  const auto check = [&](std::string name, std::string text, std::vector<std::pair<std::string, std::string>> files,
                         std::vector<std::string> words) {
    return CliCase{std::move(name), "check {scene}", 2, std::move(words), std::move(text), false, std::move(files)};
  };
  return {
      check("bem_file_not_found", replaced(scene, "\"barge.1\"", "\"nope.1\""), fixture,
            {"scene.toml:58: bem.radiation_file = \"nope.1\"", "file not found: {dir}/nope.1",
             "relative to the scene file's folder, not to the working directory"}),
      check("bem_no_infinite_frequency", scene, with_radiation_file(no_infinite),
            {"bem.radiation_file = \"barge.1\"", "{dir}/barge.1: no infinite-frequency limit (rows with PER = 0)"}),
      check("bem_missing_heave", scene, with_radiation_file(no_heave),
            {"{dir}/barge.1:12: period 0.9 s: no diagonal entry for mode 3 (heave)"}),
      check("bem_periods_not_monotonic", scene, with_radiation_file(reordered),
            {"{dir}/barge.1:", "the periods are not monotonic"}),
      check("bem_hydrostatics_of_another_hull", replaced(scene, "width = 10.0 ", "width = 14.0 "), fixture,
            {"bem.hydrostatics_file = \"barge.hst\"", "C33", "valid: within 2 %", "another hull"}),
      check("bem_and_radiation_sections", scene + "\n[radiation]\nheave_added_mass = 1.0\n", fixture,
            {"radiation: conflicts with [bem]"}),
      check("bem_excitation_without_file", replaced(scene, "excitation_file = \"barge.3\"", ""), fixture,
            {"bem.excitation = \"bem\"", "needs bem.excitation_file"}),
      CliCase{"radiation_without_bem", "run {crane} --duration 2 --radiation convolution --out {out}", 2,
              {"--radiation convolution", "no [bem] section"}},
      CliCase{"unknown_radiation", "run {scene} --duration 2 --radiation memory --out {out}", 2,
              {"--radiation memory", "choose one of constant, state-space, convolution"}, scene, false, fixture},
  };
}

std::vector<CliCase> all_cli_cases() {
  std::vector<CliCase> cases = scene_cases_through_the_program();
  for (auto part : {physics_cases(), misuse_cases(), bem_cases()}) cases.insert(cases.end(), part.begin(), part.end());
  return cases;
}

class CorpusCli : public ::testing::TestWithParam<CliCase> {};

TEST_P(CorpusCli, ExitCodeNamedMessageNothingLeftBehind) {
  const CliCase& bad = GetParam();
  TempDir dir;
  if (!bad.scene_text.empty()) write_text(dir / "scene.toml", bad.scene_text);
  for (const auto& [name, text] : bad.files) write_text(dir / name, text);
  std::string prefix;
  if (bad.as_nobody) {
    fs::create_directory(dir / "locked");
    fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                        fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    if (::geteuid() == 0) prefix = "setpriv --reuid=65534 --regid=65534 --clear-groups";  // root may write anywhere
  }
  const auto before = directory_entries(dir.path());
  const TimedRun r = run_ffrf_timed(filled(bad.args, dir.path()), dir.path(), prefix);
  EXPECT_NE(r.exit_code, 124) << "no answer within 30 s";
  EXPECT_LT(r.seconds, 30.0);
  EXPECT_EQ(r.exit_code, bad.exit_code) << r.err;
  for (const std::string& word : bad.words) {
    EXPECT_NE(r.err.find(filled(word, dir.path())), std::string::npos) << "'" << filled(word, dir.path()) << "' not in:\n"
                                                                       << r.err;
  }
  for (const std::string& text : kBareLibraryText) {
    EXPECT_EQ((r.out + r.err).find(text), std::string::npos) << "'" << text << "' reached the user:\n" << r.err;
  }
  // Nothing beside --out: the directory holds what it held before and the captured output.
  std::vector<std::string> expected = before;
  for (const char* name : {"stderr.txt", "stdout.txt"}) {
    if (std::find(expected.begin(), expected.end(), name) == expected.end()) expected.push_back(name);
  }
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(directory_entries(dir.path()), expected);
  if (bad.as_nobody) {
    EXPECT_TRUE(fs::is_empty(dir / "locked"));
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusCli, ::testing::ValuesIn(all_cli_cases()),
                         [](const ::testing::TestParamInfo<CliCase>& case_info) { return case_info.param.name; });

}  // namespace
}  // namespace ffrf::test
