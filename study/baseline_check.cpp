// Judging a run against a regression baseline (see baseline_check.hpp).
#include "study/baseline_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffrf::study {
namespace {

// The scale the relative tolerance of a channel multiplies (see the header).
double channel_scale(const ChannelBaseline& c) {
  const double magnitude = std::max({std::abs(c.min), std::abs(c.max), std::abs(c.mean)});
  return std::max(c.standard_deviation, 1e-6 * magnitude);
}

void judge(Deviation& d, double relative, double absolute) {
  d.relative_tolerance = relative;
  d.absolute_tolerance = absolute;
  d.allowed = relative * d.scale + absolute;
  d.passed = d.compared && std::isfinite(d.difference) && d.difference <= d.allowed;
}

Deviation not_compared(std::string channel, std::string quantity, std::string problem) {
  Deviation d;
  d.channel = std::move(channel);
  d.quantity = std::move(quantity);
  d.compared = false;
  d.problem = std::move(problem);
  return d;
}

double relative_for(const BaselineTolerances& t, const std::string& name, double fallback) {
  const auto found = t.per_name.find(name);
  return found != t.per_name.end() ? found->second : fallback;
}

void compare_frequencies(const Baseline& baseline, const Baseline& run, double tolerance, std::vector<Deviation>& out) {
  for (std::size_t j = 0; j < baseline.boom_frequencies.size(); ++j) {
    const BoomFrequency& b = baseline.boom_frequencies[j];
    const std::string quantity = fmt::format("f{}", j + 1);
    if (j >= run.boom_frequencies.size()) {
      out.push_back(not_compared("boom", quantity,
                                 fmt::format("this run's boom mesh (N = {}) has only {} modes", run.boom_elements,
                                             run.boom_frequencies.size())));
      continue;
    }
    const BoomFrequency& r = run.boom_frequencies[j];
    Deviation d;
    d.channel = "boom";
    d.quantity = quantity;
    d.detail = r.kind == b.kind && r.order == b.order
                   ? fmt::format("{} {}", b.kind, b.order)
                   : fmt::format("baseline {} {}, this run {} {}", b.kind, b.order, r.kind, r.order);
    d.baseline = b.hz;
    d.value = r.hz;
    d.difference = std::abs(r.hz - b.hz);
    d.scale = b.hz;
    judge(d, tolerance, 0.0);
    out.push_back(d);
  }
}

// The coupled crane's natural modes, matched by order: frequency (scale f_j) and damping ratio
// (scale ζ_j), both at the frequency tolerance.
void compare_coupled_modes(const Baseline& baseline, const Baseline& run, double tolerance, std::vector<Deviation>& out) {
  for (std::size_t j = 0; j < baseline.coupled_modes.size(); ++j) {
    const CoupledFrequency& b = baseline.coupled_modes[j];
    if (j >= run.coupled_modes.size()) {
      out.push_back(not_compared("coupled", fmt::format("f{}", j + 1),
                                 fmt::format("this run's crane has only {} natural modes", run.coupled_modes.size())));
      continue;
    }
    const CoupledFrequency& r = run.coupled_modes[j];
    const std::string detail = r.dominant == b.dominant ? b.dominant : fmt::format("baseline {}, this run {}", b.dominant, r.dominant);
    const std::pair<const char*, double CoupledFrequency::*> quantities[] = {{"f", &CoupledFrequency::hz},
                                                                           {"zeta", &CoupledFrequency::damping_ratio}};
    for (const auto& [name, member] : quantities) {
      Deviation d;
      d.channel = "coupled";
      d.quantity = fmt::format("{}{}", name, j + 1);
      d.detail = detail;
      d.baseline = b.*member;
      d.value = r.*member;
      d.difference = std::abs(d.value - d.baseline);
      d.scale = std::abs(d.baseline);
      judge(d, tolerance, 0.0);
      out.push_back(d);
    }
  }
}

void compare_statistics(const ChannelBaseline& b, const ChannelBaseline& r, double relative, double absolute,
                        std::vector<Deviation>& out) {
  const std::pair<const char*, double ChannelBaseline::*> statistics[] = {
      {"static", &ChannelBaseline::static_value}, {"min", &ChannelBaseline::min}, {"max", &ChannelBaseline::max},
      {"mean", &ChannelBaseline::mean},           {"rms", &ChannelBaseline::rms}, {"std", &ChannelBaseline::standard_deviation}};
  for (const auto& [name, member] : statistics) {
    Deviation d;
    d.channel = b.name;
    d.quantity = name;
    d.baseline = b.*member;
    d.value = r.*member;
    d.difference = std::abs(d.value - d.baseline);
    d.scale = channel_scale(b);
    judge(d, relative, absolute);
    out.push_back(d);
  }
}

// The histories at the times both sampled: the baseline's times are a prefix of the run's or the
// other way round (a run of another duration); other times cannot be compared.
void compare_history(const Baseline& baseline, const ChannelBaseline& b, const Baseline& run, const ChannelBaseline& r,
                     double relative, double absolute, std::vector<Deviation>& out) {
  const std::size_t common = std::min(baseline.history_time.size(), run.history_time.size());
  bool same_times = common > 0 && b.history.size() == baseline.history_time.size() && r.history.size() == run.history_time.size();
  for (std::size_t i = 0; same_times && i < common; ++i) {
    same_times = std::abs(baseline.history_time[i] - run.history_time[i]) <= 1e-9 * std::max(1.0, std::abs(baseline.history_time[i]));
  }
  if (!same_times) {
    out.push_back(not_compared(
        b.name, "history",
        fmt::format("sampled at other times: the baseline has {} samples every {:g} s, this run {} every {:g} s",
                    baseline.history_time.size(), baseline.model.output_interval * baseline.decimation,
                    run.history_time.size(), run.model.output_interval * run.decimation)));
    return;
  }
  double mean = 0.0;
  for (std::size_t i = 0; i < common; ++i) mean += b.history[i];
  mean /= static_cast<double>(common);
  double squared_difference = 0.0, squared_baseline = 0.0, squared_run = 0.0;
  for (std::size_t i = 0; i < common; ++i) {
    squared_difference += (r.history[i] - b.history[i]) * (r.history[i] - b.history[i]);
    squared_baseline += (b.history[i] - mean) * (b.history[i] - mean);
    squared_run += (r.history[i] - mean) * (r.history[i] - mean);
  }
  const double n = static_cast<double>(common);
  Deviation d;
  d.channel = b.name;
  d.quantity = "history";
  d.detail = fmt::format("{} samples over {:g}-{:g} s{}", common, baseline.history_time.front(), baseline.history_time[common - 1],
                         baseline.history_time.size() == run.history_time.size() ? "" : " (the runs' common part)");
  d.baseline = std::sqrt(squared_baseline / n);
  d.value = std::sqrt(squared_run / n);
  d.difference = std::sqrt(squared_difference / n);
  d.scale = channel_scale(b);
  judge(d, relative, absolute);
  out.push_back(d);
}

void compare_amplification(const Baseline& baseline, const Baseline& run, double relative, std::vector<Deviation>& out) {
  if (!baseline.wire_amplification) return;
  if (!run.wire_amplification) {
    out.push_back(not_compared("wire", "amplification", "this run has no wire tension amplification (no wire)"));
    return;
  }
  Deviation d;
  d.channel = "wire";
  d.quantity = "amplification";
  d.detail = "max tension over the run / static tension";
  d.baseline = *baseline.wire_amplification;
  d.value = *run.wire_amplification;
  d.difference = std::abs(d.value - d.baseline);
  d.scale = std::abs(d.baseline);
  judge(d, relative, 0.0);
  out.push_back(d);
}

}  // namespace

double default_response_tolerance(const Baseline& baseline) {
  const double floor = response_tolerance_factor * baseline.model.relative_tolerance;
  const std::optional<IntegrationError>& error = baseline.integration_error;
  return error && error->measured() ? std::max(floor, integration_error_factor * error->largest) : floor;
}

ToleranceError::ToleranceError(std::string name, double value, std::string problem)
    : std::invalid_argument(fmt::format("tolerance {} = {}: {}", name, value, problem)),
      name_(std::move(name)),
      value_(value),
      problem_(std::move(problem)) {}

void validate(const BaselineTolerances& tolerances, const Baseline& baseline) {
  const auto check_value = [](const std::string& name, double value) {
    if (!(value >= 0.0) || !std::isfinite(value)) throw ToleranceError(name, value, "not a tolerance (valid range [0, inf))");
  };
  if (tolerances.frequency) check_value(frequencies_name, *tolerances.frequency);
  if (tolerances.relative) check_value("relative", *tolerances.relative);
  check_value("absolute", tolerances.absolute);
  std::string names = frequencies_name;
  if (baseline.wire_amplification) names += std::string(", ") + amplification_name;
  for (const ChannelBaseline& channel : baseline.channels) names += ", " + channel.name;
  for (const auto& [name, value] : tolerances.per_name) {
    const bool known = name == frequencies_name || (name == amplification_name && baseline.wire_amplification) ||
                       baseline.channel(name) != nullptr;
    if (!known) throw ToleranceError(name, value, fmt::format("the baseline has no channel or quantity '{}'; it has {}", name, names));
    check_value(name, value);
  }
}

std::vector<SettingDifference> model_differences(const BaselineModel& b, const BaselineModel& r) {
  std::vector<SettingDifference> out;
  const auto differ = [&](const char* setting, const std::string& baseline, const std::string& run) {
    if (baseline != run) out.push_back({setting, baseline, run});
  };
  differ("boom model", std::string(scene::to_string(b.choice.kind)), std::string(scene::to_string(r.choice.kind)));
  differ("elements", fmt::format("{}", b.choice.elements), fmt::format("{}", r.choice.elements));
  if (b.choice.kind == scene::BoomKind::modal && r.choice.kind == scene::BoomKind::modal) {  // else: the boom model differs
    differ("vibration modes", fmt::format("{}", b.choice.modes), fmt::format("{}", r.choice.modes));
    differ("static correction modes", b.choice.static_modes ? "with" : "without", r.choice.static_modes ? "with" : "without");
    differ("mode set", std::string(fem::to_string(b.choice.mode_set)), std::string(fem::to_string(r.choice.mode_set)));
  }
  const auto stiffening = [](const scene::BoomChoice& c) {
    return c.stiffening ? std::string(scene::to_string(*c.stiffening)) : std::string("the scene's");
  };
  differ("geometric stiffening", stiffening(b.choice), stiffening(r.choice));
  differ("integrator", std::string(solve::to_string(b.integrator)), std::string(solve::to_string(r.integrator)));
  differ("relative tolerance", fmt::format("{:g}", b.relative_tolerance), fmt::format("{:g}", r.relative_tolerance));
  differ("absolute tolerance", fmt::format("{:g}", b.absolute_tolerance), fmt::format("{:g}", r.absolute_tolerance));
  differ("duration", fmt::format("{:g} s", b.duration), fmt::format("{:g} s", r.duration));
  differ("output interval", fmt::format("{:g} s", b.output_interval), fmt::format("{:g} s", r.output_interval));
  differ("fixed step", fmt::format("{:g} s", b.fixed_step), fmt::format("{:g} s", r.fixed_step));
  differ("largest BDF order", fmt::format("{}", b.max_order), fmt::format("{}", r.max_order));
  return out;
}

int BaselineCheck::failures() const {
  return static_cast<int>(std::count_if(deviations.begin(), deviations.end(), [](const Deviation& d) { return !d.passed; }));
}

BaselineCheck compare_baseline(const Baseline& baseline, const Baseline& run, const BaselineTolerances& tolerances) {
  validate(tolerances, baseline);
  BaselineCheck check;
  check.model_differences = model_differences(baseline.model, run.model);
  check.frequency_tolerance =
      relative_for(tolerances, frequencies_name, tolerances.frequency.value_or(default_frequency_tolerance));
  check.response_tolerance = tolerances.relative.value_or(default_response_tolerance(baseline));
  check.response_tolerance_given = tolerances.relative.has_value();
  check.absolute_tolerance = tolerances.absolute;
  compare_frequencies(baseline, run, check.frequency_tolerance, check.deviations);
  compare_coupled_modes(baseline, run, check.frequency_tolerance, check.deviations);
  for (const ChannelBaseline& b : baseline.channels) {
    const double relative = relative_for(tolerances, b.name, check.response_tolerance);
    const ChannelBaseline* r = run.channel(b.name);
    if (r == nullptr) {
      check.deviations.push_back(not_compared(b.name, "statistics", "this run did not record the channel"));
      continue;
    }
    compare_statistics(b, *r, relative, tolerances.absolute, check.deviations);
    compare_history(baseline, b, run, *r, relative, tolerances.absolute, check.deviations);
  }
  compare_amplification(baseline, run, relative_for(tolerances, amplification_name, check.response_tolerance),
                        check.deviations);
  check.run = run;
  return check;
}

BaselineCheck check_baseline(const scene::Scene& scene, const Baseline& baseline, const scene::BoomChoice& choice,
                             const multibody::RunSettings& settings, const BaselineTolerances& tolerances,
                             modal::ModeCache* modes) {
  validate(tolerances, baseline);
  BaselineRequest request;
  request.choice = choice;
  request.settings = settings;
  for (const ChannelBaseline& channel : baseline.channels) request.outputs.push_back(channel.name);
  request.decimation = baseline.decimation;
  return compare_baseline(baseline, record_run(scene, request, modes), tolerances);
}

}  // namespace ffrf::study
