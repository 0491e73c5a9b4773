#pragma once
// A navigation update for the robot links' tests (net, dds): the robot at `robot`, one ball at (3,
// 4), a route from the robot over the ball.

#include <chrono>
#include <vector>

#include "ballsight/robot/robot_link.hpp"
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

/// The seqs of `count` updates taken from `link`, waiting up to `wait` for each.
inline std::vector<std::uint64_t> take(RobotLink& link, int count,
                                       std::chrono::milliseconds wait = std::chrono::seconds(5)) {
  std::vector<std::uint64_t> seqs;
  for (int k = 0; k < count; ++k) {
    const std::optional<LinkUpdate> u = link.next(wait);
    if (!u) break;
    seqs.push_back(u->seq);
  }
  return seqs;
}

/// first, first + 1, ..., last.
inline std::vector<std::uint64_t> seq_range(std::uint64_t first, std::uint64_t last) {
  std::vector<std::uint64_t> out;
  for (std::uint64_t s = first; s <= last; ++s) out.push_back(s);
  return out;
}

}  // namespace ballsight::test
