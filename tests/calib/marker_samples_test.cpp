#include "ballsight/calib/marker_samples.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/camera/omni_rig.hpp"
#include "ballsight/core/angle.hpp"
#include "ballsight/core/conventions.hpp"
#include "calib/calib_fixtures.hpp"

namespace ballsight {
namespace {

TEST(MarkerSamples, Algorithm2Conventions) {
  const Vec2 center(320.0, 240.0);
  // 100 px straight up in the image, a marker 2 m ahead of the robot.
  const PolarSample s = sample_from_marker({{320.0, 140.0}, {2.0, 0.0}}, center);
  EXPECT_DOUBLE_EQ(s.theta_deg, 90.0);
  EXPECT_DOUBLE_EQ(s.radius_px, 100.0);
  EXPECT_DOUBLE_EQ(s.distance_cm, 200.0);
  ASSERT_TRUE(s.bearing_deg);
  EXPECT_DOUBLE_EQ(*s.bearing_deg, 90.0);  // forward is image angle 90 (Algorithm 6)
  // A marker to the robot's right is seen at image angle 0.
  EXPECT_NEAR(*sample_from_marker({{400.0, 240.0}, {0.0, -1.0}}, center).bearing_deg, 0.0, 1e-12);
}

// On a perfectly aligned rig the image angle is the true bearing, and the field and robot
// versions agree for any robot pose.
TEST(MarkerSamples, AlignedRigSeesTrueBearingsFromAnyPose) {
  const OmniRig rig;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> bearing(0.0, 360.0), distance(0.6, 4.6), coordinate(-5, 5);
  const Pose2D pose{{coordinate(rng), coordinate(rng)}, 0.7};
  std::vector<MarkerObservation> in_robot;
  std::vector<FieldMarkerObservation> in_field;
  for (int i = 0; i < 100; ++i) {
    const Vec2 p = robot_point_from_bearing(bearing(rng), distance(rng));
    const auto pixel = rig.pixel_from_point({p.x(), p.y(), 0.0});
    ASSERT_TRUE(pixel);
    in_robot.push_back({*pixel, p});
    in_field.push_back({*pixel, field_from_robot_point(pose, p)});
  }
  const auto from_robot = samples_from_markers(in_robot, rig.principal_point());
  const auto from_field = samples_from_field_markers(in_field, pose, rig.principal_point());
  for (std::size_t i = 0; i < from_robot.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(wrap_deg_180(*from_robot[i].bearing_deg - from_robot[i].theta_deg), 0.0, 1e-9);
    EXPECT_NEAR(from_robot[i].distance_cm, 100.0 * in_robot[i].p_in_robot.norm(), 1e-9);
    EXPECT_NEAR(from_field[i].distance_cm, from_robot[i].distance_cm, 1e-9);
    EXPECT_NEAR(wrap_deg_180(*from_field[i].bearing_deg - *from_robot[i].bearing_deg), 0, 1e-9);
  }
}

TEST(MarkerSamples, RejectsDegenerateMarkersByIndex) {
  const Vec2 center(320.0, 240.0);
  const std::vector<MarkerObservation> on_centre = {{{400, 240}, {1, 0}}, {{320, 240}, {1, 0}}};
  EXPECT_NE(test::input_error([&] {
              samples_from_markers(on_centre, center);
            }).find("marker 1: pixel lies on the image centre"),
            std::string::npos);
  const std::vector<MarkerObservation> at_origin = {{{400, 240}, {0, 0}}};
  EXPECT_NE(test::input_error([&] {
              samples_from_markers(at_origin, center);
            }).find("marker 0: marker lies under the robot centre"),
            std::string::npos);
  const std::vector<MarkerObservation> nan = {{{NAN, 240}, {1, 0}}};
  EXPECT_NE(test::input_error([&] { samples_from_markers(nan, center); }).find("finite"),
            std::string::npos);
}

}  // namespace
}  // namespace ballsight
