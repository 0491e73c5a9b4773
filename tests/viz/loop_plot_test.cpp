#include "ballsight/viz/loop_plot.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

TEST(LoopPlot, BallsAreColouredByWhenTheyWereCollectedAndCrossedWhenNever) {
  CourtFloor floor;
  floor.surround = {Vec2(-18, -9), Vec2(18, 9)};
  floor.court = floor.surround;
  floor.court_bgr = floor.surround_bgr = {90, 120, 70};
  LoopMapInput run;
  run.robot_start.position = Vec2(-10, 0);
  run.path_m = {Vec2(-5, 0), Vec2(0, 3)};
  run.routes = {{0.5, {Vec2(-10, 0), Vec2(-5, 0)}}, {4.0, {Vec2(-5, 0), Vec2(0, 3)}}};
  run.balls = {{Vec2(5, -5), 2.0}, {Vec2(10, 5), std::nullopt}};
  run.duration_s = 8.0;
  const cv::Mat image = draw_loop_map(floor, run, "run");
  // The fence and a metre round it at 32 px/m, a 90 px colour bar; the title and a legend of
  // five rows above.
  ASSERT_EQ(image.size(), cv::Size(38 * 32 + 90, 36 + 22 * 5 + 20 * 32));
  const auto at = [&](const Vec2& p) {
    return image.at<cv::Vec3b>(36 + 22 * 5 + static_cast<int>((10 - p.y()) * 32),
                               static_cast<int>((p.x() + 19) * 32));
  };
  EXPECT_EQ(at(Vec2(10, 5)), cv::Vec3b(0, 0, 220));  // never collected: a red cross
  const cv::Vec3b collected = at(Vec2(5, -5));       // a quarter of the run: viridis' blue end
  EXPECT_GT(collected[0], collected[2]);
  EXPECT_NE(collected, cv::Vec3b(90, 120, 70));
}

TEST(LoopPlot, TheLatencyChartHasItsSizeWithOrWithoutUpdates) {
  EXPECT_EQ(draw_latency_chart({}, {}, "none").size(), cv::Size(900, 360));
  EXPECT_EQ(draw_latency_chart({1, 2, 3}, {20.0, 35.0, 12.0}, "three").size(), cv::Size(900, 360));
}

}  // namespace
}  // namespace ballsight
