// The reports of `ffrf recommend`: the decision, the reasoning with its numbers, the candidates
// tried (error, work = RHS evaluations × state size, RHS evaluations, wall time), the speed-up over the
// reference and the exact `ffrf run` command line of the chosen model; as plain text (stdout),
// Markdown (recommendation.md) and JSON (recommendation.json, or stdout with --json).
#pragma once

#include <string>

#include "study/recommend.hpp"

namespace ffrf::report {

struct RecommendContext {
  std::string scene_file;
  const scene::Scene* scene = nullptr;
  double tolerance = 0.01;
};

std::string recommend_text(const RecommendContext& context, const study::Recommendation& rec);
std::string recommend_markdown(const RecommendContext& context, const study::Recommendation& rec);
std::string recommend_json(const RecommendContext& context, const study::Recommendation& rec);

// The exact `ffrf run` command line of a candidate (`scene`: the one the candidates were run on).
std::string run_command_line(const std::string& scene_file, const study::Candidate& candidate, double rtol, double duration,
                             const scene::Scene& scene);

}  // namespace ffrf::report
