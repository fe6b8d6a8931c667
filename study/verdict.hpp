// The verdict of a comparison against a tolerance, the same in `ffrf compare` and
// `ffrf sweep` as in recommend's decision: a measured model passes when its worst error over the
// judged outputs (study/error_measure.hpp: the total error, static and dynamic together) is within
// the tolerance τ; its speed-ups are the reference's wall time and solver work over its own, work
// being steps × state size (recommend's measure of cost: it does not depend on the machine's load);
// the verdict names the cheapest model that passes — the least solver work, wall time breaking a
// tie — and the models that fail (their error beyond τ, or their run failed or was skipped).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ffrf::study {

// One measured model (a compare model, or a sweep configuration), as the verdict sees it.
struct MeasuredModel {
  std::string label;
  bool ran = true;             // false: its run failed or was skipped (reason)
  std::string reason;
  double error = std::numeric_limits<double>::quiet_NaN();  // worst normalized RMS over the judged outputs
  std::string worst_output;
  double wall_seconds = 0.0;   // integration
  double work = 0.0;           // steps × state size
};

struct ModelVerdict {
  bool passed = false;
  double wall_speedup = std::numeric_limits<double>::quiet_NaN();  // reference wall time / the model's
  double work_speedup = std::numeric_limits<double>::quiet_NaN();  // reference work / the model's
};

struct Verdict {
  double tolerance = 0.0;
  double reference_wall_seconds = 0.0, reference_work = 0.0;
  std::vector<ModelVerdict> models;        // per measured model, in its order
  std::optional<std::size_t> cheapest;     // the passing model with the least work
  std::optional<std::size_t> most_accurate;  // the ran model with the smallest error (finite)
  std::vector<std::size_t> failed;         // models that did not pass, in order
  std::size_t passed_count() const { return models.size() - failed.size(); }
};

// Throws SettingError (Setting::tolerance) unless 0 < tolerance < 1.
Verdict judge(const std::vector<MeasuredModel>& models, double reference_wall_seconds, double reference_work,
              double tolerance);

}  // namespace ffrf::study
