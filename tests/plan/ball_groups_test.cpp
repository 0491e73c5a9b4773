#include "ballsight/plan/ball_groups.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace ballsight {
namespace {

TEST(BallGroups, PartitionTheBallsWithinTheRadius) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 3.0);
  std::vector<Vec2> points;
  for (int i = 0; i < 300; ++i) points.emplace_back(u(rng), u(rng));
  std::vector<int> which;
  for (int i = 0; i < 300; i += 2) which.push_back(i);  // every other ball
  const std::vector<BallGroup> groups = group_balls(points, which, 0.27);
  std::vector<int> seen;
  std::size_t largest = 0;
  for (const BallGroup& g : groups) {
    largest = std::max(largest, g.balls.size());
    Vec2 mean = Vec2::Zero();
    for (const int b : g.balls) mean += points[static_cast<std::size_t>(b)];
    mean /= static_cast<double>(g.balls.size());
    EXPECT_NEAR((mean - g.centre_m).norm(), 0.0, 1e-12);
    for (const int b : g.balls) {
      EXPECT_LE((points[static_cast<std::size_t>(b)] - g.centre_m).norm(), g.radius_m + 1e-12);
      seen.push_back(b);
    }
    EXPECT_LE(g.radius_m, 0.27);
  }
  std::sort(seen.begin(), seen.end());
  EXPECT_EQ(seen, which);
  EXPECT_GT(largest, 2u);  // 150 balls on 9 m^2: groups form
  EXPECT_LT(groups.size(), which.size() * 3 / 4);
}

TEST(BallGroups, FarBallsStayAlone) {
  const std::vector<Vec2> points{Vec2(0, 0), Vec2(1, 0), Vec2(0.1, 0)};
  const auto groups = group_balls(points, {0, 1, 2}, 0.27);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0].balls, (std::vector<int>{0, 2}));
  EXPECT_NEAR(groups[0].radius_m, 0.05, 1e-12);
  EXPECT_EQ(groups[1].balls, std::vector<int>{1});
}

}  // namespace
}  // namespace ballsight
