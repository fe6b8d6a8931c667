// `ffrf operability SCENE --hs a:b:n --tp a:b:n [--heading following,head] --seeds N --duration S
// --out DIR`: the operability table over sea states (study/operability.hpp) on the distributed engine:
// serially (threads) without a launcher, over MPI ranks under mpirun or srun. Every finished record is
// journaled in DIR (journal.tsv) and a rerun resumes from it; the outputs (report/operability_report.hpp)
// are written by rank 0 at the end, whole or not at all. Before the records start, on a terminal only,
// a short probe estimates the table's cost. Exit 0 when every physical cell has its verdict (cells
// too steep to exist are named as not physical, not failed), 1 when a record failed (the table names
// the cells), 2 for bad input (a grid without one physical cell included).
#include <fmt/format.h>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/option_checks.hpp"
#include "app/version.hpp"
#include "distributed/errors.hpp"
#include "distributed/farm.hpp"
#include "distributed/progress.hpp"
#include "distributed/session.hpp"
#include "report/gnuplot.hpp"
#include "report/operability_report.hpp"
#include "report/output_directory.hpp"
#include "study/operability_cost.hpp"

namespace ffrf::app {
namespace {

struct OperabilityOptions {
  std::string scene, out, hs, tp;
  std::vector<std::string> set;  // --set KEY=VALUE
  std::vector<std::string> headings{"following"};
  int seeds = 3;
  double duration = 10800.0;
  double gamma = 3.3;
  int components = 0;
  double band_share = hydro::default_variance_share;
  int threads = 0;
  int verify = 2;
  int converged_elements = 32;
  bool retry_failed = false;
  std::string tolerance = "1%";
  study::OperabilityCriteria criteria;
  std::string command_line;
};

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// "a:b:n": n values evenly from a to b (n = 1: a alone); a single number is one value.
std::optional<std::vector<double>> parse_axis(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t colon; (colon = text.find(':', start)) != std::string::npos; start = colon + 1) parts.push_back(text.substr(start, colon - start));
  parts.push_back(text.substr(start));
  const auto number = [](const std::string& s, double& value) {
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
    return error == std::errc() && end == s.data() + s.size();
  };
  double a = 0.0, b = 0.0, n = 0.0;
  if (parts.size() == 1 && number(parts[0], a)) return std::vector<double>{a};
  if (parts.size() != 3 || !number(parts[0], a) || !number(parts[1], b) || !number(parts[2], n)) return std::nullopt;
  if (n < 1.0 || n > 100.0 || n != std::floor(n) || (n == 1.0 && a != b) || !(b >= a)) return std::nullopt;
  std::vector<double> values;
  const int count = static_cast<int>(n);
  for (int i = 0; i < count; ++i) values.push_back(count == 1 ? a : a + (b - a) * i / (count - 1));
  return values;
}

// The command as it ran, every option a result depends on spelled out (defaults too), so that
// report.md's copy reproduces the table; threads and --retry-failed change no result and are left out.
std::string echoed_command(const OperabilityOptions& o) {
  std::string headings;
  for (const std::string& h : o.headings) headings += (headings.empty() ? "" : ",") + h;
  const study::OperabilityCriteria& c = o.criteria;
  std::string set;
  for (const std::string& value : o.set) set += fmt::format(" --set '{}'", value);
  return fmt::format("operability {}{} --hs {} --tp {} --heading {} --seeds {} --duration {:g} --gamma {:g} --components {} "
                     "--band-share {:g} --tolerance {} --verify {} --converged-elements {} --daf-limit {:g} "
                     "--slack-margin {:g} --cargo-motion-limit {:g} --moment-capacity {:g} --buckling-ratio {:g} --out {}",
                     o.scene, set, o.hs, o.tp, headings, o.seeds, o.duration, o.gamma, o.components, o.band_share, o.tolerance,
                     o.verify, o.converged_elements, c.daf_limit, c.slack_margin, c.cargo_motion_limit,
                     c.root_moment_capacity, c.buckling_ratio, o.out);
}

// On a terminal, before the records start: what the table will cost, from a probe of one record.
void print_cost_estimate(const scene::Scene& scene, const study::OperabilityRequest& request,
                         const study::OperabilityPlan& plan, const distributed::Session& session,
                         const distributed::FarmOptions& farm, modal::ModeCache* modes) {
  try {
    const study::TableCostEstimate e =
        study::estimate_table_cost(scene, request, plan, distributed::farm_workers(session, farm), modes);
    const study::SeaCell& cell = plan.cells[e.probe_cell];
    fmt::print(stderr,
               "ffrf operability: estimated cost {} for {} records of {:g} s on {} workers (probe: {:g} s of the Hs = "
               "{:g} m, Tp = {:g} s record: set-up {:.1f} s, {:.3g} s per simulated second{}); fewer when the journal "
               "holds some\n",
               distributed::format_duration(e.seconds), e.records, request.duration, e.workers, e.recommended.probe_length,
               cell.significant_height, cell.peak_period, e.recommended.setup_seconds,
               e.recommended.seconds_per_simulated_second,
               plan.verified.empty() ? std::string()
                                     : fmt::format("; converged model {:.3g} s per simulated second",
                                                   e.converged.seconds_per_simulated_second));
  } catch (const std::exception& error) {  // the estimate is a courtesy: the records report their own failures
    fmt::print(stderr, "ffrf operability: no cost estimate (the probe record failed: {})\n", error.what());
  }
}

int run_operability_command(const OperabilityOptions& options) {
  const std::string name = "operability";
  if (options.out.empty()) return bad_input(name, "--out DIR is required: the journal of finished records and the table go there");
  study::OperabilityRequest request;
  const auto hs = parse_axis(options.hs), tp = parse_axis(options.tp);
  if (!hs) return bad_input(name, fmt::format("--hs {}: not an axis a:b:n (n values from a to b, b >= a, 1 <= n <= 100) or one value", options.hs));
  if (!tp) return bad_input(name, fmt::format("--tp {}: not an axis a:b:n (n values from a to b, b >= a, 1 <= n <= 100) or one value", options.tp));
  request.significant_heights = *hs;
  request.peak_periods = *tp;
  request.headings.clear();
  try {
    for (const std::string& heading : options.headings) request.headings.push_back(study::parse_heading(heading));
  } catch (const study::SettingError& error) {
    return bad_input(name, option_message(error));
  }
  request.seeds = options.seeds;
  request.duration = options.duration;
  request.peak_enhancement = options.gamma;
  request.components = options.components;
  request.variance_share = options.band_share;
  request.verify_cells = options.verify;
  request.converged_elements = options.converged_elements;
  request.criteria = options.criteria;
  std::optional<scene::Scene> scene = load_scene(options.scene, options.set, name, true);
  if (!scene) return exit_bad_input;
  if (!scene->is_crane() || !scene->has_cargo()) return bad_input(name, fmt::format("{}: not a floating crane with a cargo", options.scene));
  try {
    request.tolerance = parse_tolerance(options.tolerance);
    study::validate(request);
  } catch (const BadOption& error) {
    return bad_input(name, error.what());
  } catch (const std::invalid_argument& error) {
    return bad_input(name, error.what());
  }

  modal::ModeCache modes;
  study::OperabilityPlan plan;
  try {
    plan = study::plan_operability(*scene, request, &modes);
  } catch (const std::invalid_argument& error) {
    return bad_input(name, error.what());
  }
  distributed::Session session;
  if (session.is_root()) {
    report::png_terminal();  // fail before the computation when gnuplot is missing
    std::filesystem::create_directories(options.out);
    for (const std::string& warning : plan.warnings) fmt::print(stderr, "ffrf {}: warning: {}\n", name, warning);
    if (const std::size_t steep = plan.cells.size() - plan.physical_cells(); steep > 0) {
      fmt::print(stderr, "ffrf {}: {} of {} cells are steeper than a sea can be (DNV-RP-C205's breaking limit): not "
                 "physical, no records run for them\n", name, steep, plan.cells.size());
    }
  }
  distributed::FarmOptions farm;
  farm.output_directory = options.out;
  farm.study = "ffrf " + options.command_line;
  // Everything besides the task keys that a record depends on.
  farm.settings = fmt::format("{}\n{}\nseeds={} duration={:.17g} gamma={:.17g} components={} band_share={:.17g} "
                              "tolerance={:.17g} converged={} verify={}\n",
                              version_text(), read_text(options.scene) + overrides_text(*scene), request.seeds, request.duration,
                              request.peak_enhancement, request.components, request.variance_share, request.tolerance,
                              request.converged_elements, request.verify_cells);
  farm.threads = options.threads;
  if (session.is_root() && stderr_is_terminal()) print_cost_estimate(*scene, request, plan, session, farm, &modes);
  farm.retry_failed = options.retry_failed;
  farm.progress_label = "operability records";
  study::OperabilityStudy result;
  try {
    result = study::run_operability(session, *scene, request, plan, farm);
  } catch (const distributed::JournalError& error) {
    return bad_input(name, error.what());
  }
  if (!result.farm.root) return exit_ok;
  report::OperabilityContext context{options.scene, options.command_line, request.duration, request.seeds,
                                     request.peak_enhancement, request.tolerance, report::operability_sea_text(request)};
  fmt::print(stderr, "{}", report::write_operability_outputs(options.out, result, context));
  fmt::print("{}\nwrote {} (report.md, operability.csv, operability.png, summary.json; journal {})\n",
             report::operability_text(result), options.out, result.farm.journal.string());
  return result.farm.failed > 0 ? exit_failure : exit_ok;
}

}  // namespace

Command add_operability_command(CLI::App& parent) {
  auto options = std::make_shared<OperabilityOptions>();
  CLI::App* sub = parent.add_subcommand(
      "operability", "Operability table over sea states (Hs x Tp x heading, seeds per cell) on the distributed engine");
  sub->add_option("scene", options->scene, "Scene file (TOML) of a floating crane with a cargo")->required();
  add_set_option(*sub, options->set);
  sub->add_option("--hs", options->hs, "Significant wave heights a:b:n [m] (n values from a to b)")->required();
  sub->add_option("--tp", options->tp, "Peak periods a:b:n [s]")->required();
  sub->add_option("--heading", options->headings, "Headings: following, head (several: the grid's third axis)")
      ->capture_default_str()->delimiter(',');
  sub->add_option("--seeds", options->seeds, "Records per cell")->capture_default_str()->check(whole_number(1, 1000));
  sub->add_option("--duration", options->duration, "Length of each record [s]")->capture_default_str()
      ->check(finite_number(0.0, 86400.0, "s", true));
  sub->add_option("--gamma", options->gamma, "JONSWAP peak enhancement of every cell")->capture_default_str()
      ->check(finite_number(1.0, 20.0));
  sub->add_option("--components", options->components,
                  "Wave components per record (0: dw = 2 pi / duration, a sea that never repeats; fewer are cheaper but repeat)")
      ->capture_default_str()->check(whole_number(0, 100000));
  sub->add_option("--band-share", options->band_share,
                  "Share of each cell's wave variance m0 that its synthesis band holds (the rest split equally between "
                  "the low and high tails)")
      ->capture_default_str()->check(finite_number(0.5, 1.0, "", false));
  sub->add_option("--out", options->out, "Output directory: journal.tsv, operability.csv, report.md, operability.png, summary.json");
  sub->add_option("--threads", options->threads, "Compute threads of the process that schedules (0: one per core alone, 1 beside MPI ranks)")
      ->capture_default_str()->check(whole_number(0, 1024));
  sub->add_option("--verify", options->verify, "Cells run again with the converged model (same seeds)")->capture_default_str()
      ->check(whole_number(0, 10000));
  sub->add_option("--converged-elements", options->converged_elements, "Elements of the converged (nodal) model")
      ->capture_default_str()->check(whole_number(2, 256));
  sub->add_flag("--retry-failed", options->retry_failed, "Compute again the records the journal holds as failed");
  add_tolerance_option(*sub, options->tolerance, "the model per cell must meet it (recommend's reasoning)");
  study::OperabilityCriteria& c = options->criteria;
  sub->add_option("--daf-limit", c.daf_limit, "DAF limit (0: offshore in-air DAF of the hook load, GL Noble Denton 0027/ND Table 5-1)")
      ->capture_default_str()->check(finite_number(0.0, 5.0));
  sub->add_option("--slack-margin", c.slack_margin, "Minimum tension as a fraction of the static (DNV-RP-H103: 0.10)")
      ->capture_default_str()->check(finite_number(0.0, 0.99));
  sub->add_option("--cargo-motion-limit", c.cargo_motion_limit, "MPM heave amplitude of the cargo [m] (a planning default)")
      ->capture_default_str()->check(finite_number(0.0, 100.0, "m", true));
  sub->add_option("--moment-capacity", c.root_moment_capacity, "Boom root moment capacity [N m] (0: DAF limit x static moment)")
      ->capture_default_str()->check(finite_number(0.0, 1e15, "N m"));
  sub->add_option("--buckling-ratio", c.buckling_ratio, "Allowed axial compression as a fraction of the Euler load")
      ->capture_default_str()->check(finite_number(0.0, 1.0, "", true));
  return {sub, [options] {
            options->command_line = echoed_command(*options);
            return run_operability_command(*options);
          }};
}

}  // namespace ffrf::app
