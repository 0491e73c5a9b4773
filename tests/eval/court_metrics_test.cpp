#include "ballsight/eval/court_metrics.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/angle.hpp"

namespace ballsight {
namespace {

// The definitions of docs/court-eval.md on a hand-made scene.
TEST(CourtMetrics, HitsDuplicatesFalsePositivesAndUnseenBalls) {
  const std::vector<TruthBall> truth{
      {{0, 0}, true}, {{1, 0}, true}, {{2, 0}, true}, {{5, 5}, false}};
  const std::vector<Vec2> estimates{{0.01, 0},    // hit
                                    {0.05, 0},    // second estimate of ball 0: duplicate
                                    {1.0, 0.03},  // hit
                                    {5.02, 5},    // a ball no camera sees: correct extra
                                    {8, 8}};      // false positive
  const Pose2D robot{Vec2(3, 3), rad_from_deg(10)};
  const SceneScore s =
      score_scene(truth, estimates, robot, Pose2D{Vec2(3.01, 3), rad_from_deg(9)}, 0.10);
  EXPECT_EQ(s.counted, 3);
  EXPECT_EQ(s.unseen, 1);
  EXPECT_EQ(s.true_positives, 2);
  EXPECT_EQ(s.correct_extras, 1);
  EXPECT_EQ(s.duplicates, 1);
  EXPECT_EQ(s.false_positives, 1);
  ASSERT_EQ(s.errors_m.size(), 2u);
  EXPECT_NEAR(s.errors_m[0], 0.01, 1e-12);
  EXPECT_NEAR(s.errors_m[1], 0.03, 1e-12);
  EXPECT_NEAR(s.robot_position_error_m, 0.01, 1e-12);
  EXPECT_NEAR(deg_from_rad(s.robot_heading_error_rad), 1.0, 1e-9);

  // Each mistake with its place: the missed ball's true position, the wrong estimates' own.
  ASSERT_EQ(s.mistakes.size(), 3u);
  EXPECT_EQ(s.mistakes[0].kind, BallMistake::Kind::duplicate);
  EXPECT_EQ(s.mistakes[0].position_m, Vec2(0.05, 0));
  EXPECT_EQ(s.mistakes[1].kind, BallMistake::Kind::false_positive);
  EXPECT_EQ(s.mistakes[1].position_m, Vec2(8, 8));
  EXPECT_EQ(s.mistakes[2].kind, BallMistake::Kind::missed);
  EXPECT_EQ(s.mistakes[2].position_m, Vec2(2, 0));
  EXPECT_EQ(mistake_kind_name(s.mistakes[1].kind), "false_positive");

  CourtScores scores;
  scores.add(s);
  scores.add(s);
  ASSERT_EQ(scores.mistakes.size(), 6u);
  EXPECT_EQ(scores.mistakes[2].scene, 0);
  EXPECT_EQ(scores.mistakes[3].scene, 1);
  EXPECT_NEAR(scores.recall(), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(scores.precision(), 3.0 / 5.0, 1e-12);
  EXPECT_NEAR(scores.ball_error_mean_m(), 0.02, 1e-12);
  EXPECT_NEAR(scores.ball_error_p95_m(), 0.03, 1e-12);
}

// Nearest pairs are matched first: an estimate between two balls takes the nearer one.
TEST(CourtMetrics, MatchingIsOneToOneNearestFirst) {
  const std::vector<TruthBall> truth{{{0, 0}, true}, {{0.07, 0}, true}};
  const SceneScore s = score_scene(truth, {{0.04, 0}, {0.0, 0.01}}, {}, std::nullopt, 0.10);
  EXPECT_EQ(s.true_positives, 2);
  EXPECT_EQ(s.duplicates, 0);
  EXPECT_FALSE(s.robot_found);
}

TEST(CourtMetrics, QuantileIsNearestRank) {
  EXPECT_EQ(quantile({3, 1, 2, 4}, 0.5), 2);
  EXPECT_EQ(quantile({3, 1, 2, 4}, 0.95), 4);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

}  // namespace
}  // namespace ballsight
