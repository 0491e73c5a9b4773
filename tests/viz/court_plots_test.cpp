#include "ballsight/viz/court_plots.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

// Pixels of the mistakes' magenta, anti-aliased edges included: red and blue well above green.
int count_magenta(const cv::Mat& image) {
  int n = 0;
  for (auto it = image.begin<cv::Vec3b>(); it != image.end<cv::Vec3b>(); ++it) {
    const cv::Vec3b& p = *it;
    n += p[0] > 120 && p[2] > 120 && p[1] + 60 < p[0] && p[1] + 60 < p[2];
  }
  return n;
}

TEST(CourtPlots, OnlyMistakesAreMarkedInMagenta) {
  CourtFloor floor;
  floor.surround = {Vec2(-18, -9), Vec2(18, 9)};
  floor.court = {Vec2(-12, -5.5), Vec2(12, 5.5)};
  floor.court_bgr = {90, 130, 70};
  floor.surround_bgr = {80, 90, 50};
  WorldModel world;
  world.balls.push_back(FusedBall{});
  world.balls.back().position_m = Vec2(3, 2);
  WorldLayer layer{"method", cv::Scalar(40, 200, 40), world, {}};
  const std::vector<TrueBallMark> truth{{Vec2(3, 2), true}, {Vec2(-4, 1), false}};
  const Pose2D robot{Vec2(-8, -3), 0.5};
  const cv::Mat clean = draw_field_map(floor, {Vec3(-19, -10, 6)}, truth, robot, {layer}, "clean");
  EXPECT_EQ(count_magenta(clean), 0);
  layer.mistakes = {{Vec2(-4, 1), 'M'}, {Vec2(6, -6), 'F'}};
  const cv::Mat marked =
      draw_field_map(floor, {Vec3(-19, -10, 6)}, truth, robot, {layer}, "marked");
  EXPECT_EQ(marked.rows, clean.rows + 22);  // a legend row says what the letters mean
  EXPECT_GT(count_magenta(marked), 100);
}

TEST(CourtPlots, TheOverlayDrawsOnACopyOfTheFrame) {
  const cv::Mat frame(120, 160, CV_8UC3, cv::Scalar(50, 60, 70));
  PixelDetection ball;
  ball.object = ObjectClass::ball;
  ball.center_px = Vec2(80, 60);
  ball.radius_px = 6;
  const cv::Mat overlay =
      draw_detection_overlay(frame, {Vec2(80, 60)}, {{"method", cv::Scalar(0, 255, 0), {ball}}},
                             {Vec2(30, 90)}, "overlay");
  EXPECT_EQ(overlay.size(), frame.size());
  EXPECT_EQ(frame.at<cv::Vec3b>(60, 80 + 8), cv::Vec3b(50, 60, 70));  // the frame untouched
  EXPECT_GT(count_magenta(overlay), 20);                              // the missed ball
}

}  // namespace
}  // namespace ballsight
