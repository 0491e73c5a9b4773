// Obstacles beside the robot (world/hidden_obstacles.hpp): one that drops out of the world model
// while the robot stands near it is kept until it is seen again, the robot leaves, or time is up;
// one that drops out far from the robot is gone.
#include "ballsight/world/hidden_obstacles.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

WorldModel world_with(const Vec2& robot, std::vector<FloorObstacle> obstacles) {
  WorldModel w;
  w.robot = RobotPoseEstimate{};
  w.robot->pose = {robot, 0.0};
  w.obstacles = std::move(obstacles);
  return w;
}

FloorObstacle person(const Vec2& at) {
  FloorObstacle o;
  o.center_m = at;
  o.radius_m = 0.3;
  o.cameras = {0, 1, 2};
  return o;
}

TEST(HiddenObstacles, KeptBesideTheRobotUntilSeenAgainOrLeft) {
  HiddenObstacleMemory memory(HiddenObstacleOptions{1.2, 3, 0.5});
  WorldModel w = world_with(Vec2(0, 0), {person(Vec2(1, 0)), person(Vec2(8, 0))});
  memory.apply(w);
  ASSERT_EQ(w.obstacles.size(), 2u);
  w = world_with(Vec2(0.2, 0), {});  // both dropped out: the near one is kept
  memory.apply(w);
  ASSERT_EQ(w.obstacles.size(), 1u);
  EXPECT_EQ(w.obstacles[0].center_m, Vec2(1, 0));
  EXPECT_TRUE(w.obstacles[0].cameras.empty());
  w = world_with(Vec2(0.3, 0), {person(Vec2(1.1, 0))});  // seen again: once
  memory.apply(w);
  EXPECT_EQ(w.obstacles.size(), 1u);
  for (int k = 0; k < 3; ++k) {
    w = world_with(Vec2(0.3, 0), {});
    memory.apply(w);
    EXPECT_EQ(w.obstacles.size(), 1u) << k;
  }
  w = world_with(Vec2(0.3, 0), {});  // missed in more than 3 frame sets
  memory.apply(w);
  EXPECT_TRUE(w.obstacles.empty());

  HiddenObstacleMemory left;
  WorldModel v = world_with(Vec2(0, 0), {person(Vec2(1, 0))});
  left.apply(v);
  v = world_with(Vec2(0.2, 0), {});  // remembered,
  left.apply(v);
  EXPECT_EQ(v.obstacles.size(), 1u);
  v = world_with(Vec2(0.2, 0), {});  // also while the robot itself is not seen,
  v.robot.reset();
  left.apply(v);
  EXPECT_EQ(v.obstacles.size(), 1u);
  v = world_with(Vec2(5, 0), {});  // until the robot drove away
  left.apply(v);
  EXPECT_TRUE(v.obstacles.empty());
  EXPECT_THROW(HiddenObstacleMemory(HiddenObstacleOptions{-1.0, 3, 0.5}), InputError);
}

}  // namespace
}  // namespace ballsight
