// Recording a baseline with its integration error (see baseline.hpp): the run, and the same run
// with tighter settings; the largest deviation between the two, judged as a check judges, is the
// recorded run's error estimate. Tighter by 100 (a fixed step: by 4): the error of the tighter run is
// then ~1/100 of the recorded run's (BDF: error ∝ tolerance; generalized-α and RK4 at a quarter of
// the step: 1/16 and 1/256), so the difference is the recorded run's error to a few %. When the
// tighter run fails (a solver can fail at a tolerance it does not fail at otherwise), tighter by 10
// (a fixed step: by 2) is tried, then the baseline says why it has no estimate.
#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "solve/failure.hpp"
#include "study/baseline.hpp"
#include "study/baseline_check.hpp"

namespace ffrf::study {
namespace {

// The largest deviation of any response of `run` from `reference`, in check units.
IntegrationError largest_deviation(const Baseline& run, const Baseline& reference) {
  BaselineTolerances exact;
  exact.relative = 0.0;
  const BaselineCheck difference = compare_baseline(run, reference, exact);
  IntegrationError error;
  error.relative_tolerance = reference.model.relative_tolerance;
  error.absolute_tolerance = reference.model.absolute_tolerance;
  error.fixed_step = reference.model.fixed_step;
  error.steps = reference.cost.steps;
  for (const Deviation& d : difference.deviations) {
    if (d.channel == "boom" || !d.compared) continue;  // the frequencies do not depend on the integration
    if (d.normalized() > error.largest || error.channel.empty()) {
      error.largest = d.normalized();
      error.channel = d.channel;
      error.quantity = d.quantity;
    }
  }
  return error;
}

}  // namespace

Baseline record_baseline(const scene::Scene& scene, const BaselineRequest& request, modal::ModeCache* modes) {
  Baseline baseline = record_run(scene, request, modes);
  BaselineRequest tighter = request;
  tighter.choice = baseline.model.choice;
  tighter.decimation = baseline.decimation;
  for (const ChannelBaseline& channel : baseline.channels) tighter.outputs.push_back(channel.name);
  const bool fixed_step = request.settings.fixed_step > 0.0;
  const std::array<double, 2> factors = fixed_step ? std::array{4.0, 2.0} : std::array{100.0, 10.0};
  std::string failures;
  for (const double factor : factors) {
    if (fixed_step) {
      tighter.settings.fixed_step = request.settings.fixed_step / factor;
    } else {
      tighter.settings.relative_tolerance = request.settings.relative_tolerance / factor;
      tighter.settings.absolute_tolerance = request.settings.absolute_tolerance / factor;
    }
    try {
      baseline.integration_error = largest_deviation(baseline, record_run(scene, tighter, modes));
      return baseline;
    } catch (const solve::SolverFailure& failure) {
      failures += fmt::format("{}at 1/{:g} of the {}: {}", failures.empty() ? "" : "; ", factor,
                              fixed_step ? "step" : "tolerances", failure.what());
    }
  }
  IntegrationError unmeasured;
  unmeasured.problem = "the tighter runs failed: " + failures;
  baseline.integration_error = unmeasured;
  return baseline;
}

}  // namespace ffrf::study
