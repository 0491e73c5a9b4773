// Following a route with the collector's mouth: it passes over every waypoint, within the
// robot's limits, turns to a path behind it on the spot, and stops at the end.
#include "ballsight/robot/path_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

/// Drives an ideal differential drive (no inertia) with the follower's commands at 100 Hz;
/// the closest the mouth came to each waypoint.
std::vector<double> drive(PathFollower& follower, Pose2D pose, double seconds, bool& arrived,
                          bool forwards_only = true) {
  const std::vector<Vec2>& path = follower.path();
  std::vector<double> closest(path.size(), 1e9);
  arrived = false;
  const double dt = 0.01, max_turn = rad_from_deg(90.0);
  for (int k = 0; k < static_cast<int>(seconds / dt) && !arrived; ++k) {
    const FollowCommand c = follower.command(pose);
    EXPECT_LE(std::abs(c.speed_mps), 1.0 + 1e-9);
    EXPECT_LE(std::abs(c.turn_rate_rps), max_turn + 1e-9);
    if (forwards_only) {
      EXPECT_GE(c.speed_mps, 0.0);  // the mouth collects driving forwards
    }
    arrived = c.arrived;
    pose.heading_rad += c.turn_rate_rps * dt;
    pose.position +=
        c.speed_mps * dt * Vec2(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
    const Vec2 mouth =
        pose.position + 0.30 * Vec2(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
    for (std::size_t i = 0; i < path.size(); ++i) {
      closest[i] = std::min(closest[i], (mouth - path[i]).norm());
    }
  }
  return closest;
}

TEST(PathFollower, TheMouthPassesOverEveryWaypointAndStopsAtTheEnd) {
  PathFollower follower;
  // The mouth starts at the path's start; a zig-zag with sharp corners.
  follower.set_path({Vec2(0.3, 0), Vec2(3, 0), Vec2(3, 2), Vec2(1, 3), Vec2(5, 3)});
  bool arrived = false;
  const std::vector<double> closest = drive(follower, {Vec2(0, 0), 0.0}, 60.0, arrived);
  EXPECT_TRUE(arrived);
  for (std::size_t i = 0; i < closest.size(); ++i) EXPECT_LT(closest[i], 0.12) << "waypoint " << i;
  EXPECT_NEAR(follower.progress_m(), 2.7 + 2.0 + std::sqrt(5.0) + 4.0 + 0.25,
              0.06);  // and past the end
}

TEST(PathFollower, BallsInALineAreDrivenOverAtFullSpeed) {
  PathFollower follower;
  follower.set_path({Vec2(0.3, 0), Vec2(2, 0), Vec2(4, 0), Vec2(6, 0)});
  follower.command({Vec2(0, 0), 0.0});
  const FollowCommand at_a_ball = follower.command({Vec2(1.7, 0), 0.0});  // mouth on (2, 0)
  EXPECT_NEAR(at_a_ball.speed_mps, 1.0, 1e-9);
  EXPECT_NEAR(at_a_ball.turn_rate_rps, 0.0, 1e-9);
}

TEST(PathFollower, APathBehindIsTurnedToOnTheSpot) {
  PathFollower follower;
  follower.set_path({Vec2(-0.3, 0), Vec2(-3, 0)});  // behind the robot, which faces +x
  const FollowCommand first = follower.command({Vec2(0, 0), 0.0});
  EXPECT_EQ(first.speed_mps, 0.0);
  EXPECT_NEAR(std::abs(first.turn_rate_rps), rad_from_deg(90.0), 1e-12);
  bool arrived = false;
  const std::vector<double> closest = drive(follower, {Vec2(0, 0), 0.0}, 30.0, arrived);
  EXPECT_TRUE(arrived);
  EXPECT_LT(closest.back(), 0.06);
}

TEST(PathFollower, AShortLegStraightBehindIsBackedAlong) {
  // The mouth at a ball against the net, facing it; the route backs off to the lane's edge, then
  // goes along it: the robot reverses out before it turns (no room to turn at the net).
  FollowerOptions options;
  options.back_off_zone = FieldRect{Vec2(-0.45, -6.9), Vec2(0.45, 6.9)};
  PathFollower follower(options);
  const std::vector<Vec2> path{Vec2(0.06, 2), Vec2(0.45, 2), Vec2(0.45, 4), Vec2(3, 4)};
  follower.set_path(path);
  const FollowCommand back = follower.command({Vec2(0.36, 2), kPi});
  EXPECT_LT(back.speed_mps, 0.0);
  EXPECT_NEAR(back.turn_rate_rps, 0.0, 1e-9);
  bool arrived = false;
  follower.set_path(path);
  const std::vector<double> closest = drive(follower, {Vec2(0.36, 2), kPi}, 30.0, arrived, false);
  EXPECT_TRUE(arrived);
  for (std::size_t i = 0; i < closest.size(); ++i) EXPECT_LT(closest[i], 0.12) << "waypoint " << i;
  // A long leg behind is still turned to on the spot: the mouth collects driving forwards; and
  // a short one where there is room to turn is not reversed along.
  follower.set_path({Vec2(0.06, 2), Vec2(3, 2)});
  EXPECT_EQ(follower.command({Vec2(0.36, 2), kPi}).speed_mps, 0.0);
  follower.set_path({Vec2(4.06, 2), Vec2(4.45, 2), Vec2(4.45, 4)});
  EXPECT_GE(follower.command({Vec2(4.36, 2), kPi}).speed_mps, 0.0);
}

TEST(PathFollower, ATurnOnTheSpotKeepsItsDirection) {
  // The carrot straight behind, the pose noisy and the route new at every update: the turn
  // must not flip from side to side (the robot would stand there for ever).
  PathFollower follower;
  double sign = 0.0;
  for (int k = 0; k < 20; ++k) {
    const double noise = (k % 2 ? 1.0 : -1.0) * 0.01;
    follower.set_path({Vec2(0.3, noise), Vec2(-3, -noise)});
    const FollowCommand c = follower.command({Vec2(0, 0), noise});
    EXPECT_EQ(c.speed_mps, 0.0);
    if (k == 0) sign = std::copysign(1.0, c.turn_rate_rps);
    EXPECT_EQ(std::copysign(1.0, c.turn_rate_rps), sign) << "update " << k;
  }
}

TEST(PathFollower, ABallBesideTheBodyIsReachedByMovingAwayFirst) {
  // The next waypoint beside the robot, inside the circle the mouth turns on: turning on the
  // spot would never bring the mouth over it; the robot creeps forward, then turns.
  PathFollower follower;
  follower.set_path({Vec2(0.3, 0), Vec2(0.05, 0.2), Vec2(-3, 0.2)});
  const FollowCommand away = follower.command({Vec2(0, 0), 0.0});
  EXPECT_GT(away.speed_mps, 0.0);
  EXPECT_EQ(away.turn_rate_rps, 0.0);
  bool arrived = false;
  follower.set_path({Vec2(0.3, 0), Vec2(0.05, 0.2), Vec2(-3, 0.2)});
  const std::vector<double> closest = drive(follower, {Vec2(0, 0), 0.0}, 30.0, arrived);
  EXPECT_LT(closest[1], 0.12);
}

TEST(PathFollower, NoPathMeansStandStill) {
  PathFollower follower;
  const FollowCommand c = follower.command({Vec2(1, 1), 0.3});
  EXPECT_TRUE(c.arrived);
  EXPECT_EQ(c.speed_mps, 0.0);
  FollowerOptions bad;
  bad.lookahead_m = 0.0;
  EXPECT_THROW(PathFollower{bad}, InputError);
}

}  // namespace
}  // namespace ballsight
