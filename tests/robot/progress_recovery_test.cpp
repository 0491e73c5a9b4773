// The progress checker and its recovery (robot/progress_recovery.hpp): a robot with balls left
// that neither moves nor turns for the window backs up, or drives ahead when it cannot back up,
// and then follows its route again.
#include "ballsight/robot/progress_recovery.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr double kTick = 0.1;

TEST(ProgressRecovery, MovingOrTurningIsProgress) {
  ProgressRecovery r;
  Pose2D pose{Vec2(0, 0), 0.0};
  for (int k = 0; k < 300; ++k) {  // 30 s, 0.3 m every 10 s and turning
    pose.position.x() += 0.001;
    pose.heading_rad += 0.01;
    EXPECT_FALSE(r.step(pose, k * kTick, true)) << k;
  }
  ProgressRecovery straight;  // 0.6 m in 10 s without turning
  for (int k = 0; k < 300; ++k) {
    EXPECT_FALSE(straight.step({Vec2(0.006 * k, 0.0), 0.0}, k * kTick, true)) << k;
  }
  ProgressRecovery idle;  // standing still with no ball left: nothing to do
  for (int k = 0; k < 300; ++k) EXPECT_FALSE(idle.step({Vec2(1, 1), 0.0}, k * kTick, false));
  EXPECT_EQ(idle.stalls(), 0);
}

TEST(ProgressRecovery, AStalledRobotBacksUpThenFollowsAgain) {
  ProgressRecovery r;
  const Pose2D still{Vec2(2, 1), 0.5};
  for (int k = 0; k < 100; ++k) EXPECT_FALSE(r.step(still, k * kTick, true));
  double t = 10.0;  // the window's end
  const std::optional<FollowCommand> back = r.step(still, t, true);
  ASSERT_TRUE(back);
  EXPECT_LT(back->speed_mps, 0.0);
  EXPECT_EQ(back->turn_rate_rps, 0.0);
  EXPECT_EQ(r.stalls(), 1);
  // It backs away along its heading; 0.3 m back, the route again.
  Pose2D pose = still;
  for (int k = 0; k < 5; ++k) {
    pose.position -= 0.05 * Vec2(std::cos(0.5), std::sin(0.5));
    t += kTick;
    EXPECT_TRUE(r.step(pose, t, true));
  }
  pose.position -= 0.06 * Vec2(std::cos(0.5), std::sin(0.5));
  EXPECT_FALSE(r.step(pose, t + kTick, true));
  EXPECT_EQ(r.recoveries(), 1);  // the back-up
}

TEST(ProgressRecovery, BlockedBehindItDrivesAhead) {
  ProgressRecovery r;
  const Pose2D still{Vec2(-0.47, -4.6), 1.9};  // pressed against the net
  for (int k = 0; k < 100; ++k) r.step(still, k * kTick, true);
  double t = 10.0;
  ASSERT_TRUE(r.step(still, t, true));  // backs up ...
  std::optional<FollowCommand> c;
  for (int k = 0; k < 21; ++k) c = r.step(still, t += kTick, true);  // ... but does not move
  ASSERT_TRUE(c);
  EXPECT_GT(c->speed_mps, 0.0);  // so ahead
  int ahead = 0;                 // commands ahead
  while (c && ahead < 30) {
    c = r.step(still, t += kTick, true);
    ahead += c ? 1 : 0;
  }
  EXPECT_GE(ahead, 19);  // given up after 2 s: the route again, and a new window
  EXPECT_LE(ahead, 20);
  EXPECT_FALSE(r.step(still, t += kTick, true));
  EXPECT_EQ(r.stalls(), 1);
  EXPECT_EQ(r.recoveries(), 2);  // the back-up and the drive ahead
}

// A window is timed on one clock: a restart (the clock changes) or a clock that goes back (a
// court resumed) begins a new one instead of finding a stall at once.
TEST(ProgressRecovery, ANewClockBeginsANewWindow) {
  ProgressRecovery r;
  const Pose2D still{Vec2(1, 1), 0.0};
  EXPECT_FALSE(r.step(still, 0.0, true));  // wall clock, 0 s
  r.restart();
  EXPECT_FALSE(r.step(still, 250.0, true));  // the court's clock, already at 250 s
  EXPECT_FALSE(r.step(still, 259.0, true));
  EXPECT_FALSE(r.step(still, 3.0, true));  // back: a new window from 3 s
  EXPECT_FALSE(r.step(still, 12.0, true));
  EXPECT_TRUE(r.step(still, 13.0, true));
  EXPECT_EQ(r.stalls(), 1);
}

TEST(ProgressRecovery, RefusesNonPositiveSettings) {
  ProgressOptions bad;
  bad.window_s = 0.0;
  EXPECT_THROW(ProgressRecovery{bad}, InputError);
}

}  // namespace
}  // namespace ballsight
