// Test helper: the run's detections of one kind (a slack luffing wire, a slack backstay), each of
// whose causes must name every word given (the wire, what it held); returns how many there are.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "multibody/crane_run.hpp"

namespace ffrf::test {

inline int named_detections(const multibody::RunResult& run, solve::FailureKind kind, std::initializer_list<const char*> words) {
  int named = 0;
  for (const solve::Detection& detection : run.detections) {
    if (detection.kind != kind) continue;
    ++named;
    for (const char* word : words) EXPECT_NE(detection.cause.find(word), std::string::npos) << detection.cause;
  }
  return named;
}

}  // namespace ffrf::test
