#include "ballsight/viz/court_map.hpp"

#include <gtest/gtest.h>

namespace ballsight {
namespace {

cv::Vec3b at(const cv::Mat& image, const cv::Point2d& p) {
  return image.at<cv::Vec3b>(static_cast<int>(p.y), static_cast<int>(p.x));
}

cv::Vec3b bytes(const cv::Scalar& s) {
  return {static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2])};
}

// A 20 x 10 m run-off round a 12 x 6 m court with one line across its middle.
CourtFloor small_floor() {
  CourtFloor floor;
  floor.surround = {Vec2(-10, -5), Vec2(10, 5)};
  floor.court = {Vec2(-6, -3), Vec2(6, 3)};
  floor.lines = {{Vec2(-6, -0.1), Vec2(6, 0.1)}};
  floor.surround_bgr = {10, 20, 30};
  floor.court_bgr = {40, 50, 60};
  floor.line_bgr = {250, 250, 250};
  floor.net_posts_y_m = 4.0;
  floor.net_bgr = {0, 0, 200};
  return floor;
}

TEST(CourtMap, TheViewPutsFieldYUpAndItsTopLeftAtTheOffset) {
  const MapView px{Vec2(-10, 5), 20.0, {3.0, 7.0}};
  EXPECT_EQ(px(Vec2(-10, 5)), cv::Point2d(3.0, 7.0));
  EXPECT_EQ(px(Vec2(-9, 5)), cv::Point2d(23.0, 7.0));   // x to the right
  EXPECT_EQ(px(Vec2(-10, 4)), cv::Point2d(3.0, 27.0));  // y up: down the picture
}

TEST(CourtMap, TheFloorIsPaintedRunOffCourtLinesAndNet) {
  const CourtFloor floor = small_floor();
  const MapView px{Vec2(-10, 5), 20.0, {0.0, 0.0}};
  cv::Mat image(200, 400, CV_8UC3, cv::Scalar::all(0));
  draw_court_floor(image, px, floor);
  EXPECT_EQ(at(image, px(Vec2(-8, -4))), bytes(floor.surround_bgr));
  EXPECT_EQ(at(image, px(Vec2(-3, 1.5))), bytes(floor.court_bgr));
  EXPECT_EQ(at(image, px(Vec2(-3, 0))), bytes(floor.line_bgr));
  EXPECT_EQ(at(image, px(Vec2(0, 3.5))), bytes(floor.net_bgr));  // between the court and a post

  CourtFloor no_net = floor;
  no_net.net_posts_y_m.reset();
  image.setTo(cv::Scalar::all(0));
  draw_court_floor(image, px, no_net);
  EXPECT_EQ(at(image, px(Vec2(0, 3.5))), bytes(floor.surround_bgr));
}

}  // namespace
}  // namespace ballsight
