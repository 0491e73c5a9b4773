// Scoring ball detectors on labelled photos, and ballsight's detector on the real photos of other
// people (skips when ../shared/data is absent).
#include "ballsight/eval/tennis_real.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "ballsight/core/error.hpp"
#include "shared_data.hpp"
#include "skip.hpp"

namespace ballsight {
namespace {

TEST(TennisReal, EachBoxMatchesOnceAndTheBestDetectionFirst) {
  const std::vector<cv::Rect> boxes{{10, 10, 20, 20}, {100, 100, 10, 10}};
  const std::vector<PhotoBall> balls{
      {Vec2(19.5, 19.5), 10.0, 0.9}, {Vec2(22.0, 22.0), 9.0, 0.8}, {Vec2(300, 300), 5.0, 0.7}};
  const BoxMatch match = match_balls_to_boxes(boxes, balls, {400, 400});
  EXPECT_EQ(match.labelled, 2);
  EXPECT_EQ(match.detected, 3);
  EXPECT_EQ(match.matched, 1);
  ASSERT_EQ(match.center_error_ratio.size(), 1u);
  EXPECT_NEAR(match.center_error_ratio[0], 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(recall(match), 0.5);
  EXPECT_DOUBLE_EQ(precision(match), 1.0 / 3.0);
}

TEST(TennisReal, RecallByRadiusCountsEachBoxInItsRange) {
  // Two photos: boxes of radius 2.5, 10 and 10 px (the second found), and one of 40 px (found).
  BoxMatch total;
  add_match(total, match_balls_to_boxes({{0, 0, 5, 4}, {50, 0, 20, 20}, {100, 0, 20, 18}},
                                        {{Vec2(59.5, 9.5), 10.0, 0.9}}, {400, 400}));
  add_match(total,
            match_balls_to_boxes({{0, 50, 80, 60}}, {{Vec2(39.5, 79.5), 40.0, 0.9}}, {400, 400}));
  const std::array<double, 3> edges{2.0, 5.0, 20.0};
  const std::vector<RadiusRecall> ranges = recall_by_radius(total, edges);
  ASSERT_EQ(ranges.size(), 3u);
  EXPECT_EQ(ranges[0].labelled, 1);  // [2, 5)
  EXPECT_EQ(ranges[0].matched, 0);
  EXPECT_EQ(ranges[1].labelled, 2);  // [5, 20)
  EXPECT_EQ(ranges[1].matched, 1);
  EXPECT_DOUBLE_EQ(recall(ranges[1]), 0.5);
  EXPECT_EQ(ranges[2].labelled, 1);  // [20, infinity)
  EXPECT_EQ(ranges[2].matched, 1);
  EXPECT_TRUE(std::isinf(ranges[2].max_radius_px));
  EXPECT_EQ(recall_by_radius_json(ranges)[2]["radius_px"][1], nullptr);
  const std::array<double, 3> unordered{2.0, 20.0, 5.0};
  EXPECT_THROW(recall_by_radius(total, unordered), InputError);
}

TEST(TennisReal, ABallCutByTheBorderIsComparedByItsVisiblePart) {
  // The label holds the visible part only (rows 60-99 of a 100-row image); the ball's centre,
  // at row 99.5, lies outside its label.
  const std::vector<cv::Rect> boxes{{30, 60, 80, 40}};
  const BoxMatch match = match_balls_to_boxes(boxes, {{Vec2(69.5, 99.5), 40.0, 1.0}}, {200, 100});
  EXPECT_EQ(match.matched, 1);
  ASSERT_EQ(match.center_error_ratio.size(), 1u);
  EXPECT_NEAR(match.center_error_ratio[0], 0.0, 1e-9);
}

// The level reached on the real photos (docs/RESULTS.md, "Tennis balls in real photos"); the
// issue's targets (95 % recall and precision) are not reached yet, so this guards what is.
TEST(TennisReal, BallsightBeatsTheReportOnRealPhotos) {
  TennisRealOptions options;
  options.data_dir = test::shared_data_dir();
  options.timing_runs = 1;
  if (load_labelled_photo_sets(options.data_dir).empty())
    BALLSIGHT_SKIP() << "no labelled photos under " << options.data_dir / "real" / "tennis";
  const TennisRealResult result = run_tennis_real(options);
  ASSERT_EQ(result.methods.size(), 2u);
  const BoxMatch& ballsight = result.methods[0].total;
  const BoxMatch& report = result.methods[1].total;
  EXPECT_GE(recall(ballsight), 0.85);
  EXPECT_GE(precision(ballsight), 0.90);
  EXPECT_GT(recall(ballsight), recall(report));
  EXPECT_GT(precision(ballsight), 5.0 * precision(report));
  ASSERT_FALSE(ballsight.center_error_ratio.empty());
  std::vector<double> errors = ballsight.center_error_ratio;
  std::nth_element(errors.begin(), errors.begin() + static_cast<long>(errors.size() / 2),
                   errors.end());
  EXPECT_LE(errors[errors.size() / 2], 0.15);
}

}  // namespace
}  // namespace ballsight
