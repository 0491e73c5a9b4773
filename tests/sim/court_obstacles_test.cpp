// People and bags on the simulated court (sim/court_obstacles.hpp): drawn clear of the balls and
// the robot, seen by the cameras, in the robot's way (it stops against them, and the contact is
// recorded), and a walking person goes to and fro but waits for the robot.
#include <gtest/gtest.h>

#include "ballsight/sim/court_world.hpp"
#include "court_test_support.hpp"

namespace ballsight::sim {
namespace {

CourtScene scene_with(const CourtObstacle& obstacle) {
  CourtScene scene;
  scene.robot.pose = {Vec2(5, 0), 0.0};
  scene.obstacles.push_back(obstacle);
  return scene;
}

CourtObstacle person_at(const Vec2& p) {
  CourtObstacle o;
  o.pose.position = p;
  return o;
}

TEST(CourtObstacles, DrawnClearOfTheBallsAndTheRobotAndOutOfTheLanes) {
  const TennisCourtSpec court;
  CourtScenarioOptions options;
  options.ball_count = 80;
  options.obstacles = {1, 1, 1, 0.5};
  const CourtScene plain = make_court_scene(
      court,
      [] {
        CourtScenarioOptions o;
        o.ball_count = 80;
        return o;
      }(),
      3);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const CourtScene scene = make_court_scene(court, options, seed);
    ASSERT_EQ(scene.obstacles.size(), 3u);
    EXPECT_EQ(scene.obstacles[0].kind, ObstacleKind::person);
    EXPECT_EQ(scene.obstacles[1].kind, ObstacleKind::bag);
    ASSERT_TRUE(scene.obstacles[2].walk_to.has_value());
    for (const CourtObstacle& o : scene.obstacles) {
      EXPECT_GT(std::abs(o.pose.position.x()), 1.2);
      EXPECT_LT(std::abs(o.pose.position.y()), court.surround_width_m / 2.0 - 1.2);
      for (const SceneSphere& b : scene.balls)
        EXPECT_GE(o.floor_distance(b.center_in_field.head<2>()), 0.5);
    }
  }
  // Their own stream: the balls of a seed stay where they were.
  const CourtScene with = make_court_scene(court, options, 3);
  ASSERT_EQ(with.balls.size(), plain.balls.size());
  for (std::size_t i = 0; i < plain.balls.size(); ++i)
    EXPECT_EQ(with.balls[i].center_in_field, plain.balls[i].center_in_field);
  options.obstacles.bags = 5;
  EXPECT_THROW(options.validate(), InputError);
}

TEST(CourtObstacles, EveryCameraThatLooksSeesThem) {
  const auto& f = test_support::shared_court();
  CourtScene scene = scene_with(person_at(Vec2(-6, 2)));
  CourtObstacle bag;
  bag.kind = ObstacleKind::bag;
  bag.pose = {Vec2(6, -3), 0.5};
  bag.half_size = Vec2(0.4, 0.18);
  bag.height_m = 0.3;
  scene.obstacles.push_back(bag);
  const std::size_t first = scene.spheres().size() + 1;  // after the spheres and the robot
  for (const CourtRenderer& renderer : f.renderers) {
    const CourtRender render = renderer.render(scene, 1);
    ASSERT_EQ(render.coverage.size(), first + 2);
    EXPECT_GT(render.coverage[first].visible_samples, 9 * 50);  // a person: many pixels
    EXPECT_GT(render.coverage[first + 1].visible_samples, 9 * 10);
  }
}

TEST(CourtObstacles, TheRobotStopsAgainstThemAndTheContactIsRecorded) {
  for (const ObstacleKind kind : {ObstacleKind::person, ObstacleKind::bag}) {
    CourtObstacle o = person_at(Vec2(8, 0));
    o.kind = kind;
    if (kind == ObstacleKind::bag) o.half_size = Vec2(0.2, 0.4);
    CourtWorld world(scene_with(o), TennisCourtSpec{}, DriveLimits{}, RobotFootprint{});
    bool blocked = false;
    for (int k = 0; k < 60; ++k) blocked = world.advance({1.0, 0.0}, 0.1).blocked || blocked;
    EXPECT_TRUE(blocked);
    // The body's front (0.30 m ahead of the pose) stops at the obstacle's edge (8 - 0.22 / 0.2).
    const double edge = 8.0 - o.half_size.x();
    EXPECT_LT(world.motion().pose.position.x() + 0.30, edge + 1e-9);
    EXPECT_GT(world.motion().pose.position.x() + 0.30, edge - 0.05);
    EXPECT_NEAR(world.history().back().clearance_m, 0.0, 0.05);
    EXPECT_FALSE(footprint_blocked(RobotFootprint{}, world.motion().pose, TennisCourtSpec{},
                                   world.scene().obstacles));
  }
}

TEST(CourtObstacles, AWalkerGoesToAndFroAndWaitsForTheRobot) {
  CourtObstacle walker = person_at(Vec2(-6, -3));
  walker.walk_to = Vec2(-6, 3);
  walker.walk_mps = 0.3;
  CourtWorld world(scene_with(walker), TennisCourtSpec{}, DriveLimits{}, RobotFootprint{});
  for (int k = 0; k < 100; ++k) world.advance({}, 0.1);  // 10 s: 3 m on
  EXPECT_NEAR(world.scene().obstacles[0].pose.position.y(), 0.0, 0.02);
  for (int k = 0; k < 200; ++k) world.advance({}, 0.1);  // 3 m to the end, 3 m back
  EXPECT_NEAR(world.scene().obstacles[0].pose.position.y(), 0.0, 0.02);

  CourtScene scene = scene_with(walker);
  scene.robot.pose = {Vec2(-6, -1), 0.0};  // in its way
  CourtWorld waits(scene, TennisCourtSpec{}, DriveLimits{}, RobotFootprint{});
  for (int k = 0; k < 100; ++k) waits.advance({}, 0.1);
  EXPECT_NEAR(waits.scene().obstacles[0].pose.position.y(), -1.0 - CourtWorld::kWalkerWaitM, 0.01);
  EXPECT_FALSE(std::any_of(waits.history().begin(), waits.history().end(),
                           [](const WorldTick& t) { return t.blocked; }));
}

TEST(CourtObstacles, ABallBesideThemIsReachableFromTheOtherSide) {
  const TennisCourtSpec court;
  const RobotFootprint f;
  const std::vector<CourtObstacle> person{person_at(Vec2(6, 2))};
  EXPECT_TRUE(mouth_can_reach(f, Vec2(6, 2.3), kTennisBallRadiusM, court, person));
  EXPECT_FALSE(mouth_can_reach(f, Vec2(6, 2.1), kTennisBallRadiusM, court, person));  // under it
}

}  // namespace
}  // namespace ballsight::sim
