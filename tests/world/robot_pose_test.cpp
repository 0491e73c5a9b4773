#include "ballsight/world/robot_pose.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

FieldObservation marker(const Vec2& p, int camera, double sigma_m = 0.005) {
  FieldObservation o;
  o.position_m = p;
  o.covariance_m2 = sigma_m * sigma_m * Eigen::Matrix2d::Identity();
  o.camera = camera;
  return o;
}

// Markers placed from a pose give back that pose (any heading, any layout offset).
TEST(RobotPose, MarkersToPoseRoundTrip) {
  const std::uint64_t seed = 9;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RobotModel robot;
  robot.front_marker_x_m = 0.25;
  robot.back_marker_x_m = -0.10;
  for (int i = 0; i < 100; ++i) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " sample " + std::to_string(i));
    const Pose2D pose{Vec2(10 * u(rng), 5 * u(rng)), kPi * u(rng)};
    const Rigid2 field_from_robot = pose.field_from_robot();
    const Pose2D back = pose_from_markers(field_from_robot * Vec2(robot.front_marker_x_m, 0),
                                          field_from_robot * Vec2(robot.back_marker_x_m, 0), robot);
    EXPECT_LT((back.position - pose.position).norm(), 1e-12);
    EXPECT_LT(std::abs(wrap_rad_pi(back.heading_rad - pose.heading_rad)), 1e-12);
  }
}

// Each marker fused over the cameras that see it; a blob of the marker colour elsewhere (wrong
// spacing) is not taken for the robot.
TEST(RobotPose, FusesEachMarkerOverItsCameras) {
  const RobotModel robot;
  const Pose2D truth{Vec2(3.0, -1.0), rad_from_deg(30.0)};
  const Vec2 front = truth.field_from_robot() * Vec2(0.2, 0.0);
  const Vec2 back = truth.field_from_robot() * Vec2(-0.2, 0.0);
  const std::vector<FieldObservation> fronts{marker(front + Vec2(0.004, 0), 0),
                                             marker(front - Vec2(0.004, 0), 1),
                                             marker(Vec2(-8.0, 2.0), 2)};
  const std::vector<FieldObservation> backs{marker(back + Vec2(0, 0.003), 0),
                                            marker(back - Vec2(0, 0.003), 1)};
  const auto estimate = estimate_robot_pose(fronts, backs, robot, {});
  ASSERT_TRUE(estimate.has_value());
  EXPECT_LT((estimate->pose.position - truth.position).norm(), 1e-9);
  EXPECT_NEAR(estimate->pose.heading_rad, truth.heading_rad, 1e-9);
  EXPECT_EQ(estimate->front_cameras, (std::vector<int>{0, 1}));
  EXPECT_EQ(estimate->back_cameras, (std::vector<int>{0, 1}));
  EXPECT_GT(estimate->heading_sigma_rad, 0.0);
  // Markers too far apart for the layout: no robot.
  EXPECT_FALSE(estimate_robot_pose({marker(front, 0)}, {marker(back - Vec2(1, 0), 0)}, robot, {}));
}

TEST(RobotPose, BadLayoutIsAnError) {
  RobotModel robot;
  robot.front_marker_x_m = -0.3;
  EXPECT_THROW(robot.validate(), InputError);
}

}  // namespace
}  // namespace ballsight
