#pragma once
// A navigation update for the net layer's tests: the robot at `robot`, one ball at (3, 4), a
// route from the robot over the ball.

#include "ballsight/service/navigation_hub.hpp"

namespace ballsight::test {

inline NavigationUpdate sample_update(const Pose2D& robot, std::int64_t capture_ns = utc_now_ns()) {
  NavigationUpdate u;
  u.capture_time_ns = capture_ns;
  RobotPoseEstimate estimate;
  estimate.pose = robot;
  u.world.robot = estimate;
  u.world.balls.push_back({Vec2(3, 4), Eigen::Matrix2d::Zero(), {0}});
  u.route.planner = "ballsight";
  u.route.order = {0};
  u.route.visits_m = {Vec2(3, 4)};
  u.route.waypoints_m = {robot.position, Vec2(3, 4)};
  return u;
}

}  // namespace ballsight::test
