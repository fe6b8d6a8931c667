// Integrator names, solver failures and the terminal progress line.
#include "coupling/simulation.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "coupling/sundials_support.hpp"

namespace ffrf::coupling {

std::string_view to_string(Integrator integrator) {
  switch (integrator) {
    case Integrator::ida: return "ida";
    case Integrator::cvode: return "cvode";
    case Integrator::arkode: return "arkode";
    case Integrator::generalized_alpha: return "generalized-alpha";
    case Integrator::index1: return "index1";
    case Integrator::baumgarte: return "baumgarte";
    case Integrator::projection: return "projection";
  }
  return "?";
}

std::optional<Integrator> parse_integrator(std::string_view text) {
  for (Integrator i : {Integrator::ida, Integrator::cvode, Integrator::arkode, Integrator::generalized_alpha,
                       Integrator::index1, Integrator::baumgarte, Integrator::projection}) {
    if (text == to_string(i)) return i;
  }
  return std::nullopt;
}

std::string integrator_choices() { return "ida|cvode|arkode|generalized-alpha|index1|baumgarte|projection"; }

namespace {

// A fully prescribed system (a rigid boom on a driven hub without cargo) has no minimal coordinates:
// its motion is kinematics, sampled at the output times (the reactions follow from the driving
// constraint). The full-coordinate formulations still solve for the frame and its multipliers.
RunResult kinematic_run(CraneEquations& equations, const IntegratorSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  RunResult result;
  const Eigen::VectorXd none(0);
  const long outputs = std::lround(settings.duration / settings.output_interval);
  for (long k = 0; k <= outputs; ++k) {
    const double t = static_cast<double>(k) * settings.output_interval;
    result.time.push_back(t);
    result.samples.push_back(equations.minimal_outputs(t, none, none));
  }
  result.stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

bool minimal_coordinate_integrator(Integrator kind) { return kind == Integrator::cvode || kind == Integrator::arkode; }

RunResult dispatch(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings) {
  if (equations.minimal_size() == 0 && minimal_coordinate_integrator(settings.kind)) return kinematic_run(equations, settings);
  switch (settings.kind) {
    case Integrator::ida: return integrate_lagrange(equations, z0, settings);
    case Integrator::cvode: return integrate_minimal(equations, z0, settings);
    case Integrator::arkode: return integrate_explicit(equations, z0, settings);
    case Integrator::generalized_alpha: return integrate_generalized_alpha(equations, z0, settings);
    case Integrator::index1:
    case Integrator::baumgarte:
    case Integrator::projection: return integrate_index1(equations, z0, settings);
  }
  throw std::invalid_argument("unknown integrator");
}

}  // namespace

RunResult integrate(CraneEquations& equations, const Eigen::VectorXd& z0, const IntegratorSettings& settings) {
  RunResult result = dispatch(equations, z0, settings);
  result.detections = post_run_detections(result, settings.monitor);
  return result;
}

namespace sundials {

void Progress::update(double t) {
  if (!enabled_) return;
  const int percent = static_cast<int>(100.0 * t / end_);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  std::fprintf(stderr, "\r%s: t = %7.2f / %.2f s (%3d %%)", label_, t, end_, percent);
  std::fflush(stderr);
}

void Progress::finish() {
  if (enabled_) std::fprintf(stderr, "\r\033[K");
}

}  // namespace sundials
}  // namespace ffrf::coupling
