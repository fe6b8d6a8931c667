// What `ffrf statics` reports about one model's static equilibrium (study/statics.hpp): the text
// report (the run's static report with the hull's offsets, the cargo, the wire against the cargo's
// weight, the force balance and how KINSOL reached it) and the JSON document (the run's
// "static_equilibrium" keys, so that the two can be compared key by key, and the offsets).
#pragma once

#include <string>

#include "study/statics.hpp"

namespace ffrf::report {

std::string statics_text(const std::string& scene_file, const scene::Scene& scene, const study::StaticsResult& result);
std::string statics_json(const std::string& scene_file, const scene::Scene& scene, const study::StaticsResult& result);
// {"command": "statics", "status": "failed", "model", "scene", "failure": {...}, "solver"}.
std::string statics_failure_json(const std::string& scene_file, const scene::Scene& scene, const std::string& model,
                                 const solve::SolverFailure& failure);

}  // namespace ffrf::report
