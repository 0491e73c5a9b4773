#include "ballsight/plan/drivable_court.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

const DrivableCourt kCourt = DrivableCourt::standard();
const double kEnd = 10.97 / 2.0 + 0.914 + 0.5;  // keep-out's end beyond the post
const double kLane = 0.45;                      // half the lane's width

TEST(DrivableCourt, StraightWhereTheNetIsNotInTheWay) {
  const DrivablePath p = shortest_path(kCourt, Vec2(-5, 2), Vec2(-1, -3));
  EXPECT_EQ(p.via.size(), 0u);
  EXPECT_NEAR(p.length_m, (Vec2(-5, 2) - Vec2(-1, -3)).norm(), 1e-12);
  // Past the posts, straight over the net line.
  EXPECT_EQ(shortest_path(kCourt, Vec2(-3, 8), Vec2(3, 8)).via.size(), 0u);
}

TEST(DrivableCourt, AcrossTheNetGoesRoundTheNearerPost) {
  const Vec2 a(-4, 5), b(4, 5);
  const DrivablePath p = shortest_path(kCourt, a, b);
  ASSERT_EQ(p.via.size(), 2u);
  EXPECT_NEAR(p.via[0].y(), kEnd, 1e-12);
  EXPECT_NEAR(p.via[0].x(), -kLane, 1e-12);
  EXPECT_NEAR(p.via[1].x(), kLane, 1e-12);
  const double expected =
      (Vec2(-kLane, kEnd) - a).norm() + 2 * kLane + (b - Vec2(kLane, kEnd)).norm();
  EXPECT_NEAR(p.length_m, expected, 1e-12);
  // And round the other post when that one is nearer.
  EXPECT_LT(shortest_path(kCourt, Vec2(-4, -5), Vec2(4, -5)).via[0].y(), 0.0);
}

TEST(DrivableCourt, BetweenTheStripsBeyondBothPostsAlongTheNet) {
  // Both ends level with the net, beyond opposite posts: the way runs down one side of the net.
  const DrivablePath p = shortest_path(kCourt, Vec2(0, 8), Vec2(0, -8));
  ASSERT_EQ(p.via.size(), 2u);
  EXPECT_NEAR(p.length_m, 2.0 * std::hypot(kLane, 8.0 - kEnd) + 2.0 * kEnd, 1e-9);
  EXPECT_NEAR(std::abs(p.via[0].x()), kLane, 1e-12);
  EXPECT_EQ(p.via[0].x(), p.via[1].x());
}

TEST(DrivableCourt, PathsAreSymmetricAndNeverShorterThanTheStraightLine) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(-18, 18), y(-9, 9);
  for (int trial = 0; trial < 2000; ++trial) {
    // Every other pair level with the net's keep-out, where the paths are hardest.
    Vec2 a(trial % 2 ? x(rng) : 0.3 * x(rng) / 18.0, y(rng));
    const Vec2 b(x(rng), y(rng));
    // Every fourth pair from a ball against the net (in the lane, outside the reach keep-out).
    if (trial % 4 == 1) a.x() = std::copysign(0.1 + 0.35 * (a.x() + 18) / 36, a.x());
    if (kCourt.in_net_zone(a) || kCourt.in_net_zone(b)) continue;
    const DrivablePath ab = shortest_path(kCourt, a, b), ba = shortest_path(kCourt, b, a);
    SCOPED_TRACE(testing::Message() << "seed 7 trial " << trial);
    ASSERT_TRUE(std::isfinite(ab.length_m));
    EXPECT_NEAR(ab.length_m, ba.length_m, 1e-9);
    EXPECT_GE(ab.length_m, (b - a).norm() - 1e-9);
    // Every piece of the path is clear of the net and inside the fence.
    Vec2 from = a;
    for (const Vec2& via : ab.via) {
      EXPECT_FALSE(kCourt.blocked(from, via));
      EXPECT_TRUE(kCourt.in_area(via));
      from = via;
    }
    EXPECT_FALSE(kCourt.blocked(from, b));
  }
}

TEST(DrivableCourt, AlongTheNetTheRouteKeepsToTheLaneAndReachesInStraight) {
  // Two balls against the net on one side: out to the lane's edge, along it, straight back in.
  const Vec2 a(0.1, 1.0), b(0.1, 3.0);
  EXPECT_TRUE(kCourt.blocked(a, b));
  const DrivablePath p = shortest_path(kCourt, a, b);
  ASSERT_EQ(p.via.size(), 2u);
  EXPECT_EQ(p.via[0], Vec2(kLane, 1.0));
  EXPECT_EQ(p.via[1], Vec2(kLane, 3.0));
  EXPECT_NEAR(p.length_m, 2.0 + 2 * (kLane - 0.1), 1e-12);
  // Straight away from the net is drivable; through the reach keep-out never is.
  EXPECT_FALSE(kCourt.blocked(a, Vec2(5.0, 1.0)));
  EXPECT_TRUE(kCourt.blocked(a, Vec2(-0.1, 1.0)));
  // To a ball away from the net: straight out first, then the shortest way.
  const DrivablePath out = shortest_path(kCourt, a, Vec2(4.0, 3.0));
  ASSERT_EQ(out.via.size(), 1u);
  EXPECT_EQ(out.via[0], Vec2(kLane, 1.0));
}

TEST(DrivableCourt, BallAgainstTheNetIsApproachedFromItsSide) {
  EXPECT_TRUE(kCourt.in_net_zone(Vec2(0.04, 2.0)));
  EXPECT_EQ(kCourt.approach_point(Vec2(0.04, 2.0)), Vec2(0.06, 2.0));
  EXPECT_EQ(kCourt.approach_point(Vec2(-0.04, 2.0)), Vec2(-0.06, 2.0));
  EXPECT_EQ(kCourt.approach_point(Vec2(3, 2)), Vec2(3, 2));
}

TEST(DrivableCourt, AlongTheFenceTheRouteEntersAndLeavesSquareToIt) {
  // The fence at y = -9 and x = 18; its lane 0.7 m wide.
  const Vec2 a(5.0, -8.9), b(7.0, -8.8);
  EXPECT_TRUE(kCourt.in_fence_lane(a));
  EXPECT_FALSE(kCourt.in_fence_lane(Vec2(5.0, -8.2)));
  EXPECT_EQ(kCourt.fence_exit(a), Vec2(5.0, -8.3));
  const DrivablePath p = shortest_path(kCourt, a, b);
  ASSERT_EQ(p.via.size(), 2u);
  EXPECT_EQ(p.via[0], Vec2(5.0, -8.3));
  EXPECT_EQ(p.via[1], Vec2(7.0, -8.3));
  EXPECT_NEAR(p.length_m, 0.6 + 2.0 + 0.5, 1e-12);
  const DrivablePath back = shortest_path(kCourt, b, a);  // the same bends, reversed
  ASSERT_EQ(back.via.size(), 2u);
  EXPECT_EQ(back.via[0], p.via[1]);
  EXPECT_NEAR(back.length_m, p.length_m, 1e-12);
  // In a corner: out square to the nearer side.
  EXPECT_EQ(kCourt.fence_exit(Vec2(17.9, -8.95)), Vec2(17.9, -8.3));
  EXPECT_EQ(kCourt.fence_exit(Vec2(17.9, -8.3)), Vec2(17.3, -8.3));
  // Driven within 10 degrees of square to the fence: straight.
  EXPECT_FALSE(kCourt.in_fence_lane(Vec2(5.0, -8.6)));
  EXPECT_EQ(shortest_path(kCourt, Vec2(5.0, -7.0), a).via.size(), 0u);
  EXPECT_EQ(shortest_path(kCourt, Vec2(5.1, -8.0), a).via.size(), 0u);
  EXPECT_EQ(shortest_path(kCourt, Vec2(6.0, -8.5), a).via.size(), 1u);   // 0.5 m out: no lane
  EXPECT_EQ(shortest_path(kCourt, Vec2(5.15, -8.7), a).via.size(), 0u);  // the mouth before it
  EXPECT_EQ(shortest_path(kCourt, Vec2(5.3, -8.8), a).via.size(), 2u);   // beside it
  // Out of the fence's lane and round the net: the exits first and last.
  const DrivablePath round = shortest_path(kCourt, Vec2(-2.0, -8.9), Vec2(2.0, 8.9));
  ASSERT_GE(round.via.size(), 2u);
  EXPECT_EQ(round.via[0], Vec2(-2.0, -8.3));
  EXPECT_EQ(round.via.back(), Vec2(2.0, 8.3));
  // No lane: the straight line.
  DrivableCourt open = kCourt;
  open.fence_lane_m = 0.0;
  EXPECT_EQ(shortest_path(open, a, b).via.size(), 0u);
}

TEST(DrivableCourt, BallInACornerIsApproachedSquareToTheNearerSide) {
  // 0.1 m from the fence at x = 18, 0.2 m from y = -9: the mouth square to x = 18, its centre
  // moved 0.3 m along it (the ball still in the mouth), where the body has room to turn.
  const auto near = [](const Vec2& a, const Vec2& b) { return (a - b).norm() < 1e-12; };
  EXPECT_PRED2(near, kCourt.approach_point(Vec2(17.9, -8.8)), Vec2(17.9, -8.5));
  // Far enough from the other side: the ball itself; along one side only: the ball.
  EXPECT_EQ(kCourt.approach_point(Vec2(17.9, -8.4)), Vec2(17.9, -8.4));
  EXPECT_EQ(kCourt.approach_point(Vec2(17.9, -6.0)), Vec2(17.9, -6.0));
  // The mirror corner.
  EXPECT_PRED2(near, kCourt.approach_point(Vec2(-17.8, 8.95)), Vec2(-17.5, 8.95));
}

TEST(DrivableCourt, ValidateNamesTheProblem) {
  DrivableCourt small = kCourt;
  small.area_min_m = Vec2(-18, -6);
  small.area_max_m = Vec2(18, 6);
  EXPECT_THROW(small.validate(), InputError);
  DrivableCourt narrow = kCourt;
  narrow.net->travel_clearance_m = 0.05;
  EXPECT_THROW(narrow.validate(), InputError);
  DrivableCourt bad = kCourt;
  bad.net->clearance_m = -1;
  try {
    bad.validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("net.clearance_m"), std::string::npos);
  }
}

}  // namespace
}  // namespace ballsight
