#include "ballsight/world/hidden_balls.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

WorldModel world_with(std::vector<Vec2> balls, std::optional<Vec2> robot) {
  WorldModel w;
  for (const Vec2& b : balls) w.balls.push_back({b, Eigen::Matrix2d::Zero(), {0}});
  if (robot) {
    RobotPoseEstimate estimate;
    estimate.pose = {*robot, 0.0};
    w.robot = estimate;
  }
  return w;
}

TEST(HiddenBallMemory, ABallThatVanishesBesideTheRobotIsKeptForAWhile) {
  HiddenBallOptions options;
  options.max_frame_sets = 3;
  HiddenBallMemory memory(options);
  WorldModel first = world_with({Vec2(5, 5), Vec2(0, 0.6)}, Vec2(0, 0));
  memory.apply(first);
  EXPECT_EQ(first.balls.size(), 2u);  // nothing remembered yet
  // Both vanish: the one beside the robot is remembered (as its own site), the far one is not.
  for (int k = 1; k <= 3; ++k) {
    WorldModel w = world_with({}, Vec2(0, 0));
    memory.apply(w);
    ASSERT_EQ(w.balls.size(), 1u) << "frame set " << k;
    EXPECT_EQ(w.balls[0].position_m, Vec2(0, 0.6));
    EXPECT_TRUE(w.balls[0].cameras.empty()) << "no camera sees it";
    ASSERT_EQ(w.sites.size(), 1u);
    EXPECT_EQ(w.sites[0].balls, std::vector<int>{0});
    // The memory's state says so too: one ball, missed k frame sets in a row.
    ASSERT_EQ(memory.state().remembered.size(), 1u);
    EXPECT_EQ(memory.state().remembered[0].frame_sets, k);
    EXPECT_TRUE(memory.state().last_seen.empty());
  }
  WorldModel late = world_with({}, Vec2(0, 0));
  memory.apply(late);
  EXPECT_TRUE(late.balls.empty()) << "forgotten after max_frame_sets";
}

TEST(HiddenBallMemory, SeenAgainOrTheRobotGoneItIsNotAddedTwice) {
  HiddenBallMemory memory;
  WorldModel first = world_with({Vec2(0, 0.6)}, Vec2(0, 0));
  memory.apply(first);
  WorldModel hidden = world_with({}, Vec2(0, 0));
  memory.apply(hidden);
  ASSERT_EQ(hidden.balls.size(), 1u);
  WorldModel again = world_with({Vec2(0.01, 0.62)}, Vec2(0, 0));
  memory.apply(again);
  EXPECT_EQ(again.balls.size(), 1u) << "seen again: once";
  memory.apply(hidden = world_with({}, Vec2(0, 0)));
  EXPECT_EQ(hidden.balls.size(), 1u);
  WorldModel away = world_with({}, Vec2(6, 0));
  memory.apply(away);
  EXPECT_TRUE(away.balls.empty()) << "the robot moved away: not hidden by it";
  WorldModel lost = world_with({}, std::nullopt);
  memory.apply(lost);
  EXPECT_TRUE(lost.balls.empty());
  HiddenBallOptions bad;
  bad.near_robot_m = 0.0;
  EXPECT_THROW(HiddenBallMemory{bad}, InputError);
}

TEST(HiddenBallMemory, ABallThatVanishesAtTheMouthWasTaken) {
  HiddenBallMemory memory;
  WorldModel first = world_with({Vec2(0.55, 0.2), Vec2(-0.6, 0)}, Vec2(0, 0));  // heading +x
  memory.apply(first);
  WorldModel next = world_with({}, Vec2(0, 0));
  memory.apply(next);
  ASSERT_EQ(next.balls.size(), 1u) << "the one at the mouth was collected";
  EXPECT_EQ(next.balls[0].position_m, Vec2(-0.6, 0));
}

}  // namespace
}  // namespace ballsight
