// The simulated collector's basket (sim/court_world.hpp): a full basket takes no more balls, and
// it is emptied only by standing still at the unload point for the unloading time.
#include <gtest/gtest.h>

#include "ballsight/sim/court_world.hpp"

namespace ballsight::sim {
namespace {

CourtWorld court_with_balls_ahead(const CollectorBasket& basket) {
  CourtScene scene;
  scene.robot.pose = {Vec2(5, 0), 0.0};
  for (const double x : {6.0, 6.5, 7.0, 9.5}) {
    SceneSphere b;
    b.id = static_cast<int>(scene.balls.size());
    b.center_in_field = Vec3(x, 0.0, kTennisBallRadiusM);
    scene.balls.push_back(b);
  }
  return CourtWorld(scene, TennisCourtSpec{}, DriveLimits{}, RobotFootprint{}, {}, basket);
}

TEST(CollectorBasket, AFullBasketTakesNoMore) {
  CourtWorld world = court_with_balls_ahead({2, Vec2(-15, 0), 5.0, 0.5});
  for (int k = 0; k < 30; ++k) world.advance({1.0, 0.0}, 0.1);  // over the first three
  EXPECT_EQ(world.held(), 2);
  EXPECT_EQ(world.balls_left(), 2);
  EXPECT_EQ(world.history().back().held, 2);
  CourtWorld unlimited = court_with_balls_ahead({});
  for (int k = 0; k < 30; ++k) unlimited.advance({1.0, 0.0}, 0.1);
  EXPECT_EQ(unlimited.balls_left(), 1);
}

TEST(CollectorBasket, EmptiedByStandingAtTheUnloadPoint) {
  CollectorBasket basket{2, Vec2::Zero(), 5.0, 0.5};
  CourtWorld away = court_with_balls_ahead(basket);  // unload point far behind
  for (int k = 0; k < 25; ++k) away.advance({1.0, 0.0}, 0.1);
  for (int k = 0; k < 80; ++k) away.advance({0.0, 0.0}, 0.1);
  EXPECT_EQ(away.held(), 2);

  CourtWorld world = court_with_balls_ahead(basket);
  for (int k = 0; k < 25; ++k) world.advance({1.0, 0.0}, 0.1);
  world.advance({0.0, 0.0}, 0.5);  // brakes
  basket.unload_m = world.motion().pose.ahead(RobotFootprint{}.collector_x_m) +
                    Vec2(0.3, 0.2);  // within 0.5 m of where the mouth stands
  CourtWorld there = court_with_balls_ahead(basket);
  for (int k = 0; k < 25; ++k) there.advance({1.0, 0.0}, 0.1);
  there.advance({0.0, 0.0}, 0.5);
  int unloads = 0;
  for (int k = 0; k < 45; ++k) unloads += there.advance({0.0, 0.0}, 0.1).unloaded ? 1 : 0;
  EXPECT_EQ(there.held(), 2);  // 4.5 s of the 5: not yet
  for (int k = 0; k < 10; ++k) unloads += there.advance({0.0, 0.0}, 0.1).unloaded ? 1 : 0;
  EXPECT_EQ(there.held(), 0);
  EXPECT_EQ(unloads, 1);
  // Room again: the fourth ball, driven over, is taken (the third was passed over while full).
  for (int k = 0; k < 30; ++k) there.advance({1.0, 0.0}, 0.1);
  EXPECT_EQ(there.held(), 1);
  EXPECT_EQ(there.balls_left(), 1);
}

}  // namespace
}  // namespace ballsight::sim
