#include "ballsight/service/update_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "example_site.hpp"

namespace ballsight {
namespace {

using test::kExampleSite;

WorldModel seen_world(std::int64_t capture_ns) {
  WorldModel world;
  world.capture_time_ns = capture_ns;
  world.robot.emplace();
  world.robot->pose = Pose2D{Vec2(-3.0, 2.0), 0.0};
  for (const Vec2& p : {Vec2(2.0, 1.0), Vec2(4.0, -2.0), Vec2(-1.0, 3.0)}) {
    FusedBall ball;
    ball.position_m = p;
    world.balls.push_back(ball);
  }
  return world;
}

// Whether `route` starts at the robot at `p` (at its collector's mouth, a little ahead of it).
bool starts_at(const Route& route, const Vec2& p) {
  return !route.waypoints_m.empty() && (route.waypoints_m.front() - p).norm() < 0.5;
}

// The update is a function of the values passed: the world's capture time is the update's, what
// a client set wins only when it is newer than the frames, and balls reported collected are left
// out of the route (not out of the world model: the cameras still see them).
TEST(PlanUpdate, WeighsClientReportsByTheFramesTime) {
  const Site site = read_site(kExampleSite.string());
  const WorldModel world = seen_world(5000);
  const NavigationUpdate plain = plan_update(site, world, {}, nullptr, {});
  EXPECT_EQ(plain.capture_time_ns, 5000);
  EXPECT_EQ(plain.world.balls.size(), 3u);
  EXPECT_EQ(plain.route.order.size(), 3u);
  EXPECT_TRUE(starts_at(plain.route, Vec2(-3.0, 2.0)));

  ClientReports reports;
  reports.collected = {Vec2(2.1, 1.0)};
  reports.robot = External<Pose2D>{Pose2D{Vec2(1.0, -1.0), 0.0}, 4000};  // older than the frames
  const NavigationUpdate older = plan_update(site, world, reports, nullptr, {});
  EXPECT_EQ(older.route.order.size(), 2u);
  EXPECT_EQ(older.world.balls.size(), 3u);
  EXPECT_TRUE(starts_at(older.route, Vec2(-3.0, 2.0)));

  reports.robot->set_ns = 6000;  // newer than the frames: the client's pose
  reports.balls = External<std::vector<Vec2>>{{Vec2(6.0, 2.0)}, 6000};
  const NavigationUpdate newer = plan_update(site, world, reports, nullptr, {});
  EXPECT_TRUE(starts_at(newer.route, Vec2(1.0, -1.0)));
  EXPECT_EQ(newer.route.order.size(), 1u);

  // No robot pose from anyone: no route, the world model all the same.
  WorldModel unseen = world;
  unseen.robot.reset();
  const NavigationUpdate none = plan_update(site, unseen, {}, nullptr, {});
  EXPECT_TRUE(none.route.order.empty());
  EXPECT_EQ(none.world.balls.size(), 3u);
}

// A report takes one ball: not its twin detection (one ball seen twice), not its neighbour.
TEST(PlanUpdate, AReportTakesOneBallNotItsTwinNorItsNeighbour) {
  const Site site = read_site(kExampleSite.string());
  WorldModel world = seen_world(5000);
  FusedBall twin;
  twin.position_m = Vec2(2.01, 1.0);  // the ball at (2, 1) once more
  world.balls.push_back(twin);
  FusedBall neighbour;
  neighbour.position_m = Vec2(2.0, 1.1);  // a ball touching it
  world.balls.push_back(neighbour);
  ClientReports reports;
  reports.collected = {Vec2(2.0, 1.0)};
  const NavigationUpdate u = plan_update(site, world, reports, nullptr, {});
  EXPECT_EQ(u.route.order.size(), 3u);  // (4, -2), (-1, 3) and the neighbour
  EXPECT_EQ(u.world.balls.size(), 5u);
}

// The basket matters once the balls outnumber its room: the route then empties it when full and
// leaves its last trip open; a full basket is emptied first.
TEST(PlanUpdate, TheBasketsRoomPlansTheUnloadTrips) {
  Site site = read_site(kExampleSite.string());
  site.robot.capacity = 3;
  const WorldModel world = seen_world(5000);
  const NavigationUpdate room = plan_update(site, world, {}, nullptr, {});
  EXPECT_TRUE(room.route.unload_after.empty());  // 3 balls, room for 3
  ClientReports reports;
  reports.basket = External<int>{1, 4000};
  const NavigationUpdate one = plan_update(site, world, reports, nullptr, {});
  ASSERT_EQ(one.route.unload_after.size(), 1u);
  EXPECT_LE(one.route.unload_after[0], 1);  // after at most the 2 balls it has room for
  EXPECT_EQ(one.route.order.size(), 3u);
  EXPECT_NE(
      std::find(one.route.waypoints_m.begin(), one.route.waypoints_m.end(), site.unload_point()),
      one.route.waypoints_m.end());
  reports.basket->value = 3;
  const NavigationUpdate full = plan_update(site, world, reports, nullptr, {});
  EXPECT_TRUE(full.route.unloads_first());
  EXPECT_FALSE(one.route.unloads_first());
}

// A ball the robot marked unreachable stays out of the route; the update lists the marks.
TEST(PlanUpdate, AMarkedBallStaysOutOfTheRoute) {
  const Site site = read_site(kExampleSite.string());
  const WorldModel world = seen_world(5000);
  ClientReports reports;
  reports.unreachable = {{Vec2(4.1, -2.0), "stuck"}};
  const NavigationUpdate u = plan_update(site, world, reports, nullptr, {});
  EXPECT_EQ(u.route.order.size(), 2u);
  EXPECT_EQ(u.world.balls.size(), 3u);
  ASSERT_EQ(u.reports.unreachable.size(), 1u);
  EXPECT_EQ(u.reports.unreachable[0].reason, "stuck");
}

}  // namespace
}  // namespace ballsight
