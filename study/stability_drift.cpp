// Experiment 2 of the stability map: the clamp at B treated five ways — minimal coordinates
// (cvode), Lagrange multipliers as a stabilized index-2 DAE (ida), and the index-1 ODE
// unstabilized, with Baumgarte feedback and with projection (multibody/constraint_drift.hpp) — on
// one elastic model from the scene's initial state: |C(t)| per formulation against the scene's drift
// bound (simulation.constraint_drift_limit), with the cost of each.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "multibody/constraint_drift.hpp"
#include "study/stability.hpp"

namespace ffrf::study {

const solve::Detection* DriftRun::drift_detection() const {
  if (!run) return nullptr;
  const auto& detections = run->result.detections;
  const auto fired = std::find_if(detections.begin(), detections.end(), [](const solve::Detection& d) {
    return d.kind == solve::FailureKind::constraint_drift;
  });
  return fired == detections.end() ? nullptr : &*fired;
}

double DriftStudy::max_drift(solve::Integrator formulation) const {
  for (const DriftRun& run : runs) {
    if (run.formulation == formulation && run.run) return run.max_residual;
  }
  return NAN;
}

DriftStudy constraint_drift_study(const scene::Scene& scene, const StabilityOptions& options) {
  DriftStudy study;
  // Elastic, so the clamp carries moving loads (a rigid boom on a fixed hub would not move at all).
  study.choice = {scene::BoomKind::nodal, 4};
  DynamicsRequest request;
  request.duration = std::min(scene.simulation.duration, options.quick ? 10.0 : 60.0);
  study.settings = integrator_settings(scene, request);
  study.cargo_lift = scene.simulation.cargo_lift;
  study.limit = study.settings.monitor.constraint_drift_limit;
  modal::ModeCache modes;
  for (solve::Integrator formulation : multibody::constraint_formulations()) {
    if (options.progress) {
      options.progress(fmt::format("constraint drift: {} on {}, {} s", solve::to_string(formulation),
                                   study.choice.label(), study.settings.duration));
    }
    DriftRun drift{formulation, std::nullopt, std::nullopt};
    multibody::RunSettings settings = study.settings;
    settings.kind = formulation;
    try {
      drift.run = run_model(scene, study.choice, settings, &modes);
      for (const multibody::CraneOutputs& sample : drift.run->result.samples) {
        drift.max_residual = std::max(drift.max_residual, sample.constraint_residual);
      }
      if (!drift.run->result.samples.empty()) drift.final_residual = drift.run->result.samples.back().constraint_residual;
    } catch (const solve::SolverFailure& failure) {
      drift.failure = failure.detection();
    }
    study.runs.push_back(std::move(drift));
  }
  return study;
}

}  // namespace ffrf::study
