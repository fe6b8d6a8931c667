// Running sweep configurations and their CSV rows (see sweep_run.hpp).
#include "app/sweep_run.hpp"

#include <fmt/format.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "coupling/static_equilibrium.hpp"

namespace ffrf::app {
namespace {

// Building a crane computes mode shapes with ARPACK, whose Fortran routines keep state in SAVE
// variables: builds are serialized, the static equilibrium and integration run concurrently.
std::mutex& build_mutex() {
  static std::mutex mutex;
  return mutex;
}

// Shortest exact form; empty for "no value" (NaN, infinity, or not applicable).
std::string number(double value) { return std::isfinite(value) ? fmt::format("{}", value) : std::string(); }

std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) {
    if (c == '"') q += "\"\"";
    else if (c == '\n' || c == '\r') q += ' ';
    else q += c;
  }
  return q + "\"";
}

std::string unit_slug(std::string_view unit) { return unit == "N m" ? "Nm" : std::string(unit); }

// Generalized-α rounds its step down to divide the output interval (theory §8.3).
double dividing_step(double requested, double output_interval) {
  return output_interval / std::ceil(output_interval / requested - 1e-9);
}

}  // namespace

std::string_view to_string(RunStatus status) {
  switch (status) {
    case RunStatus::ok: return "ok";
    case RunStatus::failed: return "failed";
    case RunStatus::skipped: return "skipped";
  }
  return "?";
}

SweepResult run_configuration(const SweepSetup& setup, const SweepConfig& config) {
  SweepResult r;
  r.config = config;
  coupling::IntegratorSettings settings;
  settings.kind = config.integrator;
  settings.relative_tolerance = config.rtol > 0.0 ? config.rtol : 1e-6;
  settings.absolute_tolerance = settings.relative_tolerance;
  settings.duration = setup.duration;
  settings.output_interval = setup.output_interval;
  if (config.step > 0.0) r.step = settings.fixed_step = dividing_step(config.step, setup.output_interval);
  try {
    std::unique_ptr<coupling::CraneEquations> equations;
    {
      const std::lock_guard lock(build_mutex());
      equations = cases::build_crane(*setup.scene, config.choice);
    }
    const coupling::StaticEquilibrium statics = coupling::solve_static_equilibrium(*equations, equations->initial_guess());
    const Eigen::VectorXd z0 = setup.scene->simulation.initial_state == cases::InitialState::static_equilibrium
                                   ? statics.z
                                   : equations->initial_guess();
    if (config.integrator == coupling::Integrator::arkode) {
      r.stable_step = coupling::explicit_stable_step(*equations, z0);
      const double h = config.stability_factor > 0.0 ? config.stability_factor * r.stable_step : r.stable_step;
      if (config.stability_factor > 0.0) r.step = settings.fixed_step = h;
      const double needed = setup.duration / h;
      if (config.stability_factor <= 1.0 && needed > static_cast<double>(setup.max_explicit_steps)) {
        r.status = RunStatus::skipped;
        r.reason = fmt::format("not run: the explicit stability limit {:.3g} s needs about {:.2g} steps for {:g} s, more "
                               "than the sweep's budget of {:.2g}",
                               r.stable_step, needed, setup.duration, static_cast<double>(setup.max_explicit_steps));
        return r;
      }
    }
    const coupling::RunResult run = coupling::integrate(*equations, z0, settings);
    r.errors = coupling::compare_runs(run, *setup.reference, setup.window_start);
    r.stats = run.stats;
  } catch (const coupling::SolverFailure& failure) {
    r.status = RunStatus::failed;
    r.reason = fmt::format("{}: {} (t = {:g} s)", failure.solver(), failure.cause(), failure.time());
  } catch (const std::exception& error) {
    r.status = RunStatus::failed;
    r.reason = error.what();
  }
  return r;
}

std::vector<SweepResult> run_sweep(const SweepSetup& setup, const std::vector<SweepConfig>& configs, int jobs,
                                   const std::function<void(const SweepResult&, std::size_t)>& progress) {
  std::vector<SweepResult> results(configs.size());
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex progress_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < configs.size(); i = next++) {
      results[i] = run_configuration(setup, configs[i]);
      const std::lock_guard lock(progress_mutex);
      ++done;
      if (progress) progress(results[i], done);
    }
  };
  std::vector<std::thread> threads;
  const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), configs.size());
  for (std::size_t t = 0; t < count; ++t) threads.emplace_back(worker);
  for (std::thread& thread : threads) thread.join();
  return results;
}

std::string sweep_csv_header() {
  std::string h = "id,model,family,elements,modes,static_modes,integrator,rtol,step,erk_stable_step";
  for (const auto channel : coupling::all_channels) h += fmt::format(",{}_nrms", coupling::channel_name(channel));
  for (const auto channel : coupling::all_channels) {
    h += fmt::format(",{}_max_{}", coupling::channel_name(channel), unit_slug(coupling::channel_unit(channel)));
  }
  return h + ",daf_error,worst_nrms,steps,rhs_evaluations,jacobian_evaluations,newton_iterations,status,reason,wall_s\n";
}

std::string sweep_csv_line(const SweepResult& r) {
  const SweepConfig& c = r.config;
  const bool modal = c.choice.kind == cases::BoomKind::modal;
  std::string line = fmt::format(
      "{},{},{},{},{},{},{},{},{},{}", c.id, c.choice.label(), model_family(c.choice),
      c.choice.kind == cases::BoomKind::rigid ? std::string() : std::to_string(c.choice.elements),
      modal ? std::to_string(c.choice.modes) : std::string(), modal ? (c.choice.static_modes ? "1" : "0") : "",
      coupling::to_string(c.integrator), c.rtol > 0.0 ? number(c.rtol) : std::string(), r.step > 0.0 ? number(r.step) : "",
      r.stable_step > 0.0 ? number(r.stable_step) : "");
  const bool ok = r.status == RunStatus::ok;
  for (const auto& e : r.errors.channels) line += "," + (ok ? number(e.normalized_rms) : std::string());
  for (const auto& e : r.errors.channels) line += "," + (ok ? number(e.max_abs) : std::string());
  line += "," + (ok ? number(r.errors.daf_error) : std::string());
  line += "," + (ok ? number(r.errors.worst_normalized_rms()) : std::string());
  if (ok) {
    line += fmt::format(",{},{},{},{}", r.stats.steps, r.stats.function_evaluations, r.stats.jacobian_evaluations,
                        r.stats.newton_iterations);
  } else {
    line += ",,,,";
  }
  line += fmt::format(",{},{},{}\n", to_string(r.status), r.reason.empty() ? std::string() : quoted(r.reason),
                      ok ? number(r.stats.wall_seconds) : std::string());
  return line;
}

}  // namespace ffrf::app
