// What `ffrf baseline record` and `ffrf baseline check` print (docs/baselines.md): the recorded baseline
// in a few lines, and the check's verdict — every quantity with its baseline value, this run's, the
// size of the deviation, the tolerance it was judged against and pass/fail, the model differences,
// the channels that moved — as text or JSON.
#pragma once

#include <string>

#include "report/baseline_file.hpp"
#include "study/baseline_check.hpp"

namespace ffrf::report {

// The recorded baseline: provenance, model, frequencies, statistics, decimation, cost.
std::string baseline_record_text(const BaselineFile& file);

// Where the check's run came from next to the baseline's.
struct BaselineCheckContext {
  std::string baseline_path;
  const BaselineFile* baseline = nullptr;
  std::string scene_path;
  std::string scene_hash;  // of the scene checked now
};

// The check as a table and a verdict line.
std::string baseline_check_text(const BaselineCheckContext& context, const study::BaselineCheck& check);
// The check as JSON: {"verdict", "failures", "model_differences", "tolerances", "deviations": [...], ...}.
std::string baseline_check_json(const BaselineCheckContext& context, const study::BaselineCheck& check);

}  // namespace ffrf::report
