// Experiment 3 of the stability map: the linear floating frame under spin (scenes with a spinning
// [hub], e.g. the Simo & Vu-Quoc spin-up). Without centrifugal stiffening the boom's bending
// stiffness is softened by −Ω²M and the first mode diverges once Ω passes ω1, with growth rate
// σ = √(Ω² − ω1²); with it (K + Ω²K_c) the deflection stays bounded. Each spin rate Ωs × stiffening
// × model (nodal, modal k=4+static) is run over the scene's duration; the Campbell diagram
// (study/campbell.hpp) gives the frequencies against Ω.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "multibody/prescribed_motion.hpp"
#include "fem/analytic_beam.hpp"
#include "study/stability.hpp"

namespace ffrf::study {
namespace {

SpinRun run_spin(const scene::Scene& scene, double spin, const scene::BoomChoice& base, bool stiffened,
                 modal::ModeCache& modes) {
  SpinRun run;
  run.spin = spin;
  run.choice = base;
  run.stiffened = stiffened;
  run.choice.stiffening = stiffened ? scene::Stiffening::centrifugal : scene::Stiffening::none;
  scene::Scene spun = scene;
  spun.hub->spin_rate = spin;
  const multibody::RunSettings settings = integrator_settings(spun, {});
  const multibody::RunResult* samples = nullptr;
  ModelRun model;
  std::shared_ptr<const multibody::RunResult> partial;
  try {
    model = run_model(spun, run.choice, settings, &modes);
    samples = &model.result;
  } catch (const solve::SolverFailure& failure) {
    run.failure = failure.detection();
    run.spin_rate_at_failure = hub_spin_rate(*scene.hub, spin, failure.time());
    partial = multibody::partial_run(failure);
    samples = partial.get();
  }
  if (samples) {
    run.time = samples->time;
    for (const multibody::CraneOutputs& sample : samples->samples) {
      run.deflection.push_back(sample.tip_deflection.y());
      run.max_deflection = std::max(run.max_deflection, std::abs(sample.tip_deflection.y()));
    }
  }
  return run;
}

// max |δ_nodal − δ_modal| / max |δ_nodal| over the common samples.
double agreement(const SpinRun& nodal, const SpinRun& modal) {
  double difference = 0.0;
  const std::size_t n = std::min(nodal.deflection.size(), modal.deflection.size());
  for (std::size_t i = 0; i < n; ++i) difference = std::max(difference, std::abs(nodal.deflection[i] - modal.deflection[i]));
  return nodal.max_deflection > 0.0 ? difference / nodal.max_deflection : NAN;
}

}  // namespace

std::string SpinRun::label() const { return stiffened ? choice.label() : choice.label() + ", no stiffening"; }

double hub_spin_rate(const scene::Hub& hub, double spin, double t) {
  multibody::PrescribedMotion motion;
  motion.profile = hub.motion == scene::HubMotion::spin_up ? multibody::RotationProfile::spin_up
                                                           : multibody::RotationProfile::constant_spin;
  motion.spin_rate = spin;
  motion.spin_up_time = hub.spin_up_time;
  return motion.rate(t);
}

SpinStudy spin_study(const scene::Scene& scene, const StabilityOptions& options) {
  SpinStudy study;
  const int elements = scene.boom.mesh.element_count;
  study.spins = options.quick ? std::vector<double>{2, 4, 6} : std::vector<double>{2, 4, 6, 8, 10};
  study.models = {{scene::BoomKind::nodal, elements}, {scene::BoomKind::modal, elements, 4, true}};
  study.omega1 = fem::analytic_bending_modes(scene.boom.mesh, fem::Boundary::clamped_free, 1)[0].angular_frequency;
  study.settings = integrator_settings(scene, {});
  modal::ModeCache modes;
  for (const scene::BoomChoice& model : study.models) {
    for (bool stiffened : {false, true}) {
      for (double spin : study.spins) {
        if (options.progress) {
          options.progress(fmt::format("spin: Ωs = {} rad/s, {}, {}", spin, model.label(),
                                       stiffened ? "centrifugal stiffening" : "no stiffening"));
        }
        study.runs.push_back(run_spin(scene, spin, model, stiffened, modes));
      }
    }
  }
  const SpinRun* nodal_stiff = nullptr;
  const SpinRun* modal_stiff = nullptr;
  for (const SpinRun& run : study.runs) {
    if (run.spin != study.chart_spin || !run.stiffened) continue;
    (run.choice.kind == scene::BoomKind::nodal ? nodal_stiff : modal_stiff) = &run;
  }
  study.agreement = nodal_stiff && modal_stiff && !nodal_stiff->failure && !modal_stiff->failure
                        ? agreement(*nodal_stiff, *modal_stiff) : NAN;
  study.campbell = campbell_diagram(*scene::boom_beam(scene, elements), SpinRange{0.0, study.spins.back(), 21},
                                    scene::centrifugal_hub_radius(scene), 0.0, 3, modal::EigenSolverKind::arpack, {});
  return study;
}

}  // namespace ffrf::study
