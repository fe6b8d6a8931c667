// The decision sentence of `ffrf recommend` when no candidate passes (report/recommend_report.hpp):
// with a converged reference it names the reference as the model to use; with a reference whose own
// refinement levels disagree (as in the irregular BEM barge's slack-wire record, outputs changed by 2.34
// and 2.85 between levels) it must not recommend that reference, and says why and what to try.
#include <gtest/gtest.h>

#include <string>

#include "report/recommend_report.hpp"

namespace {

using namespace ffrf;

study::Recommendation failed_recommendation(bool reference_converged) {
  study::Recommendation rec;
  rec.outputs = {multibody::OutputChannel::cargo_heave};
  rec.duration = 600.0;
  rec.reference.choice.kind = scene::BoomKind::nodal;
  rec.reference.choice.elements = 32;
  rec.reference.converged = reference_converged;
  rec.reference.bound = 1e-3;
  study::ReferenceLevel coarse, fine;
  coarse.elements = 16;
  fine.elements = 32;
  fine.change = reference_converged ? 2e-4 : 2.85;
  rec.reference.levels = {coarse, fine};
  return rec;
}

TEST(RecommendReport, NothingPassedWithAnUnconvergedReferenceDoesNotRecommendTheReference) {
  const report::RecommendContext context{"sea.toml", nullptr, 0.01};
  const std::string unconverged = report::recommend_text(context, failed_recommendation(false));
  EXPECT_NE(unconverged.find("did not converge"), std::string::npos) << unconverged;
  EXPECT_NE(unconverged.find("2.85"), std::string::npos) << unconverged;
  EXPECT_EQ(unconverged.find("model the scene with the reference"), std::string::npos) << unconverged;
  const std::string converged = report::recommend_text(context, failed_recommendation(true));
  EXPECT_NE(converged.find("model the scene with the reference (nodal N=32"), std::string::npos) << converged;
}

}  // namespace
