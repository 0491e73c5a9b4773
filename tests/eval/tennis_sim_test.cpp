// The camera-free ball detectors on the court simulator's frames, labelled from its truth.
#include "ballsight/eval/tennis_sim.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TennisSimOptions two_scenes() {
  TennisSimOptions options;
  options.scenes = 2;
  options.seed = 4;
  return options;
}

// The level reached (docs/RESULTS.md, "The same detectors on the court simulator's frames").
TEST(TennisSim, BallsightFindsMoreBallsThanTheReportAndFewWrong) {
  const TennisSimResult result = run_tennis_sim(two_scenes());
  ASSERT_EQ(result.methods.size(), 2u);
  const BoxMatch& ballsight = result.methods[0].total;
  const BoxMatch& report = result.methods[1].total;
  EXPECT_GT(ballsight.labelled, 20);
  EXPECT_EQ(report.labelled, ballsight.labelled);
  EXPECT_GE(recall(ballsight), 0.7);
  EXPECT_GE(precision(ballsight), 0.95);
  EXPECT_GT(recall(ballsight), recall(report));
  BoxMatch sum;
  for (const auto& [condition, match] : result.methods[0].conditions) add_match(sum, match);
  EXPECT_EQ(sum.labelled, ballsight.labelled);
  EXPECT_EQ(sum.matched, ballsight.matched);
}

// Balls too small to be labelled are not counted against a detector: with no ball labelled, a
// court without distractors leaves no detection to judge (on the same scenes, labelled, the test
// above finds most balls).
TEST(TennisSim, ADetectionOnAnUnlabelledSphereIsNeitherRightNorWrong) {
  TennisSimOptions options = two_scenes();
  options.min_radius_px = 1000.0;
  const TennisSimResult result = run_tennis_sim(options);
  for (const TennisSimMethod& method : result.methods) {
    EXPECT_EQ(method.total.labelled, 0) << method.method;
    EXPECT_EQ(method.total.detected, 0) << method.method;
  }
}

TEST(TennisSim, RefusesBadOptions) {
  TennisSimOptions options = two_scenes();
  options.scenes = 0;
  EXPECT_THROW(run_tennis_sim(options), InputError);
  options = two_scenes();
  options.min_radius_px = 0.5;
  EXPECT_THROW(run_tennis_sim(options), InputError);
}

}  // namespace
}  // namespace ballsight
