// The camera-free ball detectors on the court simulator's frames, labelled from its truth.
#include "ballsight/eval/tennis_sim.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_scene.hpp"
#include "ballsight/sim/tennis_court.hpp"

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
  const BallMatch& ballsight = result.methods[0].total;
  const BallMatch& report = result.methods[1].total;
  EXPECT_GT(ballsight.labelled, 20);
  EXPECT_EQ(report.labelled, ballsight.labelled);
  EXPECT_GE(recall(ballsight), 0.7);
  EXPECT_GE(precision(ballsight), 0.95);
  EXPECT_GT(recall(ballsight), recall(report));
  BallMatch sum;
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

// A red court is the stage orange's seed colour: the court grew into one blob with every ball
// on it until the floor rule took its colours out (recall 0.15, precision 0.27 without it). A
// hall's warm lamps push the green court's noise into the yellow's growth band, a speckle in
// every small ball's wide ring, until the isolation test counted only growth colours of the
// ball's own hue family (recall 0.20 without it). The figures on these scenes (`eval tennis-sim
// --scenes 3 --surface red`, `--light indoor`): 0.88 and 0.66.
TEST(TennisSim, BallsightFindsBallsOnARedCourtAndUnderWarmLamps) {
  TennisSimOptions red;
  red.scenes = 3;
  sim::set_court_surface(red.court, sim::CourtSurface::red);
  const BallMatch on_red = run_tennis_sim(red).methods[0].total;
  EXPECT_GE(recall(on_red), 0.8);
  EXPECT_GE(precision(on_red), 0.95);
  TennisSimOptions indoor;
  indoor.scenes = 3;
  indoor.scenario.light = sim::LightCondition::indoor;
  const TennisSimResult lamps = run_tennis_sim(indoor);
  EXPECT_EQ(lamps.methods[0].conditions.count("indoor"), 1u);
  EXPECT_GE(recall(lamps.methods[0].total), 0.55);
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
