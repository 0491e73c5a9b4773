// The court's costmap: the distance to the net's mesh and posts and to the fence, read between
// cells to within a fraction of a cell.
#include "ballsight/plan/costmap.hpp"

#include <gtest/gtest.h>

#include <random>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

TEST(Costmap, ReadsTheDistanceToTheNearestObstacle) {
  const DrivableCourt court = DrivableCourt::standard();
  const Costmap map(court, 0.05);
  const double post_y = court.net->half_length_m + court.net->body_half_m;
  // In front of the mesh, beyond a post, at the fence, beyond it, in the net.
  EXPECT_NEAR(map.clearance(Vec2(0.50, 2.0)), 0.50 - court.net->body_half_m, 0.005);
  EXPECT_NEAR(map.clearance(Vec2(0.0, post_y + 0.30)), 0.30, 0.005);
  EXPECT_NEAR(map.clearance(Vec2(17.9, 0.0)), 0.10, 0.005);
  EXPECT_LT(map.clearance(Vec2(18.2, 0.0)), 0.0);
  EXPECT_LT(map.clearance(Vec2(0.0, 1.0)), 0.0);
  EXPECT_LT(map.clearance(Vec2(40.0, 0.0)), 0.0);  // off the grid
  // Diagonally off a post's end: the distance to its corner.
  EXPECT_NEAR(map.clearance(Vec2(0.04 + 0.3, post_y + 0.4)), 0.5, 0.01);
}

TEST(Costmap, WithinAFractionOfACellEverywhere) {
  const DrivableCourt court = DrivableCourt::standard();
  const Costmap map(court, 0.05);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(-18.0, 18.0), y(-9.0, 9.0), near_net(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p(i % 2 ? x(rng) : near_net(rng), y(rng));
    const Vec2 half(court.net->body_half_m, court.net->half_length_m + court.net->body_half_m);
    const Vec2 q = p.cwiseAbs() - half;
    const double net = q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    const double fence = std::min({p.x() + 18.0, 18.0 - p.x(), p.y() + 9.0, 9.0 - p.y()});
    const double truth = std::min(net, fence);
    if (truth > 0.0) {
      // Between cells a ridge of the distance (equally near two sides) reads up to half a cell
      // short, a point just off a post's end up to about a ninth of a cell long (the local
      // planner's 1.5 cm margin holds it).
      const double error = map.clearance(p) - truth;
      EXPECT_GE(error, -0.5 * 0.05) << p.transpose();
      EXPECT_LE(error, 0.008) << p.transpose();
    }
  }
}

TEST(Costmap, RefusesABadResolution) {
  EXPECT_THROW(Costmap(DrivableCourt::standard(), 0.0), InputError);
  EXPECT_THROW(Costmap(DrivableCourt::standard(), 2.0), InputError);
}

}  // namespace
}  // namespace ballsight
