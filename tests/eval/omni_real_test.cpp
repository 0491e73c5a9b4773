#include "ballsight/eval/omni_real.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

// A set's result with the given medians on the direction split (floor last).
RealOmniSetResult medians(double poly, double mlp, double ours, double floor) {
  RealOmniSetResult set;
  const auto score = [](const char* method, double median) {
    HeldOutScore s{method, HeldOutSplit::kDirections, {}, 0, 0.0};
    s.distance_cm.median = median;
    return s;
  };
  set.scores = {score("poly", poly), score("paper-mlp", mlp), score("ballsight", ours)};
  set.floors = {score("floor", floor)};
  return set;
}

// The target of those medians: its rule, its limit and whether it is met.
void expect_target(const RealOmniSetResult& set, OmniRealRule rule, double limit_cm, bool met) {
  const std::optional<OmniRealTarget> target = omni_real_target(set, HeldOutSplit::kDirections);
  ASSERT_TRUE(target.has_value());
  EXPECT_EQ(target->rule, rule) << omni_real_rule_name(target->rule);
  EXPECT_DOUBLE_EQ(target->limit_cm, limit_cm);
  EXPECT_EQ(target->met(), met);
}

TEST(OmniRealTarget, SevenTenthsOfTheBetterBaselineOnlyWhereTheFloorAllowsIt) {
  // The floor below 0.7x the better baseline (3 cm): the limit is 2.1 cm.
  expect_target(medians(5.0, 3.0, 2.0, 1.0), OmniRealRule::seven_tenths, 0.7 * 3.0, true);
  expect_target(medians(5.0, 3.0, 2.2, 1.0), OmniRealRule::seven_tenths, 0.7 * 3.0, false);
  // The floor above it: within 1.1x the floor, and never above the better baseline.
  expect_target(medians(5.0, 3.0, 2.4, 2.5), OmniRealRule::floor, 1.1 * 2.5, true);
  expect_target(medians(5.0, 3.0, 2.9, 2.5), OmniRealRule::floor, 1.1 * 2.5, false);
  expect_target(medians(5.0, 3.0, 2.4, 2.9), OmniRealRule::better_baseline, 3.0, true);
  EXPECT_EQ(omni_real_rule_name(OmniRealRule::better_baseline), "the better baseline");
  // Without a baseline, or on a split with no score, there is no target.
  RealOmniSetResult no_mlp = medians(5.0, 3.0, 2.0, 1.0);
  no_mlp.scores.erase(no_mlp.scores.begin() + 1);
  EXPECT_FALSE(omni_real_target(no_mlp, HeldOutSplit::kDirections).has_value());
  EXPECT_FALSE(omni_real_target(medians(5.0, 3.0, 2.0, 1.0), HeldOutSplit::kDistance).has_value());
}

}  // namespace
}  // namespace ballsight
