// Two sweep rows equal bit for bit (==, no tolerance) in everything but the wall time: status,
// reason, steps taken, solver statistics, errors per channel. For the tests that compare a shared
// path against the path it replaced.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "study/sweep.hpp"

namespace ffrf::test {

inline void expect_same_result(const study::SweepResult& a, const study::SweepResult& b) {
  SCOPED_TRACE("configuration " + std::to_string(a.config.id) + " " + a.config.choice.label() + ", " +
               study::integrator_label(a.config) + (a.config.radiation ? ", radiation " + study::radiation_name(a.config) : ""));
  ASSERT_EQ(a.config.id, b.config.id);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.reason, b.reason);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.stable_step, b.stable_step);
  EXPECT_EQ(a.state_size, b.state_size);
  EXPECT_EQ(a.stats.steps, b.stats.steps);
  EXPECT_EQ(a.stats.function_evaluations, b.stats.function_evaluations);
  EXPECT_EQ(a.stats.jacobian_evaluations, b.stats.jacobian_evaluations);
  EXPECT_EQ(a.stats.newton_iterations, b.stats.newton_iterations);
  EXPECT_EQ(a.stats.error_test_failures, b.stats.error_test_failures);
  EXPECT_EQ(a.worst.error, b.worst.error);
  for (std::size_t c = 0; c < a.errors.channels.size(); ++c) {
    EXPECT_EQ(a.errors.channels[c].normalized_rms, b.errors.channels[c].normalized_rms) << "channel " << c;
    EXPECT_EQ(a.errors.channels[c].max_abs, b.errors.channels[c].max_abs) << "channel " << c;
  }
  EXPECT_EQ(a.errors.daf_error, b.errors.daf_error);
}

}  // namespace ffrf::test
