// The simulated collector's truth: limits on speed and turning, the net and the fence in its way,
// and the balls its mouth passes over.
#include "ballsight/sim/robot_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight::sim {
namespace {

constexpr double kDt = 0.01;

struct Drive {
  TennisCourtSpec court;
  DriveLimits limits;
  RobotFootprint footprint;
  RobotMotion motion;
  int blocked = 0;

  /// Drives with `command` for `seconds`.
  void run(const DriveCommand& command, double seconds) {
    for (int k = 0; k < static_cast<int>(std::lround(seconds / kDt)); ++k) {
      const DriveStep step = drive_step(motion, command, kDt, limits, footprint, court);
      motion = step.motion;
      blocked += step.blocked ? 1 : 0;
    }
  }
};

TEST(RobotMotion, SpeedsUpAndTurnsWithinItsLimits) {
  Drive d;
  d.motion.pose = {Vec2(-10, 0), 0.0};
  d.run({5.0, 0.0}, 0.5);                      // asks for more than the robot can
  EXPECT_NEAR(d.motion.speed_mps, 0.5, 1e-9);  // 1 m/s^2
  d.run({5.0, 0.0}, 1.5);
  EXPECT_NEAR(d.motion.speed_mps, 1.0, 1e-9);  // capped
  EXPECT_NEAR(d.motion.pose.position.x(), -10.0 + 0.5 + 1.0,
              1e-6);  // 0.5 m speeding up, then 1 m/s
  Drive t;
  t.motion.pose = {Vec2(-10, 0), 0.0};
  t.run({0.0, 10.0}, 1.25);  // 90 deg/s at most, reached after 0.25 s at 360 deg/s^2
  EXPECT_NEAR(deg_from_rad(t.motion.pose.heading_rad), 0.5 * 22.5 + 90.0, 1e-6);
  EXPECT_NEAR(t.motion.pose.position.x(), -10.0, 1e-12);  // on the spot
  // An arc of radius 1 m, 1.5 rad of it.
  Drive a;
  a.motion = {{Vec2(-10, 0), 0.0}, 0.5, 0.5};
  a.run({0.5, 0.5}, 3.0);
  EXPECT_NEAR(a.motion.pose.position.x(), -10.0 + std::sin(1.5), 1e-9);
  EXPECT_NEAR(a.motion.pose.position.y(), 1.0 - std::cos(1.5), 1e-9);
}

TEST(RobotMotion, TheNetAndTheFenceStopIt) {
  Drive net;
  net.motion.pose = {Vec2(-2, 1.0), 0.0};
  net.run({1.0, 0.0}, 5.0);
  EXPECT_GT(net.blocked, 0);
  EXPECT_LT(net.motion.pose.position.x() + net.footprint.front_m, 0.0);   // still on its side
  EXPECT_GT(net.motion.pose.position.x() + net.footprint.front_m, -0.1);  // right at the net
  // Beyond the posts it passes.
  Drive round;
  round.motion.pose = {Vec2(-2, 7.0), 0.0};
  round.run({1.0, 0.0}, 5.0);
  EXPECT_EQ(round.blocked, 0);
  EXPECT_GT(round.motion.pose.position.x(), 2.0);
  Drive fence;
  fence.motion.pose = {Vec2(16, -3), 0.0};
  fence.run({1.0, 0.0}, 5.0);
  EXPECT_GT(fence.blocked, 0);
  EXPECT_LE(fence.motion.pose.position.x() + fence.footprint.front_m, 18.0);
  // Without a net nothing stops it at x = 0.
  Drive open;
  open.court.net.enabled = false;
  open.motion.pose = {Vec2(-2, 1.0), 0.0};
  open.run({1.0, 0.0}, 5.0);
  EXPECT_EQ(open.blocked, 0);
}

TEST(RobotMotion, TheMouthCollectsTheBallsItPassesOver) {
  CourtScene scene;
  const auto ball = [&](int id, double x, double y) {
    SceneSphere b;
    b.id = id;
    b.center_in_field = Vec3(x, y, kTennisBallRadiusM);
    scene.balls.push_back(b);
  };
  ball(0, 1.0, 0.0);   // straight ahead
  ball(1, 1.5, 0.3);   // within the 70 cm mouth
  ball(2, 1.5, 0.45);  // beside it
  ball(3, -1.0, 0.0);  // behind
  SceneSphere reference;
  reference.kind = ObjectKind::reference_ball;
  reference.center_in_field = Vec3(1.2, 0.0, 0.02);
  scene.balls.push_back(reference);
  const RobotFootprint f;
  std::vector<int> taken;
  Pose2D pose{Vec2(0, 0), 0.0};
  for (int k = 0; k < 200; ++k) {  // 2 m forwards in 1 cm steps
    const Pose2D next{pose.position + Vec2(0.01, 0), 0.0};
    for (int id : collect_swept(scene, pose, next, f)) taken.push_back(id);
    pose = next;
  }
  EXPECT_EQ(taken, (std::vector<int>{0, 1}));
  EXPECT_EQ(scene.balls.size(), 3u);  // the one beside, the one behind, the reference ball
  // Driving backwards over a ball does not collect it.
  ball(4, 1.0, 0.0);
  EXPECT_TRUE(collect_swept(scene, {Vec2(1.0, 0), 0.0}, {Vec2(0.5, 0), 0.0}, f).empty());
}

TEST(RobotMotion, TheMouthTakesABallItTouches) {
  // A ball against the net, its centre 0.05 m ahead of where the mouth stops: the mouth touches
  // it (within its radius) and takes it; one a radius further stays.
  CourtScene scene;
  SceneSphere near, far;
  near.kind = far.kind = ObjectKind::tennis_ball;
  near.radius_m = far.radius_m = 0.0335;
  near.id = 1;
  far.id = 2;
  near.center_in_field = Vec3(0.03, 0.0, 0.0335);
  far.center_in_field = Vec3(-0.01, 0.2, 0.0335);
  scene.balls = {near, far};
  const RobotFootprint f = RobotFootprint::of(RobotBox{}, 0.30, 0.70);
  // Facing -x, the mouth moving from x = 0.30 to x = 0.06.
  const std::vector<int> taken =
      collect_swept(scene, {Vec2(0.60, 0.0), kPi}, {Vec2(0.36, 0.0), kPi}, f);
  EXPECT_EQ(taken, std::vector<int>{1});
  ASSERT_EQ(scene.balls.size(), 1u);
  EXPECT_EQ(scene.balls[0].id, 2);
}

TEST(RobotMotion, FootprintOfTheReportsRobot) {
  const RobotFootprint f = RobotFootprint::of(RobotBox{}, 0.30, 0.70);
  EXPECT_DOUBLE_EQ(f.front_m, 0.30);
  EXPECT_DOUBLE_EQ(f.half_width_m, 0.35);
  EXPECT_THROW((DriveLimits{0.0, 1.0, 90.0, 360.0}.validate()), InputError);
}

TEST(RobotMotion, ClearanceIsTheBodysNearestApproach) {
  const TennisCourtSpec court;
  const RobotFootprint f;  // 0.30 back and front, 0.35 either side
  const double fence_x = court.surround_length_m / 2.0;
  const double mesh = court.net.post_radius_m;
  // Facing the fence, 10 cm off; alongside the mesh, 5 cm off; turned 45 degrees off the
  // mesh, a corner nearest; beyond a post's end; overlapping the net.
  EXPECT_NEAR(footprint_clearance(f, {Vec2(fence_x - 0.40, 0.0), 0.0}, court), 0.10, 1e-9);
  EXPECT_NEAR(footprint_clearance(f, {Vec2(mesh + 0.40, 1.0), kPi / 2.0}, court), 0.05, 1e-9);
  const double corner = std::hypot(0.30, 0.35) * std::cos(std::atan2(0.35, 0.30) - kPi / 4.0);
  EXPECT_NEAR(footprint_clearance(f, {Vec2(mesh + corner + 0.02, 1.0), kPi / 4.0}, court), 0.02,
              1e-9);
  const double post_end =
      court.doubles_width_m / 2.0 + court.net.post_outside_doubles_m + court.net.post_radius_m;
  EXPECT_NEAR(footprint_clearance(f, {Vec2(0.0, post_end + 0.35 + 0.07), 0.0}, court), 0.07, 1e-9);
  EXPECT_EQ(footprint_clearance(f, {Vec2(0.2, 1.0), 0.0}, court), 0.0);
}

// A ball is reachable when the mouth can be put over it with the whole body clear: against one
// fence (square to it) or against the net's mesh, yes; in a corner, touching both fences, only
// when the body is no wider than the mouth (the ball at the mouth's edge, the body's side along
// the fence): a body 0.10 m wider on each side reaches it only 12 cm out of the corner.
TEST(RobotMotion, TheMouthReachesABallUnlessTheBodyCannotStandThere) {
  const TennisCourtSpec court;
  const RobotFootprint f;
  const double r = kTennisBallRadiusM;
  const double fx = court.surround_length_m / 2.0, fy = court.surround_width_m / 2.0;
  EXPECT_TRUE(mouth_can_reach(f, Vec2(5.0, 2.0), r, court));
  EXPECT_TRUE(mouth_can_reach(f, Vec2(fx - r, 0.0), r, court));
  EXPECT_TRUE(mouth_can_reach(f, Vec2(court.net.post_radius_m + r, 2.0), r, court));
  EXPECT_TRUE(mouth_can_reach(f, Vec2(fx - r, fy - r), r, court));
  RobotFootprint wide = f;
  wide.half_width_m = 0.45;
  EXPECT_TRUE(mouth_can_reach(wide, Vec2(fx - r, 0.0), r, court));
  EXPECT_FALSE(mouth_can_reach(wide, Vec2(fx - r, fy - r), r, court));
  EXPECT_TRUE(mouth_can_reach(wide, Vec2(fx - r - 0.12, fy - r - 0.12), r, court));
}

}  // namespace
}  // namespace ballsight::sim
