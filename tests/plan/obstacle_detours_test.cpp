// The ways round what stands on the court (plan/obstacle_detours.hpp): a path that passes an
// obstacle goes round it at the keep distance, and is no longer than it needs to be; a clear path
// is the one round the net; a point beside an obstacle is left straight away from it; the costmap
// measures the obstacles too.
#include "ballsight/plan/obstacle_detours.hpp"

#include <gtest/gtest.h>

#include "ballsight/core/error.hpp"
#include "ballsight/core/segment_distance.hpp"
#include "ballsight/plan/costmap.hpp"

namespace ballsight {
namespace {

constexpr double kKeep = 0.5;

/// The nearest any segment of a -> via -> b comes to `c`.
double nearest(const Vec2& a, const DrivablePath& path, const Vec2& b, const Vec2& c) {
  double d = INFINITY;
  Vec2 from = a;
  for (std::size_t k = 0; k <= path.via.size(); ++k) {
    const Vec2& to = k < path.via.size() ? path.via[k] : b;
    d = std::min(d, segment_distance(c, from, to));
    from = to;
  }
  return d;
}

double polyline_length(const Vec2& a, const DrivablePath& path, const Vec2& b) {
  double length = 0.0;
  Vec2 from = a;
  for (std::size_t k = 0; k <= path.via.size(); ++k) {
    const Vec2& to = k < path.via.size() ? path.via[k] : b;
    length += (to - from).norm();
    from = to;
  }
  return length;
}

TEST(ObstacleDetours, RoundAnObstacleInTheWayAtTheKeepDistance) {
  const DrivableCourt court = with_obstacles(DrivableCourt::standard(), {{Vec2(6, 2), 0.3}}, kKeep);
  const Vec2 a(3, 2), b(9, 2);
  const DrivablePath p = shortest_path(court, a, b);
  ASSERT_FALSE(p.via.empty());
  EXPECT_GE(nearest(a, p, b, Vec2(6, 2)), 0.3 + kKeep - 1e-6);
  EXPECT_NEAR(p.length_m, polyline_length(a, p, b), 1e-9);
  // Round a circle of 0.8 m: at least the tangents and the arc, at most the octagon's half.
  EXPECT_GT(p.length_m, 6.0);
  EXPECT_LT(p.length_m, 6.0 + 2.0 * 0.8 * (1.0 / std::cos(kPi / 8.0)));
  // Reversed: the same length.
  EXPECT_NEAR(shortest_path(court, b, a).length_m, p.length_m, 1e-9);
  // Not in the way: the path round the net, as without obstacles.
  const DrivablePath clear = shortest_path(court, Vec2(3, -2), Vec2(9, -2));
  EXPECT_TRUE(clear.via.empty());
  EXPECT_DOUBLE_EQ(clear.length_m, 6.0);
}

TEST(ObstacleDetours, RoundTwoObstaclesAndTheNet) {
  // Across the net round its east post, a person on each side in the way of that path.
  const Vec2 a(-8, 6), b(8, 6);
  const DrivablePath bare = shortest_path(DrivableCourt::standard(), a, b);
  ASSERT_EQ(bare.via.size(), 2u);
  const Vec2 left = 0.5 * (a + bare.via[0]), right = 0.5 * (bare.via[1] + b);
  const DrivableCourt court =
      with_obstacles(DrivableCourt::standard(), {{left, 0.3}, {right, 0.4}}, kKeep);
  const DrivablePath p = shortest_path(court, a, b);
  EXPECT_NE(p.via, bare.via);
  EXPECT_GT(p.length_m, bare.length_m);
  EXPECT_GE(nearest(a, p, b, left), 0.8 - 1e-6);
  EXPECT_GE(nearest(a, p, b, right), 0.9 - 1e-6);
  Vec2 from = a;
  for (const Vec2& via : p.via) {
    EXPECT_FALSE(court.blocked(from, via)) << via.transpose();
    from = via;
  }
  EXPECT_FALSE(court.blocked(from, b));
  EXPECT_NEAR(p.length_m, polyline_length(a, p, b), 1e-9);
}

TEST(ObstacleDetours, OutOfTwoOverlappingKeepOutsAndOnlyTheRobotsBody) {
  const DrivableCourt court =
      with_obstacles(DrivableCourt::standard(), {{Vec2(6, 2), 0.3}, {Vec2(6, 3.2), 0.3}}, kKeep);
  const Vec2 between(6.6, 2.6);  // within both keep-outs
  const DrivablePath p = shortest_path(court, between, Vec2(2, 2.6));
  ASSERT_FALSE(p.via.empty());
  EXPECT_GE((p.via.front() - Vec2(6, 2)).norm(), 0.8 - 1e-6);
  EXPECT_GE((p.via.front() - Vec2(6, 3.2)).norm(), 0.8 - 1e-6);
  const Pose2D robot{Vec2(1, 1), kPi / 2.0};
  EXPECT_TRUE(on_robot_body(robot, Vec2(1.3, 1.2)));
  EXPECT_FALSE(on_robot_body(robot, Vec2(1.6, 1.0)));
}

TEST(ObstacleDetours, APointBesideAnObstacleIsLeftStraightAway) {
  const DrivableCourt court = with_obstacles(DrivableCourt::standard(), {{Vec2(6, 2), 0.3}}, kKeep);
  const Vec2 ball(6.6, 2.0);  // 0.3 m from its edge: within the keep-out
  const Vec2 other(3, 2);     // on the far side
  const DrivablePath p = shortest_path(court, ball, other);
  ASSERT_FALSE(p.via.empty());
  EXPECT_NEAR((p.via.front() - Vec2(6.8, 2.0)).norm(), 0.0, 1e-9);
  DrivablePath rest = p;
  rest.via.erase(rest.via.begin());
  EXPECT_GE(nearest(p.via.front(), rest, other, Vec2(6, 2)), 0.8 - 1e-6);
}

TEST(ObstacleDetours, TheCostmapMeasuresThem) {
  Costmap costmap(with_obstacles(DrivableCourt::standard(), {{Vec2(6, 2), 0.3}}, kKeep));
  EXPECT_NEAR(costmap.clearance(Vec2(7, 2)), 0.7, 1e-6);
  EXPECT_LT(costmap.clearance(Vec2(6.1, 2)), 0.0);
  costmap.set_obstacles({});
  EXPECT_GT(costmap.clearance(Vec2(6.1, 2)), 5.0);
}

TEST(ObstacleDetours, BadObstaclesAreRefused) {
  EXPECT_THROW(with_obstacles(DrivableCourt::standard(), {{Vec2(NAN, 0), 0.3}}), InputError);
  EXPECT_THROW(with_obstacles(DrivableCourt::standard(), {{Vec2(1, 0), -0.3}}), InputError);
  EXPECT_FALSE(with_obstacles(DrivableCourt::standard(), {}).obstacles);
}

}  // namespace
}  // namespace ballsight
