// The robot's pose between camera fixes (robot/pose_tracker.hpp): a fix replaces the estimate;
// without one the pose moves on by the predicted motion, then by the wheels' odometry; dead
// reckoning ends after its bounds.
#include "ballsight/robot/pose_tracker.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

Rigid2 ahead(double m) {
  return {Vec2(m, 0.0), 0.0};
}

TEST(PoseTracker, ACameraFixIsThePose) {
  PoseTracker t;
  EXPECT_FALSE(t.at_capture(std::nullopt, ahead(0.1)));  // no fix yet: unknown
  const Pose2D seen{Vec2(1, 2), 0.5};
  EXPECT_EQ(t.at_capture(seen, ahead(0.1))->position, seen.position);
  EXPECT_TRUE(t.seen());
  t.odometry({Vec2(3, 3), 0.0});  // a fix is not moved by odometry
  EXPECT_EQ(t.pose()->position, seen.position);
}

TEST(PoseTracker, OutOfSightTheOdometryCarriesThePoseOn) {
  PoseTracker t;
  t.at_capture(Pose2D{Vec2(0, 0), kPi / 2.0}, ahead(0.0));  // facing +y
  t.odometry({Vec2(10, 10), 0.0});                          // the odometry's own frame
  // The prediction: 0.1 m ahead (along +y in the field).
  const std::optional<Pose2D> predicted = t.at_capture(std::nullopt, ahead(0.1));
  ASSERT_TRUE(predicted);
  EXPECT_FALSE(t.seen());
  EXPECT_NEAR(predicted->position.y(), 0.1, 1e-12);
  // The wheels say 0.08 m ahead and a turn of 0.1 rad: that replaces the prediction.
  t.odometry({Vec2(10.08, 10), 0.1});
  EXPECT_NEAR(t.pose()->position.x(), 0.0, 1e-12);
  EXPECT_NEAR(t.pose()->position.y(), 0.08, 1e-12);
  EXPECT_NEAR(t.pose()->heading_rad, kPi / 2.0 + 0.1, 1e-12);
  // A reading that jumps (a restarted court) leaves the estimate as it was.
  t.at_capture(std::nullopt, ahead(0.0));
  const Pose2D before = *t.pose();
  t.odometry({Vec2(-50, 3), 2.0});
  EXPECT_EQ(t.pose()->position, before.position);
}

TEST(PoseTracker, DeadReckoningEndsAfterItsBounds) {
  PoseTrackerOptions options;
  options.max_unseen_m = 1.0;
  options.max_unseen_updates = 1000;
  PoseTracker far(options);
  far.at_capture(Pose2D{}, ahead(0.0));
  for (int k = 0; k < 9; ++k) EXPECT_TRUE(far.at_capture(std::nullopt, ahead(0.1))) << k;
  EXPECT_FALSE(far.at_capture(std::nullopt, ahead(0.2)));  // 1.1 m
  EXPECT_FALSE(far.at_capture(std::nullopt, ahead(0.0)));  // and stays unknown
  EXPECT_TRUE(far.at_capture(Pose2D{}, ahead(0.0)));       // until the next fix
  options.max_unseen_updates = 3;
  PoseTracker long_time(options);
  long_time.at_capture(Pose2D{}, ahead(0.0));
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(long_time.at_capture(std::nullopt, ahead(0.0)));
  EXPECT_FALSE(long_time.at_capture(std::nullopt, ahead(0.0)));
}

TEST(PoseTracker, RefusesNegativeBounds) {
  PoseTrackerOptions bad;
  bad.max_unseen_m = -1.0;
  EXPECT_THROW(PoseTracker{bad}, InputError);
}

}  // namespace
}  // namespace ballsight
