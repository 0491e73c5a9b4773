#include "ballsight/core/conventions.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/angle.hpp"

namespace ballsight {
namespace {

constexpr unsigned kSeed = 7;
const Vec2 kCenter(320.0, 240.0);

TEST(ImagePolar, FollowsAlgorithm2) {
  // Right of the centre is 0 deg, *up* in the image (smaller y) is 90 deg.
  EXPECT_NEAR(image_polar_from_pixel({330.0, 240.0}, kCenter).theta_deg, 0.0, 1e-12);
  EXPECT_NEAR(image_polar_from_pixel({320.0, 200.0}, kCenter).theta_deg, 90.0, 1e-12);
  EXPECT_NEAR(image_polar_from_pixel({300.0, 240.0}, kCenter).theta_deg, 180.0, 1e-12);
  EXPECT_NEAR(image_polar_from_pixel({320.0, 250.0}, kCenter).theta_deg, 270.0, 1e-12);
  EXPECT_NEAR(image_polar_from_pixel({323.0, 236.0}, kCenter).radius, 5.0, 1e-12);
  // atan2, not atan(dy/dx): the third quadrant stays in the third quadrant.
  EXPECT_NEAR(image_polar_from_pixel({310.0, 250.0}, kCenter).theta_deg, 225.0, 1e-12);
}

TEST(ImagePolar, RoundTripsOverAPixelGrid) {
  for (int y = 0; y < 480; y += 7) {
    for (int x = 0; x < 640; x += 7) {
      const Vec2 pixel(x + 0.25, y + 0.75);
      const Polar p = image_polar_from_pixel(pixel, kCenter);
      EXPECT_NEAR((pixel_from_image_polar(p, kCenter) - pixel).norm(), 0.0, 1e-9);
    }
  }
}

TEST(RobotAndField, Algorithm6MatchesTheRigidTransform) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> pos(-10.0, 10.0), ang(0.0, 360.0), dist(0.0, 8.0);
  for (int i = 0; i < 500; ++i) {
    const Pose2D robot{{pos(rng), pos(rng)}, rad_from_deg(ang(rng))};
    const double image_theta = ang(rng), d = dist(rng);
    const Vec2 by_paper = field_point_from_image_direction(robot, image_theta, d);
    const Vec2 p_in_robot =
        robot_point_from_bearing(robot_bearing_deg_from_image_theta_deg(image_theta), d);
    EXPECT_NEAR((field_from_robot_point(robot, p_in_robot) - by_paper).norm(), 0.0, 1e-9);
    EXPECT_NEAR((robot_from_field_point(robot, by_paper) - p_in_robot).norm(), 0.0, 1e-9);
  }
}

TEST(RobotAndField, ForwardIsImageUp) {
  // A robot at (1, 2) facing +y sees a point straight ahead (image angle 90) at (1, 2 + d).
  const Pose2D robot{{1.0, 2.0}, kPi / 2};
  EXPECT_NEAR((field_point_from_image_direction(robot, 90.0, 3.0) - Vec2(1.0, 5.0)).norm(), 0.0,
              1e-12);
  // Image angle 180 (left in the image) is the robot's left.
  EXPECT_NEAR((robot_point_from_bearing(robot_bearing_deg_from_image_theta_deg(180.0), 1.0) -
               Vec2(0.0, 1.0))
                  .norm(),
              0.0, 1e-12);
}

}  // namespace
}  // namespace ballsight
