// The time domain against the frequency domain: regular-wave time-domain runs of the crane (the one run pipeline, CVODE
// on the minimal coordinates, nonlinear hull pressure on the wetted box) at three periods reproduce
// the frequency domain's RAO amplitudes (study/rao.hpp) within 1 % for hull heave and pitch and
// cargo heave, once the free modes are separated out of the settled response (study/rao_check.hpp).
#include <gtest/gtest.h>

#include <cstdio>

#include "study/rao_check.hpp"
#include "study_test_support.hpp"

namespace ffrf {
namespace rao_time_domain_test {

void expect_within_one_percent(const study::TimeDomainCheck& check) {
  for (const auto& period : check.periods) {
    for (const auto& channel : period.channels) {
      std::printf("%s T=%.1f s %s: RAO %.6g, time domain %.6g, deviation %+.3e, phase %+.2e rad, fit residual %.1e "
                  "(%d free modes, %ld steps, %.2f s)\n",
                  check.choice.label().c_str(), period.period, std::string(multibody::to_string(channel.output)).c_str(),
                  channel.frequency_domain, channel.time_domain, channel.deviation(), channel.phase_difference,
                  channel.fit_residual, period.fitted_modes, period.stats.steps, period.stats.wall_seconds);
      EXPECT_LT(std::abs(channel.deviation()), 0.01)
          << check.choice.label() << " T = " << period.period << " s " << multibody::to_string(channel.output);
      EXPECT_LT(std::abs(channel.phase_difference), 0.01) << period.period << " " << multibody::to_string(channel.output);
    }
  }
  EXPECT_TRUE(check.passed());
}

TEST(RaoTimeDomain, RegularWaveRunsReproduceTheRaosOfTheModalCrane) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  expect_within_one_percent(study::check_time_domain(scene, {scene::BoomKind::modal, 16, 2, true}, {}));
}

TEST(RaoTimeDomain, RegularWaveRunsReproduceTheRaosOfTheNodalAndRigidCranes) {
  const scene::Scene scene = test::scene_file("paper_floating_crane.toml");
  study::TimeDomainCheckRequest request;
  request.periods = {10.0};
  expect_within_one_percent(study::check_time_domain(scene, {scene::BoomKind::nodal, 16}, request));
  expect_within_one_percent(study::check_time_domain(scene, {scene::BoomKind::rigid, 1}, request));
}

}  // namespace rao_time_domain_test
}  // namespace ffrf
