// The reports of `ffrf recommend`: the decision, the reasoning with its numbers, the candidates
// tried (error, work = steps × state size, RHS evaluations, wall time), the speed-up over the
// reference and the exact `ffrf run` command line of the chosen model; as plain text (stdout),
// Markdown (recommendation.md) and JSON (recommendation.json, or stdout with --json).
#pragma once

#include <string>
#include <vector>

#include "app/recommend_candidates.hpp"

namespace ffrf::app {

struct RecommendContext {
  std::string scene_file;
  const cases::Scene* scene = nullptr;
  RecommendRequest request;
};

std::string recommend_text(const RecommendContext& context, const Recommendation& rec);
std::string recommend_markdown(const RecommendContext& context, const Recommendation& rec);
std::string recommend_json(const RecommendContext& context, const Recommendation& rec);

// "cargo_heave,wire_tension"
std::string output_list(const std::vector<coupling::OutputChannel>& outputs);

}  // namespace ffrf::app
