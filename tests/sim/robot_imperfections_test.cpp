// A real collector's latency and wheel slip in the simulated court (sim/court_world.hpp): a
// command acts only after the latency, slip makes the robot's path differ from its wheels', and
// a perfect robot is the default.
#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/core/error.hpp"
#include "ballsight/sim/court_world.hpp"

namespace ballsight::sim {
namespace {

CourtWorld world_at(const Pose2D& start, const RobotImperfections& imperfections = {}) {
  CourtScene scene;
  scene.robot.pose = start;
  return CourtWorld(scene, TennisCourtSpec{}, DriveLimits{}, RobotFootprint{}, imperfections);
}

TEST(RobotImperfections, ACommandActsAfterTheLatency) {
  RobotImperfections late;
  late.command_latency_s = 0.1;
  CourtWorld world = world_at({Vec2(-10, 0), 0.0}, late);
  world.advance({1.0, 0.0}, 0.1);  // the wheels still carry out the command before it: none
  EXPECT_NEAR(world.motion().pose.position.x(), -10.0, 1e-12);
  world.advance({0.0, 0.0}, 0.1);  // now the first command acts, the stop waits its turn
  EXPECT_GT(world.motion().speed_mps, 0.09);
  world.advance({0.0, 0.0}, 0.2);
  EXPECT_NEAR(world.motion().speed_mps, 0.0, 1e-12);

  CourtWorld at_once = world_at({Vec2(-10, 0), 0.0});
  at_once.advance({1.0, 0.0}, 0.1);
  EXPECT_GT(at_once.motion().pose.position.x(), -10.0 + 0.004);
}

TEST(RobotImperfections, SlipMakesThePathDifferFromTheWheels) {
  const auto drive = [](const RobotImperfections& imperfections) {
    CourtWorld world = world_at({Vec2(-10, 0), 0.0}, imperfections);
    for (int k = 0; k < 50; ++k) world.advance({1.0, 0.2}, 0.1);  // 5 s on an arc
    return world.motion().pose;
  };
  const Pose2D perfect = drive({});
  RobotImperfections slipping;
  slipping.odometry_drift = 0.05;
  const Pose2D slipped = drive(slipping);
  const double apart = (slipped.position - perfect.position).norm();
  EXPECT_GT(apart, 0.01);  // 5 % slip over about 4.5 m: centimetres to decimetres
  EXPECT_LT(apart, 1.0);
  EXPECT_EQ(drive(slipping).position, slipped.position);  // the same seed, the same slip
  slipping.seed = 2;
  EXPECT_NE(drive(slipping).position, slipped.position);
  RobotImperfections none;
  none.seed = 7;  // no slip: no draw, the perfect robot's path exactly
  EXPECT_EQ(drive(none).position, perfect.position);
}

TEST(RobotImperfections, OdometryCountsTheWheelsNotTheSlip) {
  RobotImperfections slipping;
  slipping.odometry_drift = 0.05;
  CourtWorld world = world_at({Vec2(-10, 0), 0.3}, slipping);
  for (int k = 0; k < 50; ++k) world.advance({1.0, 0.2}, 0.1);
  // The wheels' odometry is the perfect robot's motion from its start, in the start's frame.
  CourtWorld perfect = world_at({Vec2(-10, 0), 0.3});
  for (int k = 0; k < 50; ++k) perfect.advance({1.0, 0.2}, 0.1);
  const Rigid2 moved = Pose2D{Vec2(-10, 0), 0.3}.field_from_robot().inverse() *
                       perfect.motion().pose.field_from_robot();
  EXPECT_LT((world.odometry().position - moved.translation).norm(), 0.01);
  EXPECT_NEAR(world.odometry().heading_rad, moved.theta_rad, 1e-3);
  EXPECT_EQ(world.history().back().odometry.position, world.odometry().position);
  // ... and differs from where the slipping robot really went.
  const Rigid2 really = Pose2D{Vec2(-10, 0), 0.3}.field_from_robot().inverse() *
                        world.motion().pose.field_from_robot();
  EXPECT_GT((world.odometry().position - really.translation).norm(), 0.01);
}

TEST(RobotImperfections, RefusesValuesOutOfRange) {
  RobotImperfections bad;
  bad.command_latency_s = -0.1;
  EXPECT_THROW(bad.validate(), InputError);
  bad = {};
  bad.odometry_drift = std::nan("");
  EXPECT_THROW(bad.validate(), InputError);
  bad = {};
  bad.slip_time_s = 0.0;
  EXPECT_THROW(world_at({}, bad), InputError);
}

}  // namespace
}  // namespace ballsight::sim
