#include "ballsight/pipeline/omni_calibration.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/conventions.hpp"

namespace ballsight {
namespace {

TEST(OmniCalibrationSteps, PointsAndSamplesRoundTrip) {
  const Vec2 center(321.25, 236.5);
  const std::vector<MarkerPoint> points{{Vec2(400.0, 100.0), 250.0, 10.0},
                                        {Vec2(100.5, 300.25), 60.0, std::nullopt},
                                        {Vec2(321.25, 400.0), 460.0, 180.0}};
  const std::vector<PolarSample> samples = polar_samples_of(points, center);
  ASSERT_EQ(samples.size(), 3u);
  // Straight down in the image is image angle 270, behind the robot: bearing 180.
  EXPECT_NEAR(samples[2].theta_deg, 270.0, 1e-9);
  EXPECT_NEAR(*samples[2].bearing_deg, 270.0, 1e-9);
  EXPECT_FALSE(samples[1].bearing_deg.has_value());
  const std::vector<MarkerPoint> back = marker_points_of(samples, center);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR((back[i].pixel - points[i].pixel).norm(), 0.0, 1e-9) << i;
    EXPECT_EQ(back[i].distance_cm, points[i].distance_cm);
    EXPECT_EQ(back[i].bearing_deg.has_value(), points[i].bearing_deg.has_value());
    if (points[i].bearing_deg) {
      EXPECT_NEAR(*back[i].bearing_deg, *points[i].bearing_deg, 1e-9);
    }
  }
}

TEST(OmniCalibrationSteps, PlacesByRayAndRankWithoutAFit) {
  const Vec2 center(320.0, 240.0);
  MarkerLayout layout;  // rays every 10 deg, rings 60..460 cm every 50 cm
  // Straight up in the image is the robot's forward (bearing 0); up-left is bearing 30 (ccw).
  const auto at = [&](double bearing_deg, double radius) {
    return pixel_from_image_polar({image_theta_deg_from_robot_bearing_deg(bearing_deg), radius},
                                  center);
  };
  const std::vector<Vec2> pixels{at(0.0, 120.0), at(1.0, 60.0), at(31.0, 90.0), at(-2.0, 150.0)};
  const std::vector<MarkerPoint> places = suggest_layout_places(pixels, center, layout);
  ASSERT_EQ(places.size(), 4u);
  EXPECT_EQ(*places[0].bearing_deg, 0.0);
  EXPECT_EQ(*places[1].bearing_deg, 0.0);
  EXPECT_EQ(*places[2].bearing_deg, 30.0);
  EXPECT_EQ(*places[3].bearing_deg, 0.0);
  // On ray 0 by radius: 60 px is the nearest ring, then 120 px, then 150 px.
  EXPECT_DOUBLE_EQ(places[1].distance_cm, 60.0);
  EXPECT_DOUBLE_EQ(places[0].distance_cm, 110.0);
  EXPECT_DOUBLE_EQ(places[3].distance_cm, 160.0);
  EXPECT_DOUBLE_EQ(places[2].distance_cm, 60.0);
  EXPECT_EQ(places[2].pixel, pixels[2]);
}

}  // namespace
}  // namespace ballsight
