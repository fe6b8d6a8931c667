// Recording a regression baseline: one run through the one pipeline, the boom's frequencies, the
// statistics and decimated histories of the chosen outputs (see baseline.hpp).
#include "study/baseline.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "multibody/error_metrics.hpp"
#include "fem/boundary.hpp"
#include "scene/irregular_sea.hpp"
#include "study/error_measure.hpp"
#include "study/modes.hpp"
#include "study/rao.hpp"
#include "study/output_series.hpp"

namespace ffrf::study {

BaselineModel baseline_model(const scene::Scene& scene, const scene::BoomChoice& choice,
                             const multibody::RunSettings& settings) {
  BaselineModel model;
  model.choice = choice;
  model.choice.stiffening = choice.stiffening.value_or(scene.boom.stiffening);
  model.integrator = settings.kind;
  model.relative_tolerance = settings.relative_tolerance;
  model.absolute_tolerance = settings.absolute_tolerance;
  model.duration = settings.duration;
  model.output_interval = settings.output_interval;
  model.fixed_step = settings.fixed_step;
  model.max_order = settings.max_order;
  return model;
}

DynamicsRequest dynamics_request(const BaselineModel& model) {
  return {model.integrator, model.relative_tolerance, model.absolute_tolerance, model.duration, model.fixed_step,
          model.max_order};
}

const ChannelBaseline* Baseline::channel(const std::string& name) const {
  const auto found = std::find_if(channels.begin(), channels.end(), [&](const ChannelBaseline& c) { return c.name == name; });
  return found == channels.end() ? nullptr : &*found;
}

std::string series_column(multibody::OutputChannel channel) { return std::string(multibody::output_channel(channel).column); }

std::optional<std::string> output_column(const std::string& name) {
  for (const SeriesSpec& spec : crane_series()) {
    if (spec.column == name || spec.name == name) return std::string(spec.column);
  }
  return std::nullopt;
}

std::string output_columns() {
  std::string list;
  for (const SeriesSpec& spec : crane_series()) list += (list.empty() ? "" : ", ") + std::string(spec.column);
  return list;
}

int history_decimation(const scene::Scene& scene, double output_interval, double first_boom_hz) {
  double shortest = INFINITY;
  if (scene::has_waves(scene)) shortest = std::min(shortest, scene::shortest_wave_period(scene));
  if (scene.hub && scene.hub->motion != scene::HubMotion::fixed && scene.hub->spin_rate != 0.0) {
    shortest = std::min(shortest, 2.0 * std::numbers::pi / std::abs(scene.hub->spin_rate));
  }
  if (first_boom_hz > 0.0) shortest = std::min(shortest, 1.0 / first_boom_hz);
  if (scene.wire && scene.cargo) {  // the cargo bouncing on the wire's stiffness
    shortest = std::min(shortest, 2.0 * std::numbers::pi * std::sqrt(scene.cargo->mass / scene.wire->stiffness));
  }
  if (!std::isfinite(shortest)) return 1;
  return std::max(1, static_cast<int>(std::floor(shortest / (history_points_per_period * output_interval))));
}

std::vector<BoomFrequency> boom_frequencies(const scene::Scene& scene, int elements) {
  fem::BeamMesh mesh = scene.boom.mesh;
  mesh.element_count = elements;
  const int count = std::min(baseline_boom_modes, free_dof_count(mesh, fem::Boundary::clamped_free) - 1);
  std::vector<BoomFrequency> frequencies;
  if (count < 1) return frequencies;
  const ModesResult modes = solve_modes(mesh, fem::Boundary::clamped_free, modal::EigenSolverKind::arpack, count);
  for (const modal::ClassifiedMode& mode : modes.modes) {
    frequencies.push_back({mode.angular_frequency / (2.0 * std::numbers::pi), std::string(fem::to_string(mode.kind)), mode.order});
  }
  return frequencies;
}

std::vector<CoupledFrequency> coupled_frequencies(const scene::Scene& scene, const scene::BoomChoice& choice,
                                                  modal::ModeCache* modes) {
  std::vector<CoupledFrequency> out;
  if (!scene.is_crane()) return out;
  for (const NaturalMode& mode : coupled_natural_modes(scene, choice, modes)) {
    if (out.size() == static_cast<std::size_t>(baseline_coupled_modes)) break;
    out.push_back({mode.angular_frequency / (2.0 * std::numbers::pi), mode.damping_ratio, mode.dominant});
  }
  return out;
}

namespace {

std::vector<std::string> chosen_columns(const scene::Scene& scene, const std::vector<std::string>& outputs) {
  std::vector<std::string> columns;
  if (outputs.empty()) {
    for (const multibody::OutputChannel channel : judged_outputs(scene)) columns.push_back(series_column(channel));
    return columns;
  }
  for (const std::string& name : outputs) {
    const std::optional<std::string> column = output_column(name);
    if (!column) throw std::invalid_argument(fmt::format("unknown output '{}'; choose from {}", name, output_columns()));
    if (std::find(columns.begin(), columns.end(), *column) == columns.end()) columns.push_back(*column);
  }
  return columns;
}

}  // namespace

Baseline record_run(const scene::Scene& scene, const BaselineRequest& request, modal::ModeCache* modes) {
  const std::vector<std::string> columns = chosen_columns(scene, request.outputs);
  Baseline baseline;
  baseline.model = baseline_model(scene, request.choice, request.settings);
  baseline.boom_elements = request.choice.elements;
  baseline.boom_frequencies = boom_frequencies(scene, request.choice.elements);

  baseline.coupled_modes = coupled_frequencies(scene, baseline.model.choice, modes);
  const ModelRun run = run_model(scene, baseline.model.choice, request.settings, modes);
  baseline.cost = run.result.stats;
  baseline.window_start = run.window.start_s;
  baseline.window_after_ramp = run.window.after_ramp;
  if (scene.wire && std::isfinite(run.amplification)) baseline.wire_amplification = run.amplification;

  const double first_hz = baseline.boom_frequencies.empty() ? 0.0 : baseline.boom_frequencies.front().hz;
  baseline.decimation = request.decimation.value_or(history_decimation(scene, request.settings.output_interval, first_hz));
  if (baseline.decimation < 1) throw std::invalid_argument(fmt::format("history decimation {}: not a sample count (valid range [1, inf))", baseline.decimation));
  const std::size_t step = static_cast<std::size_t>(baseline.decimation);
  for (std::size_t i = 0; i < run.result.time.size(); i += step) baseline.history_time.push_back(run.result.time[i]);

  for (const std::string& column : columns) {
    const std::size_t index = series_index(column);
    const SeriesSpec& spec = crane_series()[index];
    const SeriesStats& stats = run.stats[index];
    ChannelBaseline channel;
    channel.name = column;
    channel.unit = std::string(spec.unit);
    channel.about_static = spec.about_static;
    channel.static_value = spec.value(run.static_outputs());
    channel.min = stats.min;
    channel.max = stats.max;
    channel.mean = stats.mean;
    channel.rms = stats.rms;
    channel.standard_deviation = stats.standard_deviation;
    for (std::size_t i = 0; i < run.result.samples.size(); i += step) {
      channel.history.push_back(series_value(spec, run.result.samples[i], run.static_outputs()));
    }
    baseline.channels.push_back(std::move(channel));
  }
  return baseline;
}

}  // namespace ffrf::study
