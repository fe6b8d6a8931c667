// `ffrf modes SCENE`: natural frequencies and mode shapes of the scene's boom, next to the
// analytic Euler–Bernoulli values; for a boom pinned at its heel also its modes as the crane
// supports it (heel pin, luffing wires: study/supported_boom.hpp). Text table, --json on stdout, --out DIR with CSV, JSON and
// gnuplot charts (written completely or not at all). With --spin Ω and/or --axial-force P: the modes
// of the spinning / prestressed beam next to the power series; with --spin-range a:b:n: the
// Campbell diagram (study/campbell.hpp).
#include <fmt/format.h>

#include <memory>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "fem/beam_model.hpp"
#include "report/campbell_report.hpp"
#include "report/chart_notes.hpp"
#include "report/gnuplot.hpp"
#include "report/modes_report.hpp"
#include "report/output_directory.hpp"
#include "scene/scene_key.hpp"
#include "scene/scene_loader.hpp"
#include "study/campbell.hpp"
#include "study/modes.hpp"

namespace ffrf::app {
namespace {

using namespace ffrf::report;
using namespace ffrf::study;

struct ModesOptions {
  std::string scene;
  std::vector<std::string> set;  // --set KEY=VALUE
  std::optional<int> elements;
  std::optional<int> modes;
  std::string boundary;
  std::string solver = "arpack";
  bool json = false;
  std::string out;
  std::optional<std::string> spin;         // Ω [rad/s]
  std::optional<std::string> spin_range;   // "a:b:n"
  std::optional<std::string> axial_force;  // P [N]
};

constexpr int default_campbell_modes = 3;  // bending modes tracked over the spin range

void progress(const std::string& message) { app::progress("modes", message); }
void progress_done() { app::progress("modes", ""); }
int bad_input(const std::string& message) { return app::bad_input("modes", message); }

// The plausible ranges of the spin (the scene's hub.spin_rate) and the axial force (beyond 1e13 N
// no boom section survives; the eigenproblem would lose all precision).
constexpr double max_spin = 1000.0;        // [rad/s]
constexpr double max_axial_force = 1e13;   // [N]

double parse_finite(const std::string& name, const std::string& text, double minimum, double maximum, const char* unit) {
  const std::string range = fmt::format("[{:g}, {:g}] {}", minimum, maximum, unit);
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) || value < minimum || value > maximum) {
    throw std::invalid_argument(fmt::format("{} {}: not a valid value (valid range {}, a finite number)", name, text, range));
  }
  return value;
}

study::SpinRange parse_spin_range(const std::string& text) {
  const auto fail = [&](const std::string& why) {
    throw std::invalid_argument(fmt::format("--spin-range {}: {} (expected a:b:n in rad/s with 0 <= a < b <= {:g} and an "
                                            "integer count n in [2, 10000])", text, why, max_spin));
  };
  const auto first_colon = text.find(':');
  const auto second_colon = first_colon == std::string::npos ? std::string::npos : text.find(':', first_colon + 1);
  if (second_colon == std::string::npos || text.find(':', second_colon + 1) != std::string::npos) {
    fail("malformed, not three fields separated by ':'");
  }
  const auto number = [&](const std::string& field, const char* what) {
    char* end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(value)) {
      fail(fmt::format("{} '{}' is not a finite number", what, field));
    }
    return value;
  };
  const double a = number(text.substr(0, first_colon), "first spin a");
  const double b = number(text.substr(first_colon + 1, second_colon - first_colon - 1), "last spin b");
  const double n = number(text.substr(second_colon + 1), "count n");
  if (a < 0.0) fail(fmt::format("first spin a = {:g} rad/s is negative", a));
  if (!(b > a)) fail(fmt::format("last spin b = {:g} must exceed the first a = {:g}", b, a));
  if (b > max_spin) fail(fmt::format("last spin b = {:g} rad/s is beyond {:g} rad/s", b, max_spin));
  if (n != std::floor(n) || n < 2.0 || n > 10000.0) fail(fmt::format("count n = {:g} is not an integer in [2, 10000]", n));
  return {a, b, static_cast<int>(n)};
}


void write_outputs(StagedDirectory& out, const ModesResult& result, const ModesContext& context) {
  const std::string terminal = png_terminal();
  out.write("modes.csv", mode_shapes_csv(result));
  out.write("mode_shapes_sampled.csv", sampled_shapes_csv(result));
  out.write("frequencies.csv", frequencies_csv(result));
  if (result.supported) out.write("supported_boom.csv", supported_boom_csv(*result.supported));
  const auto convergence = frequency_convergence(result.mesh, result.boundary, result.solver, [](int elements) {
    progress(fmt::format("convergence study: N = {} ...", elements));
  });
  progress_done();
  out.write("frequency_convergence.csv", convergence_csv(convergence));
  draw_chart(out, "mode_shapes", mode_shapes_script(result, terminal));
  draw_chart(out, "frequency_convergence", convergence_script(result, terminal));
  out.write("summary.json", with_charts_json(modes_json(result, context, convergence), out));
  out.commit();
  fmt::print(stderr, "{}", chart_notes_text("modes", out));
}

// --spin / --axial-force / --spin-range, after the common options were checked.
int run_spinning(const ModesOptions& options, const scene::Scene& scene, const fem::BeamMesh& mesh,
                 fem::Boundary boundary, modal::EigenSolverKind solver) {
  double spin = 0.0, axial_force = 0.0;
  std::optional<SpinRange> range;
  try {
    if (options.spin && options.spin_range) {
      throw std::invalid_argument(fmt::format("--spin {} and --spin-range {} exclude each other: give one spin rate or one "
                                              "range", *options.spin, *options.spin_range));
    }
    if (options.spin) spin = parse_finite("--spin", *options.spin, 0.0, max_spin, "rad/s");
    if (options.spin_range) range = parse_spin_range(*options.spin_range);
    if (options.axial_force) {
      axial_force = parse_finite("--axial-force", *options.axial_force, -max_axial_force, max_axial_force, "N");
    }
  } catch (const std::invalid_argument& error) {
    return bad_input(error.what());
  }
  if (boundary == fem::Boundary::free_free) {
    return bad_input(fmt::format("--boundary free-free: --spin, --spin-range and --axial-force need a held root "
                                 "(choose clamped-free or pinned-pinned)"));
  }
  const int dof = free_dof_count(mesh, boundary);
  const int count = options.modes.value_or(std::min(dof - 1, range ? default_campbell_modes : default_elastic_modes));
  if (count < 1 || count >= dof) {
    return bad_input(fmt::format("--modes {} is not a valid mode count for N = {} (valid range [1, {}])", count,
                                 mesh.element_count, dof - 1));
  }
  const double hub_radius = spin_hub_radius(scene);
  const ModesContext context{options.scene, scene.name};
  std::optional<StagedDirectory> out;
  if (!options.out.empty()) out.emplace(options.out, "summary.json");
  const fem::BeamModel model = fem::make_beam_model(mesh, boundary);
  std::string text, json;
  if (range) {
    const CampbellResult result = campbell_diagram(model, *range, hub_radius, axial_force, count, solver, [&](int i) {
      progress(fmt::format("Campbell diagram: spin {} of {} ...", i + 1, range->count));
    });
    progress_done();
    text = campbell_table(result, context);
    json = campbell_json(result, context);
    if (out) {
      out->write("campbell.csv", campbell_csv(result));
      draw_chart(*out, "campbell", campbell_script(result, png_terminal()));
    }
  } else {
    const SpinModesResult result = solve_spin_modes(model, spin, hub_radius, axial_force, count, solver);
    for (const std::string& warning : result.warnings) fmt::print(stderr, "ffrf modes: warning: {}\n", warning);
    text = spin_modes_table(result, context);
    json = spin_modes_json(result, context);
    if (out) out->write("prestressed_frequencies.csv", spin_modes_csv(result));
  }
  if (out) {
    out->write("summary.json", with_charts_json(json, *out));
    out->commit();
    fmt::print(stderr, "{}", chart_notes_text("modes", *out));
  }
  fmt::print("{}", options.json ? json : text);
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {}\n", options.out);
  return exit_ok;
}

int run_modes(const ModesOptions& options) {
  const std::optional<scene::Scene> loaded = load_scene(options.scene, options.set, "modes", false);
  if (!loaded) return exit_bad_input;
  const scene::Scene& scene = *loaded;
  study::ModesRequest request{options.elements, options.modes, options.boundary, options.solver};
  const bool spinning = options.spin || options.spin_range || options.axial_force;
  if (spinning) request.count.reset();  // the spinning beam's count is checked there
  study::ModesSetup setup;
  try {
    setup = study::modes_setup(scene, request);
  } catch (const study::SettingError& error) {
    return bad_input(option_message(error));
  }
  const fem::BeamMesh& mesh = setup.mesh;
  if (spinning) return run_spinning(options, scene, mesh, setup.boundary, setup.solver);
  const int dof = free_dof_count(mesh, setup.boundary);
  const int count = setup.count;
  const fem::Boundary boundary = setup.boundary;
  const modal::EigenSolverKind solver = setup.solver;

  // The input is valid: from here on, DIR's old completeness marker no longer describes DIR.
  std::optional<StagedDirectory> out;
  if (!options.out.empty()) out.emplace(options.out, "summary.json");

  progress(fmt::format("solving {} modes, N = {} ({} DOFs) ...", count, mesh.element_count, dof));
  ModesResult result = solve_modes(mesh, boundary, solver, count);
  if (scene.boom.mount && scene.boom.mount->pinned) progress("the boom as supported: heel pin and luffing wires ...");
  add_supported_boom(scene, count, result);
  progress_done();
  for (const std::string& warning : result.warnings) fmt::print(stderr, "ffrf modes: warning: {}\n", warning);
  const ModesContext context{options.scene, scene.name};
  if (out) write_outputs(*out, result, context);
  fmt::print("{}", options.json ? modes_json(result, context, {}) : modes_table(result, context));
  if (!options.out.empty() && !options.json) fmt::print("\nwrote {}\n", options.out);
  return exit_ok;
}

}  // namespace

Command add_modes_command(CLI::App& parent) {
  auto options = std::make_shared<ModesOptions>();
  CLI::App* sub = parent.add_subcommand("modes", "Natural frequencies and mode shapes of the boom vs Euler–Bernoulli");
  sub->add_option("scene", options->scene, "Scene file (TOML)")->required();
  add_set_option(*sub, options->set);
  sub->add_option("--elements,-N", options->elements, "Number of beam elements (default: boom.elements of the scene)")
      ->check(scene_key_count(scene::scene_key("boom.elements")));
  sub->add_option("--modes,-k", options->modes, "Number of modes (default: 6, plus the rigid modes for free-free)")
      ->check(whole_number(1, 1000));
  sub->add_option("--boundary", options->boundary,
                  "Boundary condition " + fem::boundary_choices() + " (default: boom.boundary of the scene)");
  sub->add_option("--solver", options->solver, "Eigen solver " + modal::eigen_solver_choices())
      ->capture_default_str();
  sub->add_flag("--json", options->json, "Print the results as JSON on stdout");
  sub->add_option("--out", options->out,
                  "Write modes.csv, mode_shapes_sampled.csv, frequencies.csv, frequency_convergence.csv, summary.json, "
                  "supported_boom.csv (a pinned boom) and PNG charts "
                  "(with their gnuplot scripts) into this directory; with --spin/--axial-force: prestressed_frequencies.csv "
                  "and summary.json; with --spin-range: campbell.csv, campbell.png (+ .gp) and summary.json");
  sub->add_option("--spin", options->spin,
                  "Spin rate Omega [rad/s] >= 0 about the axis normal to the plane: modes in the rotating frame with and "
                  "without centrifugal stiffening, vs the power series (clamped-free)");
  sub->add_option("--spin-range", options->spin_range,
                  "Campbell diagram over n spin rates a:b:n [rad/s] (0 <= a < b, n >= 2) of the lowest --modes bending modes "
                  "(default 3)");
  sub->add_option("--axial-force", options->axial_force,
                  "Uniform axial force P [N] (tension > 0, compression < 0): modes about the prestressed state, with the "
                  "buckling load");
  return {sub, [options] { return run_modes(*options); }};
}

}  // namespace ffrf::app
