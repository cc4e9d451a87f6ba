#pragma once
// Checks of a hand description's grasping semantics, shared by the shipped-hand and the
// dataset-hand tests: check_hand_conventions (the library's checks, also run by `hand init`).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cordgrasp/core/hand_conventions.h"
#include "cordgrasp/core/hand_model.h"

namespace cordgrasp::test {

/// Every convention of check_hand_conventions holds (each broken one is a failure).
inline void expect_hand_conventions(const HandModel& hand, double step, double min_gain_m) {
  HandConventionParams params;
  params.closing_step = step;
  params.min_closing_m = min_gain_m;
  for (const std::string& problem : check_hand_conventions(hand, params)) ADD_FAILURE() << problem;
}

}  // namespace cordgrasp::test
