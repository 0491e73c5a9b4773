// The collector's basket on the robot's side (robot/basket_tracker.hpp): the count, what the
// service is told, and the stop to empty the basket.
#include "ballsight/robot/basket_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TEST(BasketTracker, CountsAsTheCourtSaysElseByItself) {
  BasketTracker basket;
  basket.answered(2, std::nullopt);
  EXPECT_EQ(basket.held(), 2);
  basket.answered(1, 3);
  EXPECT_EQ(basket.held(), 3);
  basket.answered(0, 0);  // emptied
  EXPECT_EQ(basket.held(), 0);
  EXPECT_EQ(basket.unloads(), 1);
  basket.answered(1, 1);
  EXPECT_EQ(basket.unloads(), 1);
}

// Told until the service accepts it, and again when the service restarted (a new id).
TEST(BasketTracker, TheServiceIsToldUntilItKnows) {
  BasketTracker basket;
  EXPECT_FALSE(basket.to_tell("a"));  // empty, as a new service knows it
  basket.answered(4, 4);
  EXPECT_EQ(basket.to_tell("a"), 4);
  EXPECT_EQ(basket.to_tell("a"), 4);  // not accepted yet: again
  basket.told(4);
  EXPECT_FALSE(basket.to_tell("a"));
  EXPECT_EQ(basket.to_tell("b"), 4);  // the service restarted
}

TEST(BasketTracker, StopsAtTheUnloadPointAndStandsThereUntilEmpty) {
  BasketTracker basket;
  basket.answered(5, 5);
  LinkUpdate u;
  u.unload_first_m = Vec2(10, 0);
  // On the way: slowed so that braking at 1 m/s^2 stops it at the point.
  const FollowCommand far = basket.approach(u, Vec2(8, 0), {1.0, 0.2, false});
  EXPECT_DOUBLE_EQ(far.speed_mps, 1.0);
  const FollowCommand near = basket.approach(u, Vec2(9.82, 0), {1.0, 0.2, false});
  EXPECT_NEAR(near.speed_mps, std::sqrt(2.0 * 0.18), 1e-12);
  EXPECT_NEAR(near.turn_rate_rps, 0.2 * near.speed_mps, 1e-12);  // the same curvature
  EXPECT_FALSE(basket.standing(u, Vec2(9.6, 0)));
  EXPECT_TRUE(basket.standing(u, Vec2(9.8, 0)));
  EXPECT_TRUE(basket.standing(u, Vec2(10.45, 0)));  // rolled past: it stays
  EXPECT_FALSE(basket.standing(u, Vec2(10.6, 0)));
  EXPECT_FALSE(basket.standing(u, Vec2(10.4, 0)));  // not again until within 0.3 m
  basket.answered(0, 0);
  EXPECT_FALSE(basket.standing(u, Vec2(10.0, 0)));  // empty: nothing to stand for
  u.unload_first_m.reset();
  basket.answered(2, 2);
  EXPECT_FALSE(basket.standing(u, Vec2(10.0, 0)));  // the route does not unload first
  BasketOptions bad;
  bad.stand_within_m = 0.1;
  EXPECT_THROW(BasketTracker{bad}, InputError);
}

}  // namespace
}  // namespace ballsight
