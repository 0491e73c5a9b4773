#include "ballsight/detect/omni_blobs.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "ballsight/core/conventions.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/detect/radial_scan.hpp"

namespace ballsight {
namespace {

const cv::Vec3b kGreen(40, 140, 40), kOrange(0, 120, 255);
const Vec2 kCenter(319.5, 239.5);

ColorClassTable orange_table() {
  return ColorClassTable({{1, {{40, 30, 150}, {230, 125, 240}}}});
}

cv::Mat scene_with_discs(const std::vector<std::pair<Vec2, double>>& discs) {
  cv::Mat bgr(480, 640, CV_8UC3, cv::Scalar(kGreen));
  constexpr int kShift = 4;  // sub-pixel centres
  for (const auto& [c, r] : discs) {
    cv::circle(bgr, cv::Point(cvRound(c.x() * 16), cvRound(c.y() * 16)), cvRound(r * 16),
               cv::Scalar(kOrange), cv::FILLED, cv::LINE_8, kShift);
  }
  return bgr;
}

TEST(OmniBlobFinder, FindsDiscsWithSubPixelCentroids) {
  const std::vector<std::pair<Vec2, double>> discs = {{{420.3, 200.7}, 9.0}, {{250.6, 330.2}, 4.0}};
  const cv::Mat bgr = scene_with_discs(discs);
  const OmniBlobFinder finder(bgr.size(), OmniBlobOptions{});
  const std::vector<OmniBlob> blobs = finder.find(bgr, orange_table(), 1);
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_GT(blobs[0].area_px, blobs[1].area_px);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR((blobs[i].centroid_px - discs[i].first).norm(), 0.0, 0.15) << i;
    const double r = (discs[i].first - kCenter).norm();
    EXPECT_NEAR(blobs[i].inner_radius_px, r - discs[i].second, 1.0) << i;
    EXPECT_NEAR(blobs[i].outer_radius_px, r + discs[i].second, 1.0) << i;
    EXPECT_NEAR(blobs[i].centroid_polar.theta_deg,
                image_polar_from_pixel(discs[i].first, kCenter).theta_deg, 0.2);
  }
}

TEST(OmniBlobFinder, IgnoresTheRobotBodyAndBeyondTheMirror) {
  const cv::Mat bgr = scene_with_discs({{kCenter, 10.0}, {{630.0, 20.0}, 6.0}});
  const OmniBlobFinder finder(bgr.size(), OmniBlobOptions{});
  EXPECT_TRUE(finder.find(bgr, orange_table(), 1).empty());
}

TEST(OmniBlobFinder, RejectsWrongImages) {
  const OmniBlobFinder finder({640, 480}, OmniBlobOptions{});
  EXPECT_THROW(finder.find(cv::Mat(240, 320, CV_8UC3), orange_table(), 1), InputError);
  OmniBlobOptions bad;
  bad.seed_step_px = 0;
  EXPECT_THROW(OmniBlobFinder({640, 480}, bad), InputError);
}

TEST(RadialScan, ReturnsTheFirstBallPixelOfTheLastRayThatMeetsTheBall) {
  // A disc straight above the centre: the last ray meeting it is the one with the largest angle
  // below 360 that crosses it; its first pixel is on the disc's near side.
  const Vec2 ball(320.0, 120.0);
  const cv::Mat bgr = scene_with_discs({{ball, 8.0}});
  const cv::Mat1b mask = segment(bgr, orange_table(), 1);
  const auto hit = radial_scan_ball(mask, {320.0, 240.0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(mask(static_cast<int>(hit->y()), static_cast<int>(hit->x())), 255);
  const Polar p = image_polar_from_pixel(*hit, {320.0, 240.0});
  EXPECT_GT(p.theta_deg, 90.0);    // left half of the disc: the larger angles come last
  EXPECT_LT(p.radius, 120.0 - 2);  // near side of the disc
  EXPECT_FALSE(radial_scan_ball(cv::Mat1b(480, 640, uchar{0}), {320.0, 240.0}));
}

}  // namespace
}  // namespace ballsight
