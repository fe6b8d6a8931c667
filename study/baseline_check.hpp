// Checking a run against a regression baseline (`ffrf baseline check`): the model is run
// again (the baseline's model unless told otherwise) and every recorded quantity is judged:
//   |value − baseline| ≤ relative × scale + absolute
// with, per quantity,
//  * boom frequency f_j: scale f_j of the baseline, relative 1e-6 by default. ARPACK converges the
//    eigenvalues to machine precision (tolerance 0), so the same model on another compiler or BLAS
//    moves them by ~1e-13; 1e-6 leaves seven orders for that and still catches a change of 2e-6 in
//    E, ρA or L (f ∝ √(E/ρA)/L²).
//  * coupled natural mode j of the linearised crane (Baseline::coupled_modes): its frequency (scale
//    f_j) and damping ratio (scale ζ_j) at the same relative tolerance as the boom frequencies (name
//    "frequencies"): the linearisation is deterministic (difference Jacobians of fixed increments,
//    a dense eigen solver), and E × 1.01 moves the boom-dominated modes by ~5e-3.
//  * statistic (static value, min, max, mean, RMS, std) of a channel and its time history (the RMS
//    over the history's samples of the difference): scale = the channel's standard deviation in the
//    baseline (its motion in the window), at least 1e-6 of its largest magnitude (a channel that
//    hardly moves is judged against its size; an identically zero channel by `absolute` alone).
//    Relative default: the larger of response_tolerance_factor (100) × the baseline's integrator
//    rtol and integration_error_factor (10) × the recorded run's integration error (Baseline::
//    integration_error: the largest deviation of any response from the same run at 1/100 of the
//    tolerances). The recorded run is deterministic (the same program reproduces it bit for bit);
//    what the tolerance must admit is a different but equally valid solution — another compiler,
//    another linear solver, another step sequence — which differs from the recorded one by up to
//    about the sum of the two runs' errors. docs/baselines.md shows it measured on the shipped
//    scenes: the recorded runs' errors are 17–263 × rtol (an undamped spinning boom accumulates
//    phase error), the same models solved by IDA instead of CVODE at the same rtol differ from them
//    by up to 7 × that error, and a stiffer boom (E × 1.01) moves the reference crane's responses by
//    5–125 times the default.
//  * the wire tension's dynamic amplification: scale its baseline value, the responses' relative
//    tolerance (name "wire_amplification").
// Relative tolerances can be set for all responses, per channel (its column name), for
// "frequencies" and for "wire_amplification"; the absolute one (default 0, in each channel's unit)
// for all responses. A quantity that cannot be compared (missing in the run, histories sampled at
// other times) fails with the reason. The model and settings of the run that differ from the
// baseline's are listed, never an error: a baseline recorded by one model checked with another
// reports the model difference and the deviations.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "study/baseline.hpp"

namespace ffrf::study {

inline constexpr double default_frequency_tolerance = 1e-6;
inline constexpr double response_tolerance_factor = 100.0;  // × the baseline's rtol: the floor
inline constexpr double integration_error_factor = 10.0;    // × the recorded run's integration error
// Names of tolerances that are not channels.
inline constexpr const char* frequencies_name = "frequencies";
inline constexpr const char* amplification_name = "wire_amplification";

struct BaselineTolerances {
  std::optional<double> frequency;  // relative; default default_frequency_tolerance
  std::optional<double> relative;   // every response; default: default_response_tolerance()
  double absolute = 0.0;            // every response, in the channel's unit
  std::map<std::string, double> per_name;  // relative: a channel column, frequencies_name or amplification_name
};

// The relative tolerance of the responses when none is given.
double default_response_tolerance(const Baseline& baseline);

// A tolerance that cannot be used: its name ("relative", "absolute", "frequencies", a channel, ...),
// its value and what is wrong (with the valid names or range).
class ToleranceError : public std::invalid_argument {
 public:
  ToleranceError(std::string name, double value, std::string problem);
  const std::string& name() const { return name_; }
  double value() const { return value_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string name_;
  double value_;
  std::string problem_;
};

// Throws ToleranceError for a per-name tolerance that names nothing in the baseline (with the valid
// names) or a tolerance that is negative or not finite.
void validate(const BaselineTolerances& tolerances, const Baseline& baseline);

struct Deviation {
  std::string channel;    // a channel column, "boom" (frequencies), "coupled" (the crane's natural modes) or "wire" (amplification)
  std::string quantity;   // "f1", "zeta1" (coupled), "static", "min", "max", "mean", "rms", "std", "history", "amplification"
  std::string detail;     // "bending 1" of a frequency; "over 0–40 s, 801 samples" of a history
  double baseline = 0.0;  // the recorded value (history: the baseline's RMS about its mean)
  double value = 0.0;     // this run's (history: this run's RMS about the baseline's mean)
  double difference = 0.0;  // |value − baseline| (history: RMS of the sample differences), channel unit
  double scale = 0.0;       // what the relative tolerance multiplies
  double relative_tolerance = 0.0;
  double absolute_tolerance = 0.0;
  double allowed = 0.0;     // relative_tolerance × scale + absolute_tolerance
  bool compared = true;     // false: `problem` says why (a failure)
  std::string problem;
  bool passed = false;
  double normalized() const { return scale > 0.0 ? difference / scale : difference; }  // difference / scale
};

// One setting of the run's model that is not the baseline's.
struct SettingDifference {
  std::string setting;  // "boom model", "elements", ... (neutral words)
  std::string baseline, run;
};
std::vector<SettingDifference> model_differences(const BaselineModel& baseline, const BaselineModel& run);

struct BaselineCheck {
  std::vector<SettingDifference> model_differences;
  double frequency_tolerance = default_frequency_tolerance;
  double response_tolerance = 0.0;  // relative, responses without their own
  bool response_tolerance_given = false;  // false: default_response_tolerance()
  double absolute_tolerance = 0.0;
  std::vector<Deviation> deviations;
  Baseline run;                     // what this run recorded
  int failures() const;
  bool passed() const { return failures() == 0; }
};

// Judges `run` against `baseline` (both recorded; pure: no run). Throws ToleranceError as validate().
BaselineCheck compare_baseline(const Baseline& baseline, const Baseline& run, const BaselineTolerances& tolerances);

// Runs `choice` with `settings` on `scene` (recording the baseline's channels at its decimation) and
// judges it. Throws as record_run() and validate().
BaselineCheck check_baseline(const scene::Scene& scene, const Baseline& baseline, const scene::BoomChoice& choice,
                             const multibody::RunSettings& settings, const BaselineTolerances& tolerances,
                             modal::ModeCache* modes = nullptr);

}  // namespace ffrf::study
