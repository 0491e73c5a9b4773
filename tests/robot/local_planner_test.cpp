// The local planner: a command that keeps the body clear goes as wanted; one that would touch the
// net or the fence is slowed, replaced by one that keeps clear and still gets on, or stopped.
#include "ballsight/robot/local_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ballsight/core/angle.hpp"
#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

constexpr double kMouthM = 0.30;

LocalPlanner standard_planner() {
  return LocalPlanner(Costmap(DrivableCourt::standard()), LocalPlannerOptions{});
}

/// Drives an ideal differential drive with `command` for `seconds`.
Pose2D drive(Pose2D pose, const FollowCommand& command, double seconds) {
  return along_arc(pose, command.speed_mps, command.turn_rate_rps, seconds);
}

TEST(LocalPlanner, AClearCommandGoesAsWanted) {
  LocalPlanner planner = standard_planner();
  const Pose2D pose{Vec2(5.0, 3.0), 0.0};
  const FollowCommand wanted{1.0, 0.5, false};
  const GuardedCommand g = planner.guard(pose, wanted, Vec2(6.0, 3.5), kMouthM);
  EXPECT_EQ(g.guard, Guard::as_wanted);
  EXPECT_EQ(g.command.speed_mps, 1.0);
  EXPECT_EQ(g.command.turn_rate_rps, 0.5);
}

TEST(LocalPlanner, SlowsBeforeTheFenceAndDrivesNoFurtherAtIt) {
  LocalPlanner planner = standard_planner();
  // Facing the fence at x = 18: the front 0.6 m from it at full speed (braking takes 0.5 m, the
  // period 0.1 m), then 0.2 m from it, then touching the margin.
  const FollowCommand wanted{1.0, 0.0, false};
  const Vec2 carrot(18.5, 0.0);
  const GuardedCommand far = planner.guard({Vec2(17.0, 0.0), 0.0}, wanted, carrot, kMouthM);
  EXPECT_EQ(far.guard, Guard::as_wanted);
  const GuardedCommand near = planner.guard({Vec2(17.5, 0.0), 0.0}, wanted, carrot, kMouthM);
  EXPECT_EQ(near.guard, Guard::slowed);
  EXPECT_GT(near.command.speed_mps, 0.0);
  EXPECT_LT(near.command.speed_mps, 1.0);
  // Within the margin it does not drive on: it stands, or backs off (the way out that leaves the
  // body the most room).
  const GuardedCommand at = planner.guard({Vec2(17.68, 0.0), 0.0}, wanted, carrot, kMouthM);
  EXPECT_NE(at.guard, Guard::as_wanted);
  EXPECT_LE(at.command.speed_mps, 0.0);
}

TEST(LocalPlanner, NoTurnOnTheSpotThatSwingsACornerIntoTheNet) {
  LocalPlanner planner = standard_planner();
  // Alongside the net, the body's near side 2.5 cm from the mesh: any turn on the spot, even
  // slowed to a quarter, swings a corner within the 1.5 cm margin. The route wants the mouth out
  // of the lane, square to the net.
  const double x = 0.04 + 0.025 + 0.35;
  const Pose2D pose{Vec2(x, 2.0), kPi / 2.0};
  const FollowCommand spin{0.0, -rad_from_deg(90.0), false};
  const Vec2 carrot(1.0, 2.3);
  const double before = planner.clearance(pose);
  EXPECT_NEAR(before, 0.025, 0.005);
  ASSERT_EQ(planner.guard(pose, spin, carrot, kMouthM).guard, Guard::replaced);
  // Asked for the turn again and again, it keeps the body off the net and comes round to face the
  // carrot all the same, within 10 s: it backs up and arcs away, a replacement kept for a few
  // periods (not driving on and backing in turn).
  const auto facing_error = [&](const Pose2D& p) {
    const Vec2 to = carrot - p.position;
    return std::abs(wrap_rad_pi(std::atan2(to.y(), to.x()) - p.heading_rad));
  };
  Pose2D p = pose;
  double best = facing_error(pose);
  for (int k = 0; k < 100; ++k) {
    p = drive(p, planner.guard(p, spin, carrot, kMouthM).command, 0.1);
    EXPECT_GT(planner.clearance(p), 0.0);
    best = std::min(best, facing_error(p));
  }
  EXPECT_LT(best, 0.1);
}

TEST(LocalPlanner, AnOutlineInsideTheMarginMayMoveAwayOnly) {
  LocalPlanner planner = standard_planner();
  // Pose noise put the front 1 cm from the fence: reversing goes, driving on does not.
  const Pose2D pose{Vec2(17.69, 0.0), 0.0};
  EXPECT_LT(planner.clearance(pose), 0.03);
  const GuardedCommand back = planner.guard(pose, {-0.3, 0.0, false}, Vec2(16.0, 0.0), kMouthM);
  EXPECT_EQ(back.guard, Guard::as_wanted);
  const GuardedCommand on = planner.guard(pose, {0.3, 0.0, false}, Vec2(18.5, 0.0), kMouthM);
  EXPECT_NE(on.guard, Guard::as_wanted);
  EXPECT_LE(on.command.speed_mps, 0.0);
}

TEST(LocalPlanner, RefusesBadOptions) {
  LocalPlannerOptions options;
  options.margin_m = -0.1;
  EXPECT_THROW(LocalPlanner(Costmap(DrivableCourt::standard()), options), InputError);
  options = {};
  options.body.half_width_m = 0.0;
  EXPECT_THROW(LocalPlanner(Costmap(DrivableCourt::standard()), options), InputError);
}

}  // namespace
}  // namespace ballsight
