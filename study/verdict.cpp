// The verdict of a comparison against a tolerance (see verdict.hpp).
#include "study/verdict.hpp"

#include <fmt/format.h>

#include <cmath>

#include "study/run_pipeline.hpp"

namespace ffrf::study {

double solver_work(long rhs_evaluations, int state_size) { return static_cast<double>(rhs_evaluations) * state_size; }

double model_choice_rtol(double tolerance) { return std::pow(10.0, std::floor(std::log10(tolerance / 1e4) + 1e-9)); }

bool passes(const MeasuredModel& m, double tolerance) { return m.ran && std::isfinite(m.error) && m.error <= tolerance; }

std::optional<std::size_t> cheapest_passing(const std::vector<MeasuredModel>& models, double tolerance) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const MeasuredModel& m = models[i];
    if (!passes(m, tolerance) || !m.at_choice_rtol) continue;
    const bool cheaper = !best || m.work < models[*best].work ||
                         (m.work == models[*best].work && m.wall_seconds < models[*best].wall_seconds);
    if (cheaper) best = i;
  }
  return best;
}

Verdict judge(const std::vector<MeasuredModel>& models, double reference_wall_seconds, double reference_work,
              double tolerance) {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw SettingError(Setting::tolerance, fmt::format("{}", tolerance), "not a tolerance (valid range (0, 1))");
  }
  const auto ratio = [](double reference, double model) {
    return reference > 0.0 && model > 0.0 ? reference / model : std::numeric_limits<double>::quiet_NaN();
  };
  Verdict v;
  v.tolerance = tolerance;
  v.reference_wall_seconds = reference_wall_seconds;
  v.reference_work = reference_work;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const MeasuredModel& m = models[i];
    ModelVerdict mv;
    if (m.ran) {
      mv.passed = passes(m, tolerance);
      mv.wall_speedup = ratio(reference_wall_seconds, m.wall_seconds);
      mv.work_speedup = ratio(reference_work, m.work);
      if (std::isfinite(m.error) && (!v.most_accurate || m.error < models[*v.most_accurate].error)) v.most_accurate = i;
    }
    if (!mv.passed) v.failed.push_back(i);
    v.models.push_back(mv);
  }
  v.cheapest = cheapest_passing(models, tolerance);
  return v;
}

}  // namespace ffrf::study
